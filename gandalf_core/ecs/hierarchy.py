"""The Link component: an entity's place in the scene hierarchy.

A Link names the parent entity (or None for a root). The scene maintains ``children`` and rejects
cycles; change a parent through :meth:`Scene.set_parent` so that the scene can check and record it.
"""

from __future__ import annotations

import uuid

from .component import Component


class LinkComponent(Component):
    """Parent/child relation. ``parent`` is an entity id or None; ``children`` is kept by the scene."""

    def __init__(self, parent: uuid.UUID | None = None) -> None:
        if parent is not None and not isinstance(parent, uuid.UUID):
            raise TypeError(f"LinkComponent.parent must be an entity id (a uuid.UUID from create_entity) or None, "
                            f"got {parent!r}")
        self._parent = parent
        self.children: list[uuid.UUID] = []

    @property
    def parent(self) -> uuid.UUID | None:
        return self._parent

    def __repr__(self) -> str:
        return f"LinkComponent(parent={self._parent}, children={len(self.children)})"
