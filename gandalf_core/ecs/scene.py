"""The Scene: entities (UUIDs), their components, and the systems that run over them.

Systems run in the order they were added (``add_system(system, index=...)`` inserts elsewhere);
that order is the documented update order of a frame.
"""

from __future__ import annotations

import contextlib
import gc
import math
import os
import uuid
import weakref
from collections.abc import Iterator, Sequence
from time import perf_counter as _perf_counter
from typing import Any, TypeVar

import numpy as np

from ..resources.assets import Assets
from .component import ColumnarComponent, ColumnBatch, ColumnStore, Component
from .errors import HierarchyCycleError, MissingComponentError, NotAComponentError, UnknownEntityError
from .hierarchy import LinkComponent
from .info import InfoComponent
from .system import System

C = TypeVar("C", bound=Component)

#: Every scene alive, so that a mutable component held by an entity of one is refused to another (an edit of one
#: would be an edit of both).
_LIVE_SCENES: weakref.WeakSet[Scene] = weakref.WeakSet()


class Scene:
    """A world of entities. Entities are UUIDs; components are attached per type (one of each type)."""

    def __init__(self, name: str = "scene") -> None:
        self.name = name
        self.app: Any = None  # set by the Application that runs this scene
        self.assets = Assets()  # meshes, textures and materials by name (backend-neutral data)
        self._entities: dict[uuid.UUID, dict[type, Component]] = {}
        self._stores: dict[type, ColumnStore] = {}
        #: id() of each attached mutable, non-columnar component -> its entity: one object on two entities would
        #: make an edit of one (a rename) an edit of both, so a second owner is refused.
        self._owners: dict[int, uuid.UUID] = {}
        self._systems: list[System] = []
        self._systems_by_type: dict[type, list[System]] = {}
        self._queries: dict[tuple[type, ...], System] = {}
        self._updating = False  # inside a system's update: destruction waits until the system is done
        #: Entities destroyed during the running system's update, destroyed when it has finished.
        self.pending_destroy: list[uuid.UUID] = []
        self.hierarchy_version = 0  # bumped whenever a Link is added, removed or re-parented
        self.membership_version = 0  # bumped whenever any component is added or removed
        _LIVE_SCENES.add(self)

    # --- entities ---------------------------------------------------------------------------------
    def enroll_entity(self, entity: uuid.UUID | None = None) -> uuid.UUID:
        """Create a new, empty entity and return its id (``entity``: reuse a given id, e.g. to bring a destroyed
        entity back on undo; an id in use is an error)."""
        if entity is None:
            entity = _new_id()
        elif not isinstance(entity, uuid.UUID):
            raise TypeError(f"scene '{self.name}': an entity id must be a uuid.UUID, got {entity!r}")
        elif entity in self._entities:
            raise ValueError(f"scene '{self.name}': {self.describe(entity)} exists already")
        self._entities[entity] = {}
        return entity

    def create_entity(self, *components: Component) -> uuid.UUID:
        """Enroll an entity and add ``components`` to it (a shorthand for scene-building code).

        Many entities at once: :meth:`create_entities` (one call instead of a Python loop).
        """
        entity = self.enroll_entity()
        comps = self._entities[entity]
        # The common case (distinct component types, no Link, none owned elsewhere) skips add_component's
        # replace/hierarchy handling; systems see the components arrive one by one exactly as add_component does.
        for component in components:
            component_type = type(component)
            if (component_type in comps or component_type is LinkComponent or not isinstance(component, Component)
                    or (isinstance(component, ColumnarComponent) and component._store is not None)
                    or id(component) in self._owners or self._held_elsewhere(component) is not None):
                self.add_component(entity, component)  # the general path (and its errors)
                continue
            if isinstance(component, ColumnarComponent):
                self.store(component_type).attach(component)
            elif not component_type.immutable:
                self._owners[id(component)] = entity
            comps[component_type] = component
            self._joined(entity, comps, component_type)
        return entity

    def create_entities(self, n: int, *components: Component | ColumnBatch | Sequence[Component]) -> list[uuid.UUID]:
        """Create ``n`` entities at once and return their ids (the bulk form of :meth:`create_entity`).

        Each argument gives one component type for all ``n`` entities:

        * a batch of a columnar component, e.g. ``TransformComponent.batch(translations=xyz)`` (``xyz`` of
          shape ``(n, 3)``): its rows are written into the scene's column store in one call per field;
        * a single component, e.g. ``MeshComponent("cube")``: each entity gets its own shallow copy (or, for
          component types marked ``immutable`` such as MeshComponent and MaterialComponent, the same object);
        * a sequence of ``n`` components, one per entity.

        Systems see the new entities as if they had been created one by one (``on_create_entity`` is called
        for each entity that matches, in creation order, one system after the other). 100k entities with a
        Transform, a Mesh and a Material take ~0.2-0.4 s instead of several seconds. LinkComponents (the
        hierarchy) are added one by one, with their checks.
        """
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 0:
            raise ValueError(f"scene '{self.name}': create_entities needs a non-negative int n, got {n!r}")
        n = int(n)
        columns: list[tuple[type, list[Any]]] = []
        links: list[Any] | None = None
        for position, arg in enumerate(components):
            what = f"scene '{self.name}': create_entities argument {position + 1}"
            if isinstance(arg, ColumnBatch):
                if arg.count != n:
                    raise ValueError(f"{what}: the {arg.component_type.__name__} batch has {arg.count} rows, n is {n}")
                columns.append((arg.component_type, [arg]))
                continue
            if isinstance(arg, Component):
                if isinstance(arg, ColumnarComponent):
                    raise ValueError(f"{what}: pass {type(arg).__name__}.batch(...) (rows for n entities) instead "
                                     f"of one {type(arg).__name__}")
                items = [arg] * n if type(arg).immutable else _copies(arg, n)
            elif isinstance(arg, Sequence) and not isinstance(arg, str):
                items = list(arg)
                if len(items) != n:
                    raise ValueError(f"{what}: {len(items)} components given for {n} entities")
                if not items:
                    continue
                kinds = {type(c) for c in items}
                if len(kinds) != 1 or not isinstance(items[0], Component):
                    raise NotAComponentError(f"{what}: a sequence must hold components of one type, got "
                                             f"{', '.join(sorted(k.__name__ for k in kinds))}")
                if isinstance(items[0], ColumnarComponent):
                    raise ValueError(f"{what}: pass {type(items[0]).__name__}.batch(...) for columnar components")
            else:
                hint = f" (pass an instance: {arg.__name__}(...))" if isinstance(arg, type) else ""
                raise NotAComponentError(f"{what}: {arg!r} is not a component, a component batch or a sequence "
                                         f"of components{hint}")
            ctype = type(items[0]) if items else None
            if ctype is LinkComponent:
                links = items
                continue
            columns.append((ctype, items))
        types = [t for t, _ in columns]
        if len(set(types)) != len(types) or (links is not None and LinkComponent in types):
            raise ValueError(f"scene '{self.name}': create_entities got two components of one type")
        if n == 0:
            return []
        # The cyclic garbage collector would run many times while ~n * (components + 2) objects are made, each
        # time walking every object alive: paused here, it runs once afterwards as usual.
        with _gc_paused():
            return self._create_entities(n, columns, links)

    def _create_entities(self, n: int, columns: list[tuple[type, list[Any]]], links: list[Any] | None,
                         ) -> list[uuid.UUID]:
        ids = _new_ids(n)
        resolved: list[tuple[type, list[Any]]] = []
        for ctype, items in columns:
            if len(items) == 1 and isinstance(items[0], ColumnBatch):
                items = self.store(ctype).attach_batch(items[0])
            resolved.append((ctype, items))
        owned = [(t, items) for t, items in resolved if not issubclass(t, ColumnarComponent) and not t.immutable]
        for ctype, items in owned:
            self._check_unowned(ctype, items)
        entities = self._entities
        keys = [t for t, _ in resolved]
        if not resolved:
            for entity in ids:
                entities[entity] = {}
        else:
            for entity, values in zip(ids, zip(*(items for _, items in resolved))):
                entities[entity] = dict(zip(keys, values))
        for _, items in owned:
            self._owners.update(zip(map(id, items), ids))
        self.membership_version += 1
        # Systems that need any of the new types, each once, in the order they joined.
        seen: set[int] = set()
        systems: list[System] = []
        for ctype in keys:
            for system in self._systems_by_type.get(ctype, ()):
                if id(system) not in seen:
                    seen.add(id(system))
                    systems.append(system)
        by_type = dict(resolved)
        for system in systems:
            if all(t in by_type for t in system.component_types):
                system._add_members(list(zip(ids, zip(*(by_type[t] for t in system.component_types)))))
        if links is not None:
            for entity, link in zip(ids, links):
                self.add_component(entity, link)
        return ids

    @property
    def entities(self) -> list[uuid.UUID]:
        return list(self._entities)

    def __contains__(self, entity: object) -> bool:
        return entity in self._entities

    def __len__(self) -> int:
        return len(self._entities)

    def describe(self, entity: uuid.UUID) -> str:
        """A readable name for messages: the Info name when there is one, plus the id."""
        info = self._entities.get(entity, {}).get(InfoComponent)
        return f"entity '{info.name}' ({entity})" if info is not None else f"entity {entity}"

    def destroy_entity(self, entity: uuid.UUID) -> None:
        """Remove an entity, its components, and (through its Link) all of its descendants.

        Asked for while a system runs its update, the destruction waits until that system has finished (so its
        loop never visits an entity it has already destroyed, and never skips one); :attr:`pending_destroy` holds
        what waits. Everywhere else it happens at once.
        """
        self._require(entity)
        if self._updating:
            if entity not in self.pending_destroy:
                self.pending_destroy.append(entity)
            return
        self._destroy_now(entity)

    def _destroy_now(self, entity: uuid.UUID) -> None:
        if entity not in self._entities:  # destroyed already, e.g. as a descendant of another pending entity
            return
        # Collect the subtree breadth-first without recursion (a 1000-deep chain must not hit the
        # recursion limit), then destroy it from the leaves up so every child goes before its parent.
        subtree = [entity]
        for node in subtree:
            link = self._entities[node].get(LinkComponent)
            if link is not None:
                subtree.extend(child for child in link.children if child in self._entities)
        for node in reversed(subtree):
            for component_type in list(self._entities[node]):
                self.remove_component(node, component_type)
            del self._entities[node]

    # --- components -------------------------------------------------------------------------------
    def add_component(self, entity: uuid.UUID, component: C) -> C:
        """Attach ``component`` to ``entity`` (replacing one of the same type) and update systems."""
        comps = self._require(entity)
        if not isinstance(component, Component):
            # Passing the class instead of an instance is the usual slip: say so.
            hint = (
                f" (pass an instance: {component.__name__}(...))"
                if isinstance(component, type) and issubclass(component, Component)
                else ""
            )
            raise NotAComponentError(
                f"cannot add {component!r} to {self.describe(entity)}: "
                f"{type(component).__name__} is not a Component subclass{hint}"
            )
        component_type = type(component)
        if isinstance(component, ColumnarComponent) and component._store is not None:
            raise ValueError(
                f"cannot add this {component_type.__name__} to {self.describe(entity)}: it already belongs to an entity"
            )
        holder = self._held_by(component, entity)
        if holder is not None:
            raise ValueError(
                f"cannot add this {component_type.__name__} to {self.describe(entity)}: the same object already "
                f"belongs to {holder} (a change to one would change both); give each entity its own "
                f"(copy.copy(component) or a new {component_type.__name__}(...))"
            )
        kept_children: list[uuid.UUID] = []
        if component_type is LinkComponent:
            self._check_parent(entity, component.parent)
            if LinkComponent in comps:  # a new Link replaces the parent, not the entity's children
                kept_children = list(comps[LinkComponent].children)
        if component_type in comps:
            self.remove_component(entity, component_type)
        if isinstance(component, ColumnarComponent):
            self.store(component_type).attach(component)
        elif not component_type.immutable:
            self._owners[id(component)] = entity
        comps[component_type] = component
        if component_type is LinkComponent:
            self._attach_link(entity, component)
            for child in kept_children:
                self._entities[child][LinkComponent]._parent = entity
                component.children.append(child)
        self._joined(entity, comps, component_type)
        return component

    def _check_unowned(self, ctype: type, items: list[Any]) -> None:
        """A bulk creation's mutable components must be distinct objects that no entity holds yet."""
        seen: dict[int, int] = {}
        for k, item in enumerate(items):
            holder = self._held_by(item)
            if holder is not None:
                raise ValueError(f"create_entities: {ctype.__name__} number {k} is the object that {holder} holds "
                                 "(a change to one would change both); give each entity its own")
            if seen.setdefault(id(item), k) != k:
                raise ValueError(f"create_entities: {ctype.__name__} number {k} is the same object as number "
                                 f"{seen[id(item)]} (a change to one would change both); give each entity its own")

    def _held_by(self, component: Any, entity: uuid.UUID | None = None) -> str | None:
        """Who already holds this very mutable component object, described: an entity of this scene other than
        ``entity``, or one of another live scene; None when nobody does."""
        owner = self._owners.get(id(component))
        if owner is not None and owner != entity and owner in self._entities:
            return self.describe(owner)
        return self._held_elsewhere(component)

    def _held_elsewhere(self, component: Any) -> str | None:
        """Which entity of another live scene holds this very mutable component object ("entity 'box' (…) of
        scene 'a'"), or None. A scene dropped but not yet collected is collected first, so it never refuses a
        reuse."""
        if len(_LIVE_SCENES) < 2 or type(component).immutable or isinstance(component, ColumnarComponent):
            return None
        if self._holder(component) is None:
            return None
        gc.collect()  # the holder may be garbage that a reference cycle keeps: collect, then look again
        return self._holder(component)

    def _holder(self, component: Any) -> str | None:
        """The entity of another scene that holds ``component``, described (no reference to that scene is kept)."""
        for scene in list(_LIVE_SCENES):
            owner = scene._owners.get(id(component)) if scene is not self else None
            if owner is not None and scene._entities.get(owner, {}).get(type(component)) is component:
                return f"{scene.describe(owner)} of scene '{scene.name}'"
        return None

    def _joined(self, entity: uuid.UUID, comps: dict[type[Component], Component], component_type: type) -> None:
        """``entity`` (its components ``comps``) has gained a ``component_type``: every system of that type whose
        component types it now all has takes it in."""
        self.membership_version += 1
        for system in self._systems_by_type.get(component_type, ()):
            types = system.component_types
            if all(t in comps for t in types):
                system._add_member(entity, tuple([comps[t] for t in types]))

    def remove_component(self, entity: uuid.UUID, component_type: type[Component]) -> Component:
        """Detach and return the entity's component of ``component_type``."""
        comps = self._require(entity)
        if component_type not in comps:
            raise MissingComponentError(
                f"{self.describe(entity)} has no {getattr(component_type, '__name__', component_type)} to remove"
            )
        for system in self._systems_by_type.get(component_type, ()):
            if entity in system._members:
                system._remove_member(entity)
        component = comps.pop(component_type)
        if isinstance(component, ColumnarComponent):
            self._stores[component_type].detach(component)
        elif self._owners.get(id(component)) == entity:
            del self._owners[id(component)]
        if component_type is LinkComponent:
            self._detach_link(entity, component)
            for child in component.children:  # orphans become roots rather than point at a missing Link
                self._entities[child][LinkComponent]._parent = None
            component.children = []
        self.membership_version += 1
        return component

    def get_component(self, entity: uuid.UUID, component_type: type[C]) -> C:
        """The entity's component of ``component_type``; raises MissingComponentError naming both."""
        comps = self._require(entity)
        try:
            return comps[component_type]  # type: ignore[return-value]
        except KeyError:
            have = ", ".join(t.__name__ for t in comps) or "none"
            raise MissingComponentError(
                f"{self.describe(entity)} has no {getattr(component_type, '__name__', component_type)} "
                f"(it has: {have})"
            ) from None

    def try_component(self, entity: uuid.UUID, component_type: type[C]) -> C | None:
        """The entity's component of ``component_type``, or None."""
        return self._require(entity).get(component_type)  # type: ignore[return-value]

    def has_component(self, entity: uuid.UUID, component_type: type[Component]) -> bool:
        return component_type in self._require(entity)

    def components_of(self, entity: uuid.UUID) -> list[Component]:
        return list(self._require(entity).values())

    def view(self, *component_types: type[Component]) -> Iterator[tuple[uuid.UUID, tuple[Any, ...]]]:
        """Every (entity, components) that has all ``component_types`` (uncached; systems cache)."""
        for entity, comps in self._entities.items():
            if all(t in comps for t in component_types):
                yield entity, tuple(comps[t] for t in component_types)

    def query(self, *component_types: type[Component]) -> System:
        """A cached, always-current view of the entities that have all ``component_types``.

        The result is a hook-less system that is never updated: read ``.entities`` / ``.components``.
        """
        query = self._queries.get(component_types)
        if query is None:
            query = self._queries[component_types] = System(component_types, name=f"query{component_types}")
            query.scene = self
            self._track(query)
        return query

    def store(self, component_type: type[ColumnarComponent]) -> ColumnStore:
        """The numpy column store of a columnar component type (created on first use)."""
        store = self._stores.get(component_type)
        if store is None:
            store = self._stores[component_type] = ColumnStore(component_type)
        return store

    # --- hierarchy ----------------------------------------------------------------------------------
    def set_parent(self, entity: uuid.UUID, parent: uuid.UUID | None) -> None:
        """Re-parent ``entity`` (which must have a LinkComponent); rejects cycles."""
        link = self.get_component(entity, LinkComponent)
        self._check_parent(entity, parent)
        self._detach_link(entity, link)
        link._parent = parent
        self._attach_link(entity, link)

    def parent_of(self, entity: uuid.UUID) -> uuid.UUID | None:
        link = self._require(entity).get(LinkComponent)
        return None if link is None else link.parent

    def _check_parent(self, entity: uuid.UUID, parent: uuid.UUID | None) -> None:
        if parent is None:
            return
        if parent not in self._entities:
            raise UnknownEntityError(f"parent {parent} of {self.describe(entity)} is not in scene '{self.name}'")
        node: uuid.UUID | None = parent
        chain = [entity]
        while node is not None:
            chain.append(node)
            if node == entity:
                names = " -> ".join(self.describe(e) for e in chain)
                raise HierarchyCycleError(f"parenting would create a cycle: {names}")
            node = self.parent_of(node)

    def _attach_link(self, entity: uuid.UUID, link: LinkComponent) -> None:
        if link.parent is not None:
            parent_link = self._entities[link.parent].get(LinkComponent)
            if parent_link is None:
                parent_link = self.add_component(link.parent, LinkComponent(None))
            parent_link.children.append(entity)
        self.hierarchy_version += 1

    def _detach_link(self, entity: uuid.UUID, link: LinkComponent) -> None:
        if link.parent is not None and link.parent in self._entities:
            parent_link = self._entities[link.parent].get(LinkComponent)
            if parent_link is not None and entity in parent_link.children:
                parent_link.children.remove(entity)
        self.hierarchy_version += 1

    # --- systems ------------------------------------------------------------------------------------
    @property
    def systems(self) -> list[System]:
        """The systems in update order."""
        return list(self._systems)

    def add_system(self, system: System, index: int | None = None) -> System:
        """Add ``system`` (at the end of the update order, or at ``index``) and match existing entities."""
        if not isinstance(system, System):
            raise TypeError(f"scene '{self.name}': {system!r} is not a System")
        if system.scene is not None:
            raise ValueError(f"{system.name} already belongs to scene '{system.scene.name}'")
        system.scene = self
        if index is None:
            self._systems.append(system)
        else:
            self._systems.insert(index, system)
        system.on_create_system()
        self._track(system)
        return system

    def _track(self, system: System) -> None:
        types = system.component_types
        for t in types:
            self._systems_by_type.setdefault(t, []).append(system)
        # One pass over the entities, testing the first type before the rest (a query for a camera looks at 100k
        # entities without building a tuple for each), and the members handed over at once.
        items = self._entities.items()
        if len(self._entities) > 1000:
            with _gc_paused():
                members = self._matching(types, items)
        else:
            members = self._matching(types, items)
        if members:
            system._add_members(members)

    def _matching(self, types: tuple[type, ...], items: Any) -> list[tuple[uuid.UUID, tuple[Any, ...]]]:
        if not types:
            members = [(entity, ()) for entity, _ in items]
        elif len(types) == 1:
            only = types[0]
            members = [(entity, (comps[only],)) for entity, comps in items if only in comps]
        else:
            first, rest = types[0], types[1:]
            members = [(entity, tuple([comps[t] for t in types])) for entity, comps in items
                       if first in comps and all(t in comps for t in rest)]
        return members

    def remove_system(self, system: System) -> None:
        """Take ``system`` out of the scene (calling its ``on_destroy_system``)."""
        if system not in self._systems:
            names = ", ".join(type(s).__name__ for s in self._systems) or "none"
            what = type(system).__name__ if isinstance(system, System) else repr(system)
            raise ValueError(f"scene '{self.name}' has no system {what} to remove (its systems: {names})")
        self._systems.remove(system)
        for t in system.component_types:
            self._systems_by_type[t].remove(system)
        system.on_destroy_system()
        system.scene = None
        system._members.clear()
        system._lists = None

    def move_system(self, system: System, index: int) -> None:
        """Move ``system`` to position ``index`` of the update order (clamped to the list)."""
        if system not in self._systems:
            raise ValueError(f"scene '{self.name}' has no system {system!r} to move")
        self._systems.remove(system)
        self._systems.insert(max(0, min(int(index), len(self._systems))), system)

    def get_system(self, system_type: type[System]) -> System:
        for system in self._systems:
            if isinstance(system, system_type):
                return system
        raise KeyError(f"scene '{self.name}' has no {system_type.__name__}")

    def update(self, ts: float) -> None:
        """Run one frame: every enabled system's ``on_update_system`` in order; entities a system destroys go
        when it has finished. Each system's wall-clock time lands in its ``update_seconds``.

        ``ts`` is the frame's time step in seconds: a finite number >= 0 (a NaN would spread into every position a
        system integrates, silently)."""
        if type(ts) is not float and (isinstance(ts, bool) or not isinstance(ts, (int, np.integer, np.floating))):
            raise TypeError(f"scene '{self.name}': update(ts) needs the time step in seconds, got {ts!r}")
        if not 0.0 <= ts < math.inf:  # False for NaN too
            raise ValueError(f"scene '{self.name}': update(ts) needs a finite time step >= 0, got {ts!r}")
        for system in list(self._systems):
            if system.enabled and system.updates_each_frame:
                self.run_system(system, ts)

    def run_system(self, system: System, ts: float) -> None:
        """One ``on_update_system`` of ``system`` (enabled or not: a paused system's single step), timed."""
        outer, self._updating = self._updating, True  # a step asked for inside another system's update nests
        start = _perf_counter()
        try:
            system.on_update_system(ts)
        finally:
            system.update_seconds = _perf_counter() - start
            self._updating = outer
            if not outer:
                self._flush_destroyed()

    def _flush_destroyed(self) -> None:
        pending, self.pending_destroy = self.pending_destroy, []
        for entity in pending:
            self._destroy_now(entity)

    def gui_update(self) -> None:
        for system in self._systems:
            if system.enabled:
                system.on_gui_update()

    def teardown(self) -> None:
        """Remove every system (calling ``on_destroy_system``) — used when an app shuts down."""
        for system in reversed(list(self._systems)):
            self.remove_system(system)

    # --- internals ----------------------------------------------------------------------------------
    def _require(self, entity: uuid.UUID) -> dict[type, Component]:
        try:
            return self._entities[entity]
        except (KeyError, TypeError):
            raise UnknownEntityError(f"{entity!r} is not an entity of scene '{self.name}'") from None


