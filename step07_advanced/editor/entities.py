"""Entities as data the editor can keep: snapshots of a subtree (for destroy/undo), clones (for duplicate).

A snapshot lists, parents first, each entity's id, parent and copies of its components (the LinkComponent is
not copied: restoring gives each entity a fresh Link to its parent). Restoring puts the same ids back, so every
other command that names those entities stays valid.
"""

from __future__ import annotations

import copy
import uuid
from dataclasses import dataclass
from typing import Any

import numpy as np

from gandalf_core.ecs import ColumnarComponent, Component, InfoComponent, LinkComponent, Scene


def clone_component(component: Component) -> Component:
    """An independent copy of ``component`` that can join any scene (a columnar one with its current values)."""
    if isinstance(component, LinkComponent):
        raise TypeError("a LinkComponent is not copied: give the copy its own Link")
    cls = type(component)
    if isinstance(component, ColumnarComponent):
        new = object.__new__(cls)
        for key, value in component.__dict__.items():
            if key not in ("_store", "_row", "_local"):
                new.__dict__[key] = copy.deepcopy(value)
        new._store, new._row = None, -1
        new._local = {name: np.array(getattr(component, name), dtype=np.float64) for name in cls.columns}
        return new
    try:
        return copy.deepcopy(component)
    except Exception:  # noqa: BLE001 - a step's component may hold something that cannot be deep-copied
        return copy.copy(component)


@dataclass
class EntityRecord:
    entity: uuid.UUID
    parent: uuid.UUID | None
    has_link: bool
    components: list[Component]
    index: int = -1  # its place among the parent's children (-1: last)


def place_child(scene: Scene, entity: uuid.UUID, index: int) -> None:
    """Move ``entity`` to position ``index`` among its parent's children (the hierarchy panel's order)."""
    parent = scene.parent_of(entity)
    if parent is None or index < 0:
        return
    children = scene.get_component(parent, LinkComponent).children
    if entity in children:
        children.remove(entity)
        children.insert(min(index, len(children)), entity)


def child_index(scene: Scene, entity: uuid.UUID) -> int:
    parent = scene.parent_of(entity)
    if parent is None:
        return -1
    children = scene.get_component(parent, LinkComponent).children
    return children.index(entity) if entity in children else -1


def subtree(scene: Scene, entity: uuid.UUID) -> list[uuid.UUID]:
    """``entity`` and its descendants, parents first."""
    out = [entity]
    for node in out:
        link = scene.try_component(node, LinkComponent)
        if link is not None:
            out.extend(c for c in link.children if c in scene)
    return out


def snapshot(scene: Scene, entity: uuid.UUID) -> list[EntityRecord]:
    """Copies of ``entity``'s subtree, enough to :func:`restore` it after it was destroyed."""
    records = []
    for node in subtree(scene, entity):
        link = scene.try_component(node, LinkComponent)
        comps = [clone_component(c) for c in scene.components_of(node) if not isinstance(c, LinkComponent)]
        records.append(EntityRecord(node, link.parent if link is not None else None, link is not None, comps,
                                    child_index(scene, node)))
    return records


def restore(scene: Scene, records: list[EntityRecord]) -> None:
    """Create the entities of ``records`` again, with their ids, parents and (fresh copies of) components.

    Destroyed while a system runs (the scene defers it) and restored before it happened: the destruction is
    called off instead."""
    if records and records[0].entity in scene.pending_destroy:
        scene.pending_destroy.remove(records[0].entity)
        return
    for record in records:
        scene.enroll_entity(record.entity)
        for component in record.components:
            scene.add_component(record.entity, clone_component(component))
        parent = record.parent if record.parent in scene else None
        if record.has_link or parent is not None:
            scene.add_component(record.entity, LinkComponent(parent))
            place_child(scene, record.entity, record.index)


def renamed_copy(records: list[EntityRecord]) -> list[EntityRecord]:
    """``records`` with new ids (parents mapped inside the subtree) and the root's name marked as a copy."""
    ids = {r.entity: uuid.uuid4() for r in records}
    out = []
    for i, r in enumerate(records):
        comps = [clone_component(c) for c in r.components]
        if i == 0:
            for c in comps:
                if isinstance(c, InfoComponent):
                    c.name = f"{c.name} copy"
        index = -1 if i == 0 else r.index
        out.append(EntityRecord(ids[r.entity], ids.get(r.parent, r.parent), r.has_link, comps, index))
    return out


def display_name(scene: Scene, entity: uuid.UUID) -> str:
    """A readable name: the Info name, or for an unnamed entity what it is ("Camera", "Mesh cube") and a short id."""
    info = scene.try_component(entity, InfoComponent)
    if info is not None and info.name:
        return info.name
    kinds = [type(c).__name__.removesuffix("Component") for c in scene.components_of(entity)
             if not isinstance(c, LinkComponent)]
    mesh = next((c for c in scene.components_of(entity) if type(c).__name__ == "MeshComponent"), None)
    what = f"Mesh {mesh.mesh}" if mesh is not None else next(
        (k for k in ("Camera", "Light", "ClearColor", "Skybox") if k in kinds), kinds[0] if kinds else "Empty")
    return f"{what} ({str(entity)[:4]})"


def records_ids(records: list[EntityRecord]) -> list[uuid.UUID]:
    return [r.entity for r in records]


def world_of(scene: Scene, entity: uuid.UUID | None) -> Any:
    """The world matrix of ``entity`` (identity for None or an entity without a Transform)."""
    from gandalf_core.components import TransformComponent

    if entity is None:
        return np.eye(4)
    transform = scene.try_component(entity, TransformComponent)
    return np.eye(4) if transform is None else np.array(transform.world)
