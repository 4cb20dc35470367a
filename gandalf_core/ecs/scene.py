"""The Scene: entities (UUIDs), their components, and the systems that run over them.

Systems run in the order they were added (``add_system(system, index=...)`` inserts elsewhere);
that order is the documented update order of a frame.
"""

from __future__ import annotations

import uuid
from collections.abc import Iterator
from typing import Any, TypeVar

from ..resources.assets import Assets
from .component import ColumnarComponent, ColumnStore, Component
from .errors import HierarchyCycleError, MissingComponentError, NotAComponentError, UnknownEntityError
from .hierarchy import LinkComponent
from .info import InfoComponent
from .system import System

C = TypeVar("C", bound=Component)


class Scene:
    """A world of entities. Entities are UUIDs; components are attached per type (one of each type)."""

    def __init__(self, name: str = "scene") -> None:
        self.name = name
        self.app: Any = None  # set by the Application that runs this scene
        self.assets = Assets()  # meshes, textures and materials by name (backend-neutral data)
        self._entities: dict[uuid.UUID, dict[type, Component]] = {}
        self._stores: dict[type, ColumnStore] = {}
        self._systems: list[System] = []
        self._systems_by_type: dict[type, list[System]] = {}
        self._queries: dict[tuple[type, ...], System] = {}
        self.hierarchy_version = 0  # bumped whenever a Link is added, removed or re-parented
        self.membership_version = 0  # bumped whenever any component is added or removed

    # --- entities ---------------------------------------------------------------------------------
    def enroll_entity(self) -> uuid.UUID:
        """Create a new, empty entity and return its id."""
        entity = uuid.uuid4()
        self._entities[entity] = {}
        return entity

    def create_entity(self, *components: Component) -> uuid.UUID:
        """Enroll an entity and add ``components`` to it (a shorthand for scene-building code)."""
        entity = self.enroll_entity()
        for component in components:
            self.add_component(entity, component)
        return entity

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
        """Remove an entity, its components, and (through its Link) all of its descendants."""
        self._require(entity)
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
        kept_children: list[uuid.UUID] = []
        if component_type is LinkComponent:
            self._check_parent(entity, component.parent)
            if LinkComponent in comps:  # a new Link replaces the parent, not the entity's children
                kept_children = list(comps[LinkComponent].children)
        if component_type in comps:
            self.remove_component(entity, component_type)
        if isinstance(component, ColumnarComponent):
            self.store(component_type).attach(component)
        comps[component_type] = component
        if component_type is LinkComponent:
            self._attach_link(entity, component)
            for child in kept_children:
                self._entities[child][LinkComponent]._parent = entity
                component.children.append(child)
        self.membership_version += 1
        for system in self._systems_by_type.get(component_type, ()):
            if system.matches(comps):
                system._add_member(entity, tuple(comps[t] for t in system.component_types))
        return component

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
        for t in system.component_types:
            self._systems_by_type.setdefault(t, []).append(system)
        for entity, comps in self._entities.items():
            if system.matches(comps):
                system._add_member(entity, tuple(comps[t] for t in system.component_types))

    def remove_system(self, system: System) -> None:
        self._systems.remove(system)
        for t in system.component_types:
            self._systems_by_type[t].remove(system)
        system.on_destroy_system()
        system.scene = None
        system._members.clear()
        system._lists = None

    def get_system(self, system_type: type[System]) -> System:
        for system in self._systems:
            if isinstance(system, system_type):
                return system
        raise KeyError(f"scene '{self.name}' has no {system_type.__name__}")

    def update(self, ts: float) -> None:
        """Run one frame: every enabled system's ``on_update_system`` in order."""
        for system in self._systems:
            if system.enabled:
                system.on_update_system(ts)

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
