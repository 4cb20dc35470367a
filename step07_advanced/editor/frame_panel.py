"""The frame inspector panel: capture a frame, walk its passes and draws, view any texture, pick a pixel.

* **Capture frame** records the next frame (:mod:`.frame_inspector.capture`): a tree of passes (shadow map,
  opaque, sky, transparent, overlay: the editor's own GUI) with their GPU milliseconds, and under each its draws.
  A selected draw shows its entities, mesh (vertex and index counts, vertex layout), material, shader files,
  pipeline state, the uniform blocks decoded by field name, and the textures and buffers it binds.
* **Texture viewer**: any texture of the renderer (every cube face and mip level), the viewport's colour and depth
  and the shadow map, as an image; the pointer over it reads out the texel's value. (imgui-bundle's
  ``imgui_tex_inspect`` draws through the C++ OpenGL backend's callbacks, which neither of the editor's GUI
  renderers runs, so the viewer is a plain image with its own read-out, the same in both APIs.)
* **Pick**: with "pick on click" on, a click on the viewport picks that pixel (:mod:`.frame_inspector.picking`):
  the draw, entity, material and shader that wrote it, and its depth; the entity becomes the selection.

Captures, picks and texture reads happen between frames, in this system's update (before the viewport renders),
never inside the GUI; an open panel that is not used costs only its drawing, a closed one nothing.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from imgui_bundle import imgui

from gandalf_core.render.gpu_memory import MIB

from .components import EditorPanelComponent
from .entities import display_name
from .panel_base import ERROR_COLOR, PanelSystem, wrapped


def _number(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, list):
        return "(" + ", ".join(_number(v) for v in value) + ")"
    return str(value)


def _short_path(path: str) -> str:
    """A shader file's path from the working folder when it lies below it (the course's files), else as it is."""
    import os

    try:
        relative = os.path.relpath(path)
    except ValueError:
        return path
    return path if relative.startswith("..") else relative


def _ms(value: float | None) -> str:
    return f"{value:.3f} ms" if value is not None else "- ms"


class FramePanelSystem(PanelSystem):
    """Frame capture, draw details, texture viewer and pixel picking (see the module's docstring)."""

    kind = "frame"
    updates_each_frame = True  # captures and picks run between frames, before the viewport renders

    def __init__(self, editor) -> None:  # noqa: ANN001 - the Editor
        super().__init__(editor)
        #: The last captured frame (a FrameCapture) and the last pick (a Pick), or None.
        self.capture: Any = None
        self.picked: Any = None
        #: Whether a click on the viewport picks.
        self.pick_on_click = False
        self.selected_draw: int | None = None
        self._recorder: Any = None
        self._want_capture = False
        self._want_pick: tuple[int, int] | None = None
        self._viewport_rect: tuple[float, float, float, float] | None = None
        self.error = ""
        self._was_shown = False
        self._focus_frames = 0
        self._open_viewer = False
        # texture viewer
        self.source = "frame colour"
        self.face = 0
        self.level = 0
        self.texels: np.ndarray | None = None
        self._view_key: Any = None
        self._display: Any = None
        self._display_ref: Any = None
        self._display_key: Any = None

    # --- what tests and other tools call ---------------------------------------------------------------
    def request_capture(self) -> None:
        """Capture the next frame."""
        self._want_capture = True

    def request_pick(self, x: int, y: int) -> None:
        """Pick pixel (``x``, ``y``) of the viewport's picture (from its top-left corner) before the next frame."""
        self._want_pick = (int(x), int(y))

    def view_texture(self, source: str, face: int = 0, level: int = 0) -> None:
        """Show ``source`` (a texture name, "frame colour", "frame depth" or "shadow map") in the viewer."""
        self.source, self.face, self.level = source, int(face), int(level)
        self._view_key = None
        self._open_viewer = True  # the viewer's header opens to show it

    # --- between frames -------------------------------------------------------------------------------
    def on_update_system(self, ts: float) -> None:
        from .frame_inspector.capture import FrameRecorder, name_entities

        renderer = self.editor.app.renderer
        self._viewport_rect = self.editor.item_rects.get("viewport/image")
        if self._recorder is not None:  # the captured frame has ended
            renderer.recorder = None
            self.capture = self._recorder.finish()
            self._recorder = None
            name_entities(self.capture, self.scene)
            self.selected_draw = None
            self.editor.invalidate_gui()
        if self._want_pick is not None:  # before a capture is armed: a pick draws a frame of its own
            x, y = self._want_pick
            self._want_pick = None
            self.editor.attempt(self._pick, x, y, ts)
            self.editor.invalidate_gui()
        if self._want_capture:
            self._want_capture = False
            self._recorder = FrameRecorder(renderer)
            renderer.recorder = self._recorder
        if self.panel_shown():
            self._refresh_texture()

    def panel_shown(self) -> bool:
        return any(p.kind == self.kind and p.visible for (p,) in self.components)

    def _pick(self, x: int, y: int, ts: float) -> None:
        from gandalf_core.render import RenderSystem

        from .frame_inspector.picking import pick_frame

        target = self.editor.viewport.target if self.editor.viewport is not None else None
        systems = [s for s in self.scene.systems if isinstance(s, RenderSystem)]
        if target is None or not systems:
            raise ValueError("pick: the viewport shows no picture yet")
        with target.drawing():
            self.picked = pick_frame(self.editor.app.renderer, systems[0].frame_data(ts), self.scene, x, y)
        if self.picked.entity is not None and self.picked.entity in self.scene:
            self.editor.selected = self.picked.entity

    def _refresh_texture(self) -> None:
        """Read the viewed texture again when the choice changed or a new frame was captured."""
        from .frame_inspector.texture_readback import display_rgba, read_source

        key = (self.source, self.face, self.level, id(self.capture))
        if key == self._view_key:
            return
        self._view_key = key
        renderer = self.editor.app.renderer
        target = self.editor.viewport.target if self.editor.viewport is not None else None
        try:
            if target is not None and self.source.startswith("frame "):
                with target.drawing():  # the viewport's picture, not the editor's own frame
                    self.texels = read_source(renderer, self.source, self.face, self.level)
            else:
                self.texels = read_source(renderer, self.source, self.face, self.level)
            self.error = ""
        except (ValueError, KeyError) as exc:
            self.texels, self.error = None, str(exc)
            return
        self._upload(display_rgba(self.texels))
        self.editor.invalidate_gui()

    def _upload(self, rgba: np.ndarray) -> None:
        """The viewer's image as a texture the GUI can show (made again when its size changes)."""
        from .frame_inspector.texture_readback import upload_display

        size = rgba.shape[1::-1]
        if self._display is not None and self._display_size != size:
            self._forget_display()
        self._display, shown = upload_display(self.editor.app.renderer, rgba, self._display)
        if self._display_ref is None:
            self._display_size = size
            self._display_key, self._display_ref = self.editor._gui.texture_ref(shown)

    def _forget_display(self) -> None:
        from .frame_inspector.texture_readback import release_display

        if self._display_key is not None:
            self.editor._gui.forget_texture(self._display_key)
        if self._display is not None:
            release_display(self._display)
        self._display = self._display_ref = self._display_key = None

    def on_destroy_system(self) -> None:
        if self._recorder is not None:  # armed, its frame not run: given up
            self.editor.app.renderer.recorder = None
            self._recorder.abandon()
            self._recorder = None
        self._forget_display()

    # --- the GUI -------------------------------------------------------------------------------------
    def _window(self, entity: Any, panel: EditorPanelComponent) -> None:
        # Just opened (it starts hidden, over other panels): bring it to the front, on two GUI frames, as panels
        # made in its first frame are put in front of it.
        if self._focus_frames > 0:
            imgui.set_next_window_focus()
            self._focus_frames -= 1
        super()._window(entity, panel)

    def on_gui_update(self) -> None:
        shown = self.panel_shown()
        if shown and not self._was_shown:
            self._focus_frames = 2
        self._was_shown = shown
        super().on_gui_update()

    def draw(self, panel: EditorPanelComponent) -> None:
        if imgui.button("Capture frame"):
            self.request_capture()
        self.remember("frame/capture")
        imgui.same_line()
        _changed, self.pick_on_click = imgui.checkbox("pick on click", self.pick_on_click)
        self.remember("frame/pick")
        self._viewport_click()
        if self.picked is not None:
            self._pick_summary()
        if self.capture is not None:
            imgui.text_disabled(f"GPU timing: {self.capture.timing}")
            if self.capture.gpu_memory:  # by kind: the stats panel, hovered
                imgui.text_disabled(f"GPU memory held: {self.capture.gpu_memory['total'] / MIB:.1f} MiB")
            self._tree()
            self._details()
        if self._open_viewer:
            imgui.set_next_item_open(True)
            self._open_viewer = False
        if imgui.collapsing_header("Texture viewer"):
            self._texture_viewer()
        self.remember("frame/viewer")

    def _viewport_click(self) -> None:
        rect = self._viewport_rect
        target = self.editor.viewport.target if self.editor.viewport is not None else None
        if not (self.pick_on_click and rect and target is not None) or imgui.is_window_hovered():
            return
        if self.editor.gizmo_over or not imgui.is_mouse_clicked(0):
            return
        mx, my = imgui.get_mouse_pos()
        x0, y0, x1, y1 = rect
        if x0 <= mx < x1 and y0 <= my < y1:
            self.request_pick(int((mx - x0) / (x1 - x0) * target.size[0]), int((my - y0) / (y1 - y0) * target.size[1]))

    def _pick_summary(self) -> None:
        picked, scene = self.picked, self.scene
        who = display_name(scene, picked.entity) if picked.entity is not None and picked.entity in scene else "-"
        if picked.draw is None:
            imgui.text(f"pixel ({picked.x}, {picked.y}): background, depth {picked.depth:.6g}")
        else:
            imgui.text(f"pixel ({picked.x}, {picked.y}): {who}, draw #{picked.draw.index} ({picked.draw.pass_name})")
            imgui.text(f"  material '{picked.material}', shader '{picked.shader}', depth {picked.depth:.6g}")
        self.remember("frame/picked")

    def _tree(self) -> None:
        for i, p in enumerate(self.capture.passes):
            flags = imgui.TreeNodeFlags_.default_open if p.name != "overlay" else 0
            opened = imgui.tree_node_ex(f"{p.name}  {_ms(p.gpu_ms)}  -> {p.target}##pass{i}", flags)
            self.remember(f"frame/pass/{i}")
            if not opened:
                continue
            for d in p.draws:
                if imgui.selectable(f"{d.label}  {_ms(d.gpu_ms)}##draw{d.index}", self.selected_draw == d.index)[0]:
                    self.selected_draw = d.index
                self.remember(f"frame/draw/{d.index}")
            imgui.tree_pop()

    def _details(self) -> None:
        draws = {d.index: d for d in self.capture.draws}
        d = draws.get(self.selected_draw) if self.selected_draw is not None else None
        if d is None:
            return
        imgui.separator()
        scene = self.scene
        names = [display_name(scene, e) for e in d.entities if e in scene]
        imgui.text(f"draw #{d.index} in '{d.pass_name}': {', '.join(names) or 'no entity'}")
        imgui.text(f"mesh '{d.mesh}': {d.vertex_count} vertices, {d.index_count} indices, {d.instances} instance(s)")
        for line in d.layout:
            imgui.bullet_text(line)
        imgui.text(f"material '{d.material}', shader '{d.shader}'")
        if d.shader_files and imgui.tree_node(f"{_short_path(d.shader_files[0])} (+{len(d.shader_files) - 1} "
                                              "more)##files"):
            for path in d.shader_files[1:]:
                imgui.bullet_text(_short_path(path))
            imgui.tree_pop()
        if imgui.tree_node_ex("pipeline state", imgui.TreeNodeFlags_.default_open):
            for key, value in d.state.items():
                imgui.text(f"{key:14} {value}")
            imgui.tree_pop()
        self.remember("frame/state")
        for block, content in d.blocks.items():
            flags = imgui.TreeNodeFlags_.default_open if block == "Material" else 0
            if imgui.tree_node_ex(f"{block} block ({content['binding']})##{block}", flags):
                self._block_fields(block, content["values"])
                imgui.tree_pop()
            self.remember(f"frame/block/{block}")
        for texture in d.textures:
            imgui.text(f"texture {texture['slot']}: '{texture['name']}' {texture.get('kind', '')} "
                       f"{texture.get('size', '')}")
            imgui.same_line()
            if imgui.small_button(f"view##{texture['slot']}"):
                self.view_texture(texture["name"] if texture["name"] != "shadow map" else "shadow map")
        for buffer in d.buffers:
            imgui.text(f"buffer {buffer['slot']}: {buffer['name']}, {buffer.get('bytes')} bytes")

    @staticmethod
    def _block_fields(block: str, values: dict[str, Any]) -> None:
        count = values.get("count", [None])[0] if block == "Lights" else None
        for name, value in values.items():
            if block == "Lights" and name in ("position", "color") and count is not None:
                value = value[:count]  # the lights in use, not the whole array
            imgui.text(f"{name} = {_number(value)}")

    def _texture_viewer(self) -> None:
        from .frame_inspector.texture_readback import CUBE_FACES, texture_sources

        sources = {s.name: s for s in texture_sources(self.editor.app.renderer)}
        if imgui.begin_combo("texture", self.source):
            for name, source in sources.items():
                if imgui.selectable(f"{name} ({source.kind})", name == self.source)[0]:
                    self.view_texture(name)
            imgui.end_combo()
        self.remember("frame/texture")
        source = sources.get(self.source)
        if source is not None and source.faces > 1:
            changed, face = imgui.combo("face", self.face, list(CUBE_FACES))
            if changed:
                self.view_texture(self.source, face, self.level)
        if source is not None and source.levels > 1:
            changed, level = imgui.slider_int("mip level", self.level, 0, source.levels - 1)
            if changed:
                self.view_texture(self.source, self.face, level)
        if self.error:
            wrapped(self.error, ERROR_COLOR)
        if self._display_ref is None or self.texels is None:
            return
        height, width = self.texels.shape[:2]
        avail = imgui.get_content_region_avail().x
        scale = min(max(avail, 16.0) / width, 256.0 / height)
        origin = imgui.get_cursor_screen_pos()
        imgui.image(self._display_ref, imgui.ImVec2(width * scale, height * scale))
        self.remember("frame/texture/image")
        if imgui.is_item_hovered():
            mx, my = imgui.get_mouse_pos()
            tx = min(width - 1, max(0, int((mx - origin.x) / scale)))
            ty = min(height - 1, max(0, int((my - origin.y) / scale)))
            imgui.set_tooltip(f"texel ({tx}, {ty}) level {self.level}: {_number(self.texels[ty, tx].tolist())}")
        imgui.text(f"{width} x {height}, level {self.level}")
