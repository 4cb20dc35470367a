"""The hierarchy's system: move an entity under another parent without moving it in the world."""

from __future__ import annotations

from gandalf_core import System
from gandalf_core.systems.transform_system import set_parent_keep_world

from .components import ReparentOnKeyComponent


class ReparentSystem(System):
    """On a key press, moves an entity under its other parent without moving it in the world."""

    def __init__(self) -> None:
        super().__init__([ReparentOnKeyComponent])

    def on_update_entity(self, ts, entity, components) -> None:
        (swap,) = components
        app = self.scene.app
        if app is not None and app.input.pressed(swap.key):
            current = self.scene.parent_of(entity)
            # --8<-- [start:reparent]
            # local = inverse(new parent's world) @ world: the world pose stays
            set_parent_keep_world(self.scene, entity, swap.other_parent)
            # --8<-- [end:reparent]
            swap.other_parent = current

# Saved in USD scenes by name (the loader only builds classes registered like this).
