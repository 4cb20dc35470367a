"""The Info component: a human-readable name (and optional tag) for an entity."""

from __future__ import annotations

from .component import Component


class InfoComponent(Component):
    """Name and tag of an entity, used in the editor, in USD paths and in error messages."""

    def __init__(self, name: str = "entity", tag: str = "") -> None:
        self.name = name
        self.tag = tag
