"""The viewport panel: the scene rendered into a texture of the panel's size, with ImGuizmo gizmos.

Its system runs in the frame's update just before the render system: it renders the scene from the primary camera
into an :class:`~gandalf_core.render.offscreen.OffscreenTarget` that follows the panel's content size (aspect
included), and the panel shows that texture. For the selected entity, ImGuizmo draws a translate, rotate or scale
gizmo (W, E, R; local or world space); a drag moves the entity through the editor's undoable
``set_world_matrix`` (one undo step per drag). A mesh dragged from the content browser onto the picture is placed
in the scene.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from imgui_bundle import imgui, imguizmo

from gandalf_core.components import TransformComponent

from .components import EditorPanelComponent
from .panel_base import PanelSystem

_GZ = imguizmo.im_guizmo
OPERATIONS = {"translate": _GZ.OPERATION.translate, "rotate": _GZ.OPERATION.rotate, "scale": _GZ.OPERATION.scale}
MODES = {"local": _GZ.MODE.local, "world": _GZ.MODE.world}


def _matrix16(m: np.ndarray) -> Any:
    """ImGuizmo's layout: column-major floats (OpenGL's), i.e. the transpose of our row-major array."""
    return _GZ.Matrix16(np.asarray(m, dtype=np.float32).T.ravel().tolist())


class ViewportPanelSystem(PanelSystem):
    """Renders the scene into the panel's texture and handles the gizmo."""

    kind = "viewport"
    updates_each_frame = True  # it renders the scene into its texture in the frame's update

    @property
    def window_flags(self) -> int:  # type: ignore[override]
        flags = imgui.WindowFlags_.no_collapse | imgui.WindowFlags_.no_scrollbar
        if self.editor.gizmo_over or self.editor.gizmo_using:  # a press on the gizmo must not drag the window
            flags |= imgui.WindowFlags_.no_move
        return flags

    def __init__(self, editor) -> None:  # noqa: ANN001 - the Editor
        super().__init__(editor)
        self.target: Any = None
        self._texture_ref: Any = None
        self._texture_key: Any = None
        #: The image's content size the panel asked for in the last GUI frame (the target follows it).
        self.wanted: tuple[int, int] | None = None
        self.operation = "translate"
        self.mode = "local"
        #: Draw calls of the viewport's render this frame (the stats panel adds them to the frame's).
        self.draw_calls = 0

    # --- the frame: render into the target ---------------------------------------------------------------
    # --8<-- [start:viewport_render]
    def on_update_system(self, ts: float) -> None:
        from gandalf_core.render import RenderSystem
        from gandalf_core.render.offscreen import OffscreenTarget

        scene = self.scene
        renderers = [s for s in scene.systems if isinstance(s, RenderSystem)]
        shown = self.wanted is not None and any(p.kind == "viewport" and p.visible for (p,) in self.components)
        # The panels cover the frame: while the viewport shows the scene, the frame itself is only cleared.
        self._draw_scene_in_frame(renderers, not shown)
        self.draw_calls = 0
        if not shown or not renderers:
            return
        renderer = self.editor.app.renderer
        if self.target is None:
            self.target = OffscreenTarget(renderer, *self.wanted)
        elif self.target.resize(*self.wanted):
            self._forget_texture()
        with self.target.drawing():
            renderer.render(renderers[0].frame_data(ts), scene.assets)
        self.draw_calls = renderer.stats["draw_calls"]  # the frame's own render counts from 0 again
    # --8<-- [end:viewport_render]

    def _forget_texture(self) -> None:
        if self._texture_key is not None:
            self.editor._gui.forget_texture(self._texture_key)
            self.editor.invalidate_gui()  # the last GUI frame shows the old texture: lay it out again
        self._texture_ref = self._texture_key = None

    @staticmethod
    def _draw_scene_in_frame(renderers: list[Any], draw: bool) -> None:
        for system in renderers:
            system.draws_scene = draw

    def on_destroy_system(self) -> None:
        from gandalf_core.render import RenderSystem

        if self.scene is not None:
            self._draw_scene_in_frame([s for s in self.scene.systems if isinstance(s, RenderSystem)], True)
        self._forget_texture()
        if self.target is not None:
            self.target.release()
            self.target = None

    # --- the GUI -------------------------------------------------------------------------------------------
    def draw(self, panel: EditorPanelComponent) -> None:
        editor = self.editor
        for name, short in zip(OPERATIONS, "TRS"):  # W, E, R as keys
            if imgui.radio_button(short, self.operation == name):
                self.operation = name
            self.remember(f"viewport/{name}")
            if imgui.is_item_hovered():
                imgui.set_tooltip(name)
            imgui.same_line()
        imgui.text("|")
        imgui.same_line()
        for name in MODES:
            if imgui.radio_button(name, self.mode == name):
                self.mode = name
            self.remember(f"viewport/{name}")
            imgui.same_line()
        imgui.new_line()
        if imgui.is_window_focused() and not imgui.get_io().want_text_input:
            for key, name in ((imgui.Key.w, "translate"), (imgui.Key.e, "rotate"), (imgui.Key.r, "scale")):
                if imgui.is_key_pressed(key, False):
                    self.operation = name
        avail = imgui.get_content_region_avail()
        size = (max(int(avail.x), 16), max(int(avail.y), 16))
        self.wanted = size
        origin = imgui.get_cursor_screen_pos()
        target = self.target
        if target is None or target.display_texture is None:
            imgui.dummy(imgui.ImVec2(*size))
        else:
            if self._texture_ref is None:
                self._texture_key, self._texture_ref = editor._gui.texture_ref(target.display_texture)
            flip = editor.app.renderer.backend == "opengl"  # GL textures store the bottom row first
            imgui.image(self._texture_ref, imgui.ImVec2(*target.size),
                        imgui.ImVec2(0, 1 if flip else 0), imgui.ImVec2(1, 0 if flip else 1))
        self.remember("viewport/image")
        if imgui.begin_drag_drop_target():
            payload = imgui.accept_drag_drop_payload_py_id("GANDALF_MESH")
            if payload is not None:
                _kind, mesh = editor.payload(payload.data_id)
                self.act(editor.spawn_mesh, mesh)
            imgui.end_drag_drop_target()
        shown = target.size if target is not None else size
        self._gizmo(origin.x, origin.y, *shown)

    def _gizmo(self, x: float, y: float, width: float, height: float) -> None:
        editor, scene = self.editor, self.scene
        editor.gizmo_over = editor.gizmo_using = False
        entity = editor.selected
        if entity is None or entity not in scene or scene.try_component(entity, TransformComponent) is None:
            return
        from gandalf_core.render import RenderSystem

        renderers = [s for s in scene.systems if isinstance(s, RenderSystem)]
        chosen = renderers[0].primary_camera() if renderers else None
        if chosen is None or chosen[0] == entity:
            return
        _cam, camera, cam_transform = chosen
        view = np.linalg.inv(cam_transform.world)  # one LAPACK call: this runs every frame
        projection = camera.projection_matrix("opengl", width / height)
        world = np.array(scene.get_component(entity, TransformComponent).world)
        # --8<-- [start:gizmo]
        _GZ.set_orthographic(camera.projection == "orthographic")
        _GZ.set_gizmo_size_clip_space(0.2)  # a panel is small: a larger gizmo is easier to grab
        _GZ.set_drawlist()
        _GZ.set_rect(x, y, width, height)
        matrix = _matrix16(world)
        moved = _GZ.manipulate(_matrix16(view), _matrix16(projection), OPERATIONS[self.operation],
                               MODES[self.mode], matrix)
        editor.gizmo_over, editor.gizmo_using = bool(_GZ.is_over()), bool(_GZ.is_using())
        editor.gizmo_hovered = _GZ.get_hovered_move_type().name.removeprefix("mt_")  # "move_x", "none", ...
        if moved:
            new_world = np.array(matrix.values, dtype=np.float64).reshape(4, 4).T
            self.act(editor.set_world_matrix, entity, new_world, merge=True)
        # --8<-- [end:gizmo]