@contextlib.contextmanager
def _gc_paused() -> Iterator[None]:
    """Pause the cyclic garbage collector while many objects are made: it would otherwise run many times, each
    time walking every object alive; it runs as usual afterwards."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


_new_uuid = object.__new__
_set_slot = object.__setattr__
_UNKNOWN_SAFETY = uuid.SafeUUID.unknown


def _new_id() -> uuid.UUID:
    """One random (version 4) UUID, like ``uuid.uuid4()`` at a third of its cost."""
    value = int.from_bytes(os.urandom(16), "big")
    value = (value & ~(0xF000 << 64) & ~(0xC000 << 48)) | (0x4000 << 64) | (0x8000 << 48)
    u = _new_uuid(uuid.UUID)
    _set_slot(u, "int", value)
    _set_slot(u, "is_safe", _UNKNOWN_SAFETY)
    return u


def _new_ids(n: int) -> list[uuid.UUID]:
    """``n`` random (version 4) UUIDs: the random bits in one os.urandom call, the version and variant bits set
    with numpy, each UUID made without re-validating its int (what ``uuid.UUID(int=...)`` would check)."""
    words = np.frombuffer(os.urandom(16 * n), dtype=">u8").reshape(n, 2).astype(np.uint64)
    hi = (words[:, 0] & np.uint64(~0xF000 & 0xFFFFFFFFFFFFFFFF)) | np.uint64(0x4000)  # version 4
    lo = (words[:, 1] & np.uint64(0x3FFFFFFFFFFFFFFF)) | np.uint64(0x8000000000000000)  # RFC 4122 variant
    ids = []
    for h, low in zip(hi.tolist(), lo.tolist()):
        u = _new_uuid(uuid.UUID)
        _set_slot(u, "int", (h << 64) | low)
        _set_slot(u, "is_safe", _UNKNOWN_SAFETY)
        ids.append(u)
    return ids


def _copies(component: Component, n: int) -> list[Component]:
    """``n`` shallow copies of ``component`` (its attributes shared, like ``copy.copy``), made cheaply."""
    cls = type(component)
    new = object.__new__
    state = getattr(component, "__dict__", None)
    names = []
    for klass in cls.__mro__:
        declared = getattr(klass, "__slots__", ())
        names.extend((declared,) if isinstance(declared, str) else declared)
    slots = [(name, getattr(component, name)) for name in names
             if name not in ("__dict__", "__weakref__") and hasattr(component, name)]
    out = [new(cls) for _ in range(n)]
    if state:
        for c in out:
            c.__dict__.update(state)
    for name, value in slots:
        for c in out:
            _set_slot(c, name, value)
    return out
