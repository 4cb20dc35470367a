"""The editor's edits, each one undoable: entities (create, destroy, duplicate, rename, reparent), components (add,
remove, set a field), transforms, and materials (colour, texture, the values of its Material block). Panels, the
gizmo, menus and tests all call these.

Each method checks its input (an unknown entity, a field a component does not have, a value the field refuses:
the error names it), applies the edit and records a :class:`~step07_advanced.editor.commands.Command` that takes it
back. Commands find components by (entity, type) when they run, so an entity destroyed and restored by undo is
edited again correctly.
"""

from __future__ import annotations

import dataclasses
import uuid
from collections.abc import Sequence
from typing import Any

import numpy as np

from gandalf_core.components import MaterialComponent, MeshComponent, TransformComponent
from gandalf_core.ecs import Component, InfoComponent, LinkComponent, Scene
from gandalf_core.math import decompose_trs, invert_affine
from gandalf_core.systems import world_matrix

from .commands import Command
from .entities import (
    EntityRecord,
    child_index,
    display_name,
    place_child,
    renamed_copy,
    restore,
    snapshot,
    subtree,
)


def _copy(value: Any) -> Any:
    return np.array(value, dtype=np.float64) if isinstance(value, np.ndarray) else value


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return bool(np.shape(a) == np.shape(b) and np.array_equal(a, b))
    return bool(a == b)


