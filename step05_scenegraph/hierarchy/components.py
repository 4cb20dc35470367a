"""The hierarchy's own component: re-parent an entity on a key press (data only; ``systems.py`` acts on it)."""

from __future__ import annotations

import uuid

from gandalf_core import Component


class ReparentOnKeyComponent(Component):
    """Pressing ``key`` swaps the entity's parent with ``other_parent``, keeping its world pose."""

    def __init__(self, other_parent: uuid.UUID | None, key: str = "M") -> None:
        self.other_parent = other_parent
        self.key = key.upper()

# Saved in USD scenes by name (the loader only builds classes registered like this).
