"""The editor's systems: one per panel kind, drawing its panel entities with ImGui in ``on_gui_update``.

Each system matches the entities that have an :class:`EditorPanelComponent` and draws those of its
kind that are visible. The editor keeps shared state (the selection, the Save/Load path and status)
on the :class:`~gandalf_core.editor.editor.Editor`, which every panel system holds.
"""

from __future__ import annotations

import uuid
from typing import TYPE_CHECKING, Any

import numpy as np
from imgui_bundle import imgui

from ..components import CameraComponent, LightComponent, MaterialComponent, TransformComponent
from ..ecs import InfoComponent, LinkComponent, System
from .components import EditorPanelComponent, is_editor_entity

if TYPE_CHECKING:
    from .editor import Editor

_ERROR_COLOR = imgui.ImVec4(1.0, 0.45, 0.4, 1.0)


class PanelSystem(System):
    """Draws every visible panel entity of ``kind``; subclasses fill the window in :meth:`draw`."""

    kind = ""

    def __init__(self, editor: Editor) -> None:
        super().__init__([EditorPanelComponent], name=f"Editor{self.kind.capitalize()}System")
        self.editor = editor

    def on_update_system(self, ts: float) -> None:
        """Panels change nothing in the simulation step; they act in :meth:`on_gui_update`."""

    def on_gui_update(self) -> None:
        for entity, (panel,) in zip(self.entities, self.components):
            if panel.kind == self.kind and panel.visible:
                self._window(entity, panel)

    def _window(self, entity: uuid.UUID, panel: EditorPanelComponent) -> None:
        layout = (panel.position, panel.size)
        if panel._shown != layout:  # a program moved or resized the panel: apply it
            imgui.set_next_window_pos(imgui.ImVec2(*panel.position), imgui.Cond_.always)
            imgui.set_next_window_size(imgui.ImVec2(*panel.size), imgui.Cond_.always)
        imgui.begin(f"{panel.title}##{entity}", None, imgui.WindowFlags_.no_collapse)
        try:
            self.draw(panel)
        finally:
            pos, size = imgui.get_window_pos(), imgui.get_window_size()
            panel.position, panel.size = (pos.x, pos.y), (size.x, size.y)
            panel._shown = (panel.position, panel.size)
            imgui.end()

    def draw(self, panel: EditorPanelComponent) -> None:
        raise NotImplementedError

    def remember(self, key: str, width: float | None = None) -> None:
        """Record the last item's rectangle (pixels) under ``key``: tests and tools find widgets by it.

        ``width`` limits it to the widget's fields (without the label to their right).
        """
        lo, hi = imgui.get_item_rect_min(), imgui.get_item_rect_max()
        right = hi.x if width is None else lo.x + width
        self.editor.item_rects[key] = (lo.x, lo.y, right, hi.y)


class HierarchyPanelSystem(PanelSystem):
    """The scene's entities as a tree (InfoComponent names, LinkComponent parents); a click selects."""

    kind = "hierarchy"

    def draw(self, panel: EditorPanelComponent) -> None:
        scene = self.scene
        roots = [e for e in scene.entities if not is_editor_entity(scene, e) and scene.parent_of(e) is None]
        for entity in roots:
            self._node(entity)

    def _node(self, entity: uuid.UUID) -> None:
        scene = self.scene
        link = scene.try_component(entity, LinkComponent)
        children = [c for c in link.children if c in scene] if link is not None else []
        info = scene.try_component(entity, InfoComponent)
        label = info.name if info is not None else str(entity)[:8]
        flags = imgui.TreeNodeFlags_.open_on_arrow | imgui.TreeNodeFlags_.default_open
        flags |= imgui.TreeNodeFlags_.span_avail_width
        if not children:
            flags |= imgui.TreeNodeFlags_.leaf
        if entity == self.editor.selected:
            flags |= imgui.TreeNodeFlags_.selected
        is_open = imgui.tree_node_ex(f"{label}##{entity}", flags)
        self.remember(f"hierarchy/{entity}")
        if imgui.is_item_clicked() and not imgui.is_item_toggled_open():
            self.editor.selected = entity
        if is_open:
            for child in children:
                self._node(child)
            imgui.tree_pop()