class EditorActions:
    """Mixed into :class:`~step07_advanced.editor.editor.Editor` (it provides ``app``, ``commands``, ``selected``)."""

    app: Any
    commands: Any
    selected: uuid.UUID | None

    @property
    def scene(self) -> Scene:
        return self.app.scene

    def _entity(self, entity: uuid.UUID) -> uuid.UUID:
        if entity not in self.scene:
            raise ValueError(f"editor: {entity!r} is not an entity of scene '{self.scene.name}'")
        return entity

    # --- entities ---------------------------------------------------------------------------------------
    def create_entity(self, name: str = "Entity", *components: Component, parent: uuid.UUID | None = None,
                      ) -> uuid.UUID:
        """A new entity named ``name`` (with a Transform unless ``components`` bring one), under ``parent``."""
        scene = self.scene
        if parent is not None:
            self._entity(parent)
        comps = list(components)
        if not any(isinstance(c, InfoComponent) for c in comps):
            comps.insert(0, InfoComponent(name))
        if not any(isinstance(c, TransformComponent) for c in comps):
            comps.append(TransformComponent())
        entity = uuid.uuid4()
        records = [EntityRecord(entity, parent, parent is not None, comps)]  # do() makes it, redo() again
        self.commands.push(Command(f"create {name}", lambda: restore(scene, records),
                                   lambda: self._destroy(scene, entity)))
        self.selected = entity
        return entity

    def _destroy(self, scene: Scene, entity: uuid.UUID) -> None:
        if entity in scene:
            scene.destroy_entity(entity)
        if self.selected is not None and self.selected not in scene:
            self.selected = None

    def destroy_entity(self, entity: uuid.UUID) -> None:
        """Destroy ``entity`` and its descendants (undo brings them back with the same ids)."""
        scene = self.scene
        self._entity(entity)
        records = snapshot(scene, entity)
        self.commands.push(Command(f"destroy {display_name(scene, entity)}", lambda: self._destroy(scene, entity),
                                   lambda: restore(scene, records)))

    def duplicate_entity(self, entity: uuid.UUID) -> uuid.UUID:
        """A copy of ``entity``'s subtree (new ids, the copy's name ends in " copy") under the same parent."""
        scene = self.scene
        self._entity(entity)
        records = renamed_copy(snapshot(scene, entity))
        copy_id = records[0].entity
        self.commands.push(Command(f"duplicate {display_name(scene, entity)}", lambda: restore(scene, records),
                                   lambda: self._destroy(scene, copy_id)))
        self.selected = copy_id
        return copy_id

    def rename_entity(self, entity: uuid.UUID, name: str, merge: bool = False) -> None:
        """Set the entity's Info name (adding an InfoComponent to an unnamed entity)."""
        if not isinstance(name, str):
            raise TypeError(f"editor: a name must be a string, got {name!r}")
        scene = self.scene
        self._entity(entity)
        if scene.try_component(entity, InfoComponent) is None:
            self.add_component(entity, InfoComponent(name))
            return
        self.set_field(entity, InfoComponent, "name", name, merge=merge, label=f"rename to {name}")

    def reparent(self, entity: uuid.UUID, parent: uuid.UUID | None, keep_world: bool = True) -> None:
        """Move ``entity`` under ``parent`` (None: make it a root). With ``keep_world`` it stays where it is on
        screen (its local transform is recomputed); a cycle (a parent under its own child) is refused."""
        scene = self.scene
        self._entity(entity)
        if parent is not None:
            self._entity(parent)
            if parent in subtree(scene, entity):
                raise ValueError(f"editor: cannot put {display_name(scene, entity)} under "
                                 f"{display_name(scene, parent)}, which is inside it")
        old_parent = scene.parent_of(entity)
        if old_parent == parent:
            return
        had_link = scene.has_component(entity, LinkComponent)
        old_index = child_index(scene, entity)
        # Parenting gives a parent without a Link one: undo takes it away again (when it is left empty).
        bare_parent = parent if parent is not None and not scene.has_component(parent, LinkComponent) else None
        transform = scene.try_component(entity, TransformComponent)
        old_local = None if transform is None else (transform.translation.copy(), transform.quaternion.copy(),
                                                    transform.scale.copy())
        new_local = old_local
        if transform is not None and keep_world:
            local = invert_affine(_world(scene, parent)) @ _world(scene, entity)
            t, q, s = decompose_trs(local)
            new_local = (t, q, s)

        def apply(target: uuid.UUID | None, trs: Any, link: bool, index: int = -1) -> None:
            if scene.has_component(entity, LinkComponent):
                if target is None and not link:
                    scene.remove_component(entity, LinkComponent)
                else:
                    scene.set_parent(entity, target)
            else:
                scene.add_component(entity, LinkComponent(target))
            place_child(scene, entity, index)
            if bare_parent is not None and target != bare_parent and bare_parent in scene:
                link = scene.try_component(bare_parent, LinkComponent)
                if link is not None and link.parent is None and not link.children:
                    scene.remove_component(bare_parent, LinkComponent)
            if trs is not None:
                comp = scene.get_component(entity, TransformComponent)
                comp.translation, comp.quaternion, comp.scale = trs

        self.commands.push(Command(
            f"reparent {display_name(scene, entity)}",
            lambda: apply(parent, new_local, True), lambda: apply(old_parent, old_local, had_link, old_index)))

    # --- components -------------------------------------------------------------------------------------
    def add_component(self, entity: uuid.UUID, component: Component) -> Component:
        """Attach ``component`` (replacing one of its type; undo puts the old one back)."""
        scene = self.scene
        self._entity(entity)
        if not isinstance(component, Component):
            raise TypeError(f"editor: {component!r} is not a component")
        ctype = type(component)
        if ctype is LinkComponent:
            raise ValueError("editor: set a parent with reparent(), not by adding a LinkComponent")
        old = scene.try_component(entity, ctype)

        def do() -> None:
            scene.add_component(entity, component)

        def undo() -> None:
            scene.remove_component(entity, ctype)
            if old is not None:
                scene.add_component(entity, old)

        self.commands.push(Command(f"add {ctype.__name__}", do, undo))
        return component

    def remove_component(self, entity: uuid.UUID, component_type: type[Component]) -> None:
        """Detach the entity's ``component_type`` (undo re-attaches the same component, values and all)."""
        scene = self.scene
        self._entity(entity)
        if component_type is LinkComponent:
            raise ValueError("editor: make an entity a root with reparent(entity, None)")
        component = scene.get_component(entity, component_type)  # raises naming what the entity has
        self.commands.push(Command(f"remove {component_type.__name__}",
                                   lambda: scene.remove_component(entity, component_type),
                                   lambda: scene.add_component(entity, component)))

    # --8<-- [start:set_field]
    def set_field(self, entity: uuid.UUID, component_type: type[Component], field: str, value: Any,
                  merge: bool = False, label: str | None = None) -> None:
        """Set ``component.field = value`` (checked by the component, whose error names the field)."""
        scene = self.scene
        self._entity(entity)
        component = scene.get_component(entity, component_type)
        if not hasattr(component, field) or field.startswith("_"):
            raise AttributeError(f"editor: {component_type.__name__} has no field '{field}'")
        before = _copy(getattr(component, field))
        setattr(component, field, value)  # validates now, so a bad value never reaches the history
        after = _copy(getattr(component, field))
        setattr(component, field, before)
        if _same(before, after):
            return

        def put(v: Any) -> None:
            setattr(scene.get_component(entity, component_type), field, _copy(v))

        label = label or f"{component_type.__name__}.{field}"
        key = (entity, component_type, field)
        command = Command(label, lambda: put(after), lambda: put(before), merge_key=key)
        self.commands.push(command, merge=merge)
    # --8<-- [end:set_field]

    def set_transform(self, entity: uuid.UUID, translation: Sequence[float] | None = None,
                      quaternion: Sequence[float] | None = None, scale: Sequence[float] | None = None,
                      merge: bool = False) -> None:
        """Set any of the entity's local translation, rotation (unit quaternion w, x, y, z) and scale as one edit."""
        scene = self.scene
        self._entity(entity)
        transform = scene.get_component(entity, TransformComponent)
        before = (transform.translation.copy(), transform.quaternion.copy(), transform.scale.copy())
        after = tuple(np.array(v if v is not None else b, dtype=np.float64)
                      for v, b in zip((translation, quaternion, scale), before))
        probe = TransformComponent()
        probe.translation, probe.scale = after[0], after[2]  # checks shape and finiteness, naming the field
        probe.quaternion = after[1] / np.linalg.norm(after[1]) if np.linalg.norm(after[1]) > 0 else after[1]
        after = (probe.translation.copy(), probe.quaternion.copy(), probe.scale.copy())
        if all(np.array_equal(a, b) for a, b in zip(after, before)):
            return

        def put(trs: tuple[np.ndarray, ...]) -> None:
            comp = scene.get_component(entity, TransformComponent)
            comp.translation, comp.quaternion, comp.scale = trs

        self.commands.push(Command(f"transform {display_name(scene, entity)}", lambda: put(after),
                                   lambda: put(before), merge_key=(entity, "transform")), merge=merge)

    def set_world_matrix(self, entity: uuid.UUID, world: np.ndarray, merge: bool = False) -> None:
        """Place ``entity`` so that its world matrix becomes ``world`` (what the gizmo hands back)."""
        scene = self.scene
        local = invert_affine(_world(scene, scene.parent_of(entity))) @ np.asarray(world, dtype=np.float64)
        t, q, s = decompose_trs(local)
        self.set_transform(entity, t, q, s, merge=merge)

    # --- resources --------------------------------------------------------------------------------------
    def spawn_mesh(self, mesh: str, material: str | None = None, position: Sequence[float] = (0.0, 0.0, 0.0),
                   parent: uuid.UUID | None = None) -> uuid.UUID:
        """A new entity drawing ``mesh`` (with ``material``, or the scene's first material), named after the mesh."""
        assets = self.scene.assets
        if mesh not in assets.meshes:
            raise ValueError(f"editor: no mesh '{mesh}' in scene '{self.scene.name}' "
                             f"(known: {', '.join(sorted(assets.meshes)) or 'none'})")
        material = material or next(iter(assets.materials), None)
        if material is None or material not in assets.materials:
            raise ValueError(f"editor: mesh '{mesh}' needs a material; scene '{self.scene.name}' has "
                             f"{'no material ' + repr(material) if material else 'none'}")
        return self.create_entity(mesh, TransformComponent(position), MeshComponent(mesh),
                                  MaterialComponent(material), parent=parent)

    def set_material_texture(self, material: str, texture: str, slot: int = 0) -> None:
        """Put ``texture`` into ``material``'s texture ``slot`` (the renderer rebuilds the material on next use)."""
        assets = self.scene.assets
        data = self._material(material)
        if texture not in assets.textures:
            raise ValueError(f"editor: no texture '{texture}' in scene '{self.scene.name}' "
                             f"(known: {', '.join(sorted(assets.textures)) or 'none'})")
        if not 0 <= slot < max(len(data.textures), 1):
            raise ValueError(f"editor: material '{material}' has {len(data.textures)} texture slot(s), not {slot}")
        textures = list(data.textures) or [texture]
        textures[slot] = texture
        new = dataclasses.replace(data, textures=tuple(textures))

        def put(value: Any) -> None:
            self.scene.assets.material(material, value)
            self._material_colors.pop(material, None)

        self.commands.push(Command(f"texture of {material}", lambda: put(new), lambda: put(data)))

    def set_material_param(self, material: str, field: str, value: Any, merge: bool = False) -> None:
        """Set one of ``material``'s values (a field of its shader's Material block; the renderer rebuilds the
        material on next use); undoable, a drag is one step."""
        data = self._material(material)
        if field not in data.params:
            raise ValueError(f"editor: material '{material}' has no value '{field}' "
                             f"(it has: {', '.join(sorted(data.params)) or 'none'})")
        new = dataclasses.replace(data, params={**data.params, field: value})  # checked here, naming the field
        if _same(np.asarray(new.params[field]), np.asarray(data.params[field])):
            return

        def put(value: Any) -> None:
            self.scene.assets.material(material, value)

        self.commands.push(Command(f"{field} of {material}", lambda: put(new), lambda: put(data),
                                   merge_key=("param", material, field)), merge=merge)

    def _material(self, material: str) -> Any:
        """The scene's MaterialData named ``material``; a ValueError naming it and the scene when there is none."""
        data = self.scene.assets.materials.get(material)
        if data is None:
            raise ValueError(f"editor: no material '{material}' in scene '{self.scene.name}'")
        return data

    _material_colors: dict[str, tuple[float, ...]]

    # --- history ----------------------------------------------------------------------------------------
    def undo(self) -> str | None:
        """Take back the last edit (its label, or None)."""
        return self.commands.undo()

    def redo(self) -> str | None:
        """Apply the last undone edit again (its label, or None)."""
        return self.commands.redo()


def _world(scene: Scene, entity: uuid.UUID | None) -> np.ndarray:
    """The entity's world matrix from its and its ancestors' local transforms now, not the one the transform
    system cached last frame: an entity created or moved this frame has no up-to-date ``world`` yet."""
    return np.eye(4) if entity is None else world_matrix(scene, entity)
