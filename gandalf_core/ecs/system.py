"""Systems: behaviour over every entity that has a given set of component types.

A system names the component types it needs when it is created, e.g.
``GravitySystem([GravityComponent, TransformComponent])``. The scene keeps, per system, the matching
entities and their component tuples (in the order the types were given), and keeps them current as
components are added and removed while the app runs.

Two ways to write a system:

* per entity (the teaching path): override :meth:`System.on_update_entity`;
* in one batch (the fast path): override :meth:`System.on_update_system` and work on
  :attr:`System.entities` / :meth:`System.column`, or on a columnar store with numpy.
"""

from __future__ import annotations

import uuid
from collections.abc import Iterable, Sequence
from typing import Any, ClassVar

from .component import Component
from .errors import NotAComponentError


class System:
    """Base class of systems. Subclasses override the hooks they need."""

    #: False for a system that acts only in :meth:`on_gui_update` (the editor's panels): ``Scene.update`` then
    #: skips it, so a frame pays nothing for it.
    updates_each_frame: ClassVar[bool] = True
    #: False for a system that belongs to a tool layered on the app, not to the scene (the render system, an
    #: editor's panels): saving a scene leaves it out.
    saved: ClassVar[bool] = True

    def __init__(self, component_types: Sequence[type[Component]] = (), *, name: str | None = None) -> None:
        types = tuple(component_types)
        for t in types:
            if not (isinstance(t, type) and issubclass(t, Component)):
                raise NotAComponentError(
                    f"{type(self).__name__}: {t!r} is not a Component subclass; systems filter on component types"
                )
        if len(set(types)) != len(types):
            raise ValueError(f"{type(self).__name__}: component types listed twice: {types}")
        self.component_types: tuple[type[Component], ...] = types
        self.name = name or type(self).__name__
        #: The :class:`~gandalf_core.ecs.scene.Scene` it belongs to (set by ``Scene.add_system``; the scene
        #: imports systems, never the other way round).
        self.scene: Any = None
        #: False pauses the system: the scene skips its update (``Scene.run_system`` still runs it once).
        self.enabled = True
        #: Wall-clock seconds of its last ``on_update_system`` (written by the scene).
        self.update_seconds = 0.0
        self._members: dict[uuid.UUID, tuple[Any, ...]] = {}
        self._lists: tuple[list[uuid.UUID], list[tuple[Any, ...]]] | None = None
        #: Bumped whenever an entity starts or stops matching: caches built from the members compare it.
        self.version = 0

    # --- hooks -----------------------------------------------------------------------------
    def on_create_system(self) -> None:
        """Called once when the system joins a scene, before ``on_create_entity`` for existing entities."""

    def on_create_entity(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        """Called when an entity starts matching this system (also for entities that existed before)."""

    def on_remove_entity(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        """Called when an entity stops matching (a component removed, or the entity destroyed)."""

    def on_update_system(self, ts: float) -> None:
        """Called once per frame. The default calls :meth:`on_update_entity` for every matching entity."""
        update = self.on_update_entity  # bound once: one attribute lookup per frame, not per entity
        for entity, components in zip(*self._cached_lists()):
            update(ts, entity, components)

    def on_update_entity(self, ts: float, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        """Per-entity update; ``ts`` is the frame time step in seconds."""

    def on_gui_update(self) -> None:
        """Called once per frame while a GUI layer (the editor) is drawing; empty by default."""

    def on_destroy_system(self) -> None:
        """Called when the system leaves its scene (or the scene is torn down): release resources here."""

    # --- matching entities --------------------------------------------------------------------
    @property
    def entities(self) -> list[uuid.UUID]:
        """Matching entities in the order they started matching."""
        return self._cached_lists()[0]

    @property
    def components(self) -> list[tuple[Any, ...]]:
        """Component tuples of the matching entities, same order as :attr:`entities`."""
        return self._cached_lists()[1]

    def column(self, index_or_type: int | type[Component]) -> list[Any]:
        """All matching components of one type (by position in ``component_types`` or by type)."""
        i = index_or_type if isinstance(index_or_type, int) else self.component_types.index(index_or_type)
        return [c[i] for c in self._cached_lists()[1]]

    def __len__(self) -> int:
        return len(self._members)

    def matches(self, component_types: Iterable[type]) -> bool:
        have = component_types if isinstance(component_types, (dict, set, frozenset)) else set(component_types)
        return all(t in have for t in self.component_types)

    # --- called by the scene --------------------------------------------------------------------
    def _add_member(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        self._members[entity] = components
        self._lists = None
        self.version += 1
        self.on_create_entity(entity, components)

    def _add_members(self, members: list[tuple[uuid.UUID, tuple[Any, ...]]]) -> None:
        """Many entities start matching at once (Scene.create_entities); ``on_create_entity`` for each, in order,
        unless the system does not override it."""
        self._members.update(members)
        self._lists = None
        self.version += 1
        hook = self.on_create_entity
        if type(self).on_create_entity is not System.on_create_entity:
            for entity, components in members:
                hook(entity, components)

    def _remove_member(self, entity: uuid.UUID) -> None:
        components = self._members.pop(entity)
        self._lists = None
        self.version += 1
        self.on_remove_entity(entity, components)

    def _cached_lists(self) -> tuple[list[uuid.UUID], list[tuple[Any, ...]]]:
        # Rebuilt lazily after membership changed: iteration stays cheap every other frame.
        if self._lists is None:
            self._lists = (list(self._members.keys()), list(self._members.values()))
        return self._lists