class InspectorPanelSystem(PanelSystem):
    """Edits the selected entity's components: Info, Transform, Material colour, Light, Camera."""

    kind = "inspector"

    def draw(self, panel: EditorPanelComponent) -> None:
        scene, entity = self.scene, self.editor.selected
        if entity is None or entity not in scene:
            imgui.text_disabled("nothing selected")
            return
        info = scene.try_component(entity, InfoComponent)
        if info is not None:
            changed, name = imgui.input_text("name", info.name)
            if changed:
                info.name = name
        transform = scene.try_component(entity, TransformComponent)
        if transform is not None and imgui.collapsing_header("Transform", imgui.TreeNodeFlags_.default_open):
            self._transform(transform)
        material = scene.try_component(entity, MaterialComponent)
        if material is not None and imgui.collapsing_header("Material", imgui.TreeNodeFlags_.default_open):
            self._material(material.material)
        light = scene.try_component(entity, LightComponent)
        if light is not None and imgui.collapsing_header("Light", imgui.TreeNodeFlags_.default_open):
            self._light(light)
        camera = scene.try_component(entity, CameraComponent)
        if camera is not None and imgui.collapsing_header("Camera", imgui.TreeNodeFlags_.default_open):
            self._camera(camera)

    def _transform(self, transform: TransformComponent) -> None:
        width = imgui.calc_item_width()  # the three fields share it: X, Y, Z thirds from the left
        for field, speed in (("translation", 0.01), ("rotation", 0.5), ("scale", 0.01)):
            current = np.array(getattr(transform, field), dtype=np.float64)
            changed, value = imgui.drag_float3(field, current.tolist(), speed)
            self.remember(f"inspector/{field}", width)
            if changed:
                setattr(transform, field, _edited(current, value))

    def _material(self, name: str) -> None:
        imgui.text(name)
        color = self.editor.material_color(name)
        if color is None:
            imgui.text_disabled("(not built yet)")
            return
        changed, value = imgui.color_edit3("color", list(color))
        self.remember("inspector/material_color")
        if changed:
            self.editor.set_material_color(name, value)

    def _light(self, light: LightComponent) -> None:
        imgui.text(light.kind)
        changed, value = imgui.color_edit3("light color", [float(c) for c in light.color])
        if changed:
            light.color = np.clip(np.asarray(value, dtype=np.float64), 0.0, None)
        changed, value = imgui.drag_float("intensity", light.intensity, 0.01, 0.0, 1.0e6)
        if changed:
            light.intensity = max(float(value), 0.0)

    def _camera(self, camera: CameraComponent) -> None:
        if camera.projection == "perspective":
            changed, value = imgui.drag_float("fov", float(camera.fov), 0.1, 1.0, 179.0)
            if changed:
                camera.fov = min(max(float(value), 1.0), 179.0)
        # near stays positive and below far: a projection with near >= far is singular.
        changed, value = imgui.drag_float("near", float(camera.near), 0.001, 1.0e-4, float(camera.far))
        if changed:
            camera.near = min(max(float(value), 1.0e-4), float(camera.far) * 0.999)
        changed, value = imgui.drag_float("far", float(camera.far), 0.1, float(camera.near), 1.0e9)
        if changed:
            camera.far = max(float(value), float(camera.near) * 1.001)


class StatsPanelSystem(PanelSystem):
    """Frame rate, frame time, draw calls, entity count and backend."""

    kind = "stats"

    def draw(self, panel: EditorPanelComponent) -> None:
        io = imgui.get_io()
        app = self.editor.app
        renderer = app.renderer
        scene = self.scene
        entities = sum(1 for e in scene.entities if not is_editor_entity(scene, e))
        # In a window: the wall clock, whatever the app's time step. Headless (captures, tests): the app's
        # own time step, so that a picture does not depend on how fast the machine was.
        seconds = self.editor.frame_seconds if app.window is not None else io.delta_time
        imgui.text(f"fps       {1.0 / seconds if seconds else 0.0:8.1f}")
        imgui.text(f"frame     {1000.0 * seconds:8.3f} ms")
        imgui.text(f"draws     {renderer.stats['draw_calls']:8d}")
        imgui.text(f"entities  {entities:8d}")
        imgui.text(f"backend   {renderer.backend:>8}")


class FilePanelSystem(PanelSystem):
    """Save and Load of the scene as USD; the path is typed in, errors are shown in the panel."""

    kind = "file"

    def draw(self, panel: EditorPanelComponent) -> None:
        editor = self.editor
        changed, path = imgui.input_text("path", editor.path)
        if changed:
            editor.path = path
        if imgui.button("Save"):
            editor.save(editor.path)
        self.remember("file/save")
        imgui.same_line()
        if imgui.button("Load"):
            editor.load(editor.path)
        self.remember("file/load")
        if editor.status:
            if editor.status_is_error:
                imgui.text_colored(_ERROR_COLOR, editor.status)
            else:
                imgui.text_wrapped(editor.status)


PANEL_SYSTEMS: tuple[type[PanelSystem], ...] = (
    HierarchyPanelSystem, InspectorPanelSystem, StatsPanelSystem, FilePanelSystem,
)


def _edited(current: np.ndarray, widget: Any) -> np.ndarray:
    """The widget's values where the user changed them, the float64 values elsewhere (ImGui works in float32,
    so an untouched axis would otherwise come back rounded)."""
    widget = np.asarray(widget, dtype=np.float64)
    moved = current.astype(np.float32) != widget.astype(np.float32)
    return np.where(moved, widget, current)
