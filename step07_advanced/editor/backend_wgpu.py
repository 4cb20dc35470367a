"""Draws ImGui's draw data with wgpu: into a cached GUI layer, composited over the WebGPU renderer's frame.

ImGui blends its sRGB colours as they are. An sRGB render target would blend in linear light instead, so the
GUI would look different from the OpenGL backend (which draws with GL_FRAMEBUFFER_SRGB off). So:

* on frames that run the panels, the GUI is drawn into a transparent ``rgba8unorm`` layer with wgpu's ImGui
  pipeline (gamma 1: the bytes are treated as the colours, blended as bytes, exactly as OpenGL does it; a live
  image leaves a hole, see :mod:`step07_advanced.editor.gui_layer`);
* every frame, at the end of the renderer's own pass (no pass, copy or target of its own), the live images are
  drawn (their bytes decoded to linear light, which the sRGB target encodes back to the same bytes) and then the
  layer over the frame in the windows' rectangles, in linear light (see :mod:`step07_advanced.editor.gui_layer`).

The rest of the frame is never touched.
"""

from __future__ import annotations

from typing import Any

import wgpu
from imgui_bundle import imgui
from wgpu.utils.imgui.imgui_backend import FRAGMENT_SHADER_SRC, VERTEX_SHADER_SRC, ImguiWgpuBackend

from .gui_layer import clip_box, command_vertices, gui_rects, rect_vertices

GUI_FORMAT = "rgba8unorm"

_SRGB_TO_LINEAR = """
fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    return select(pow((c + 0.055) / 1.055, vec3<f32>(2.4)), c / 12.92, c <= vec3<f32>(0.04045));
}
"""

# The layer (premultiplied sRGB bytes) in the windows' rectangles, two triangles each in clip space: its colour
# decoded to linear light and premultiplied again, for the blending unit's "one, one-minus-src-alpha".
_COMPOSITE_WGSL = _SRGB_TO_LINEAR + """
@group(0) @binding(0) var layer: texture_2d<f32>;

@vertex
fn vs_main(@location(0) position: vec2<f32>) -> @builtin(position) vec4<f32> {
    return vec4<f32>(position, 0.0, 1.0);
}

@fragment
fn fs_main(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    let l = textureLoad(layer, vec2<i32>(pos.xy), 0);
    let colour = select(vec3<f32>(0.0), min(l.rgb / l.a, vec3<f32>(1.0)), l.a > 0.0);  // 8-bit rims: <= 1
    return vec4<f32>(srgb_to_linear(colour) * l.a, l.a);
}
"""

# A live image (bytes in a plain texture) drawn straight into the sRGB frame: decoded here, encoded back there.
_LIVE_WGSL = _SRGB_TO_LINEAR + """
struct Uniforms {
    mvp: mat4x4<f32>,
    gamma: f32,
};
struct Varyings {
    @builtin(position) position: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@group(0) @binding(0) var<uniform> uniforms: Uniforms;
@group(0) @binding(1) var s: sampler;
@group(1) @binding(0) var t: texture_2d<f32>;

@vertex
fn vs_main(@location(0) position: vec2<f32>, @location(1) uv: vec2<f32>) -> Varyings {
    var out: Varyings;
    out.position = uniforms.mvp * vec4<f32>(position, 0.0, 1.0);
    out.uv = uv;
    return out;
}

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let c = textureSample(t, s, in.uv);
    return vec4<f32>(srgb_to_linear(c.rgb), c.a);
}
"""

_PREMULTIPLIED = {"src_factor": "one", "dst_factor": "one-minus-src-alpha", "operation": "add"}

_IMGUI_VERTEX = {"array_stride": imgui.VERTEX_SIZE, "step_mode": "vertex", "attributes": [
    {"format": "float32x2", "offset": 0, "shader_location": 0},
    {"format": "float32x2", "offset": 8, "shader_location": 1},
    {"format": "unorm8x4", "offset": 16, "shader_location": 2}]}


class WGPUGuiRenderer:
    """Owns the GUI's wgpu objects; call :meth:`release` to free them."""

    def __init__(self, device: Any, target_format: str, depth_format: str) -> None:
        """``target_format`` and ``depth_format``: the renderer's pass, which the composite draws in."""
        self.device = device
        self.backend = ImguiWgpuBackend(device, GUI_FORMAT)
        # Drawn in the renderer's pass: its attachments' formats, the depth neither tested nor written.
        self._depth = {"format": depth_format, "depth_write_enabled": False, "depth_compare": "always"}
        module = device.create_shader_module(code=_COMPOSITE_WGSL, label="editor composite")
        self.composite_pipeline = device.create_render_pipeline(
            layout="auto",
            vertex={"module": module, "entry_point": "vs_main", "buffers": [{
                "array_stride": 8, "step_mode": "vertex",
                "attributes": [{"format": "float32x2", "offset": 0, "shader_location": 0}]}]},
            fragment={"module": module, "entry_point": "fs_main", "targets": [{
                "format": target_format, "blend": {"color": _PREMULTIPLIED, "alpha": _PREMULTIPLIED}}]},
            primitive={"topology": "triangle-list"},
            depth_stencil=self._depth,
            label="editor composite",
        )
        self.hole_pipeline = self._imgui_pipeline(VERTEX_SHADER_SRC, FRAGMENT_SHADER_SRC, GUI_FORMAT, "zero")
        live = device.create_shader_module(code=_LIVE_WGSL, label="editor live image")
        self.live_pipeline = self._imgui_pipeline(live, live, target_format, None)
        self._size: tuple[int, int] | None = None
        self._layer: Any = None
        self._layer_group: Any = None
        self._texture_groups: dict[int, tuple[Any, Any]] = {}
        self.rects: list[tuple[int, int, int, int]] = []
        self._rect_buffer: Any = None
        self._rect_vertices = 0
        self._live: list[tuple[int, tuple[int, int, int, int], int, int]] = []
        self._live_buffer: Any = None

    def _imgui_pipeline(self, vertex: Any, fragment: Any, target_format: str, blend: str | None) -> Any:
        """A pipeline with the layout of wgpu's ImGui pipeline (its bind groups fit): ``blend="zero"`` writes
        transparent black into the layer (a live image's hole), None writes the fragment as it is into the
        renderer's pass (a live image)."""
        backend, device = self.backend, self.device
        if isinstance(vertex, str):
            vertex, fragment = device.create_shader_module(code=vertex), device.create_shader_module(code=fragment)
        entry = "main" if vertex is not fragment else "vs_main"
        layout = device.create_pipeline_layout(bind_group_layouts=[
            backend._render_pipeline.get_bind_group_layout(0), backend._texture_bind_group_layout])
        target: dict[str, Any] = {"format": target_format}
        if blend == "zero":
            zero = {"src_factor": "zero", "dst_factor": "zero", "operation": "add"}
            target["blend"] = {"color": zero, "alpha": zero}
        return device.create_render_pipeline(
            layout=layout,
            vertex={"module": vertex, "entry_point": entry, "buffers": [_IMGUI_VERTEX]},
            primitive={"topology": "triangle-list", "cull_mode": "none"},
            depth_stencil=None if blend == "zero" else self._depth,
            fragment={"module": fragment, "entry_point": "main" if vertex is not fragment else "fs_main",
                      "targets": [target]},
            label="editor hole" if blend == "zero" else "editor live image",
        )

    def texture_ref(self, view: Any) -> tuple[Any, Any]:
        """Register a texture view a panel shows with ``imgui.image``: (key for :meth:`forget_texture`, its ref)."""
        ref = self.backend.register_texture(view)
        return ref, ref

    def forget_texture(self, key: Any) -> None:
        tex_id = key.get_tex_id()
        self.backend._texture_views.pop(tex_id, None)
        self._texture_groups.pop(tex_id, None)

    def _target(self, width: int, height: int) -> None:
        if self._size == (width, height):
            return
        if self._layer is not None:
            self._layer.destroy()
        usage = wgpu.TextureUsage
        self._layer = self.device.create_texture(
            size=(width, height, 1), format=GUI_FORMAT, usage=usage.RENDER_ATTACHMENT | usage.TEXTURE_BINDING,
            label="editor gui layer",
        )
        self._layer_view = self._layer.create_view()
        self._layer_group = self.device.create_bind_group(
            layout=self.composite_pipeline.get_bind_group_layout(0),
            entries=[{"binding": 0, "resource": self._layer_view}],
        )
        self._size = (width, height)

    def _texture_group(self, tex_id: int) -> Any:
        view = self.backend._texture_views[tex_id]
        cached = self._texture_groups.get(tex_id)
        if cached is None or cached[0] is not view:
            group = self.device.create_bind_group(layout=self.backend._texture_bind_group_layout,
                                                  entries=[{"binding": 0, "resource": view}])
            cached = self._texture_groups[tex_id] = (view, group)
        return cached[1]

    # --- a GUI frame: the layer -----------------------------------------------------------------------
    def draw_layer(self, draw_data: Any, width: int, height: int) -> None:
        """Draw ``draw_data`` into the transparent GUI layer (the frame is left alone)."""
        backend = self.backend
        backend._clear_pending_textures()
        if draw_data.textures is not None:
            for tex in draw_data.textures:
                if tex.status != imgui.ImTextureStatus.ok:
                    backend._update_texture(tex)
        self._target(width, height)
        self.rects, self._live = [], []
        encoder = self.device.create_command_encoder()
        layer_pass = encoder.begin_render_pass(color_attachments=[
            {"view": self._layer_view, "load_op": "clear", "clear_value": (0, 0, 0, 0), "store_op": "store"}
        ])
        live_bytes: list[bytes] = []
        if draw_data.cmd_lists_count > 0 and draw_data.total_idx_count > 0:
            backend._update_vertex_buffer(draw_data)
            backend._set_render_state(draw_data)
            layer_pass.set_viewport(0, 0, width, height, 0, 1)
            layer_pass.set_vertex_buffer(0, backend._vertex_buffer)
            layer_pass.set_index_buffer(backend._index_buffer, "uint32" if imgui.INDEX_SIZE == 4 else "uint16")
            layer_pass.set_bind_group(0, backend._bind_group)
            pipeline = bound_texture = scissor = None  # state set only when it changes: each call costs
            vtx_base = idx_base = first = 0
            for commands in draw_data.cmd_lists:
                for command in commands.cmd_buffer:
                    box = clip_box(command, width, height)
                    if box is None:
                        continue
                    tex_id = command.tex_ref.get_tex_id()
                    hole = tex_id not in backend._textures
                    wanted = self.hole_pipeline if hole else backend._render_pipeline
                    if wanted is not pipeline:
                        layer_pass.set_pipeline(wanted)
                        pipeline = wanted
                    if hole:  # a live image: a hole here, the image drawn into the frame every frame
                        live_bytes.append(command_vertices(commands, command))
                        self._live.append((tex_id, box, first, command.elem_count))
                        first += command.elem_count
                    if tex_id != bound_texture:
                        layer_pass.set_bind_group(1, self._texture_group(tex_id))
                        bound_texture = tex_id
                    if box != scissor:
                        x0, y0, x1, y1 = box
                        layer_pass.set_scissor_rect(x0, y0, x1 - x0, y1 - y0)
                        scissor = box
                    layer_pass.draw_indexed(command.elem_count, 1, command.idx_offset + idx_base,
                                            command.vtx_offset + vtx_base, 0)
                vtx_base += commands.vtx_buffer.size()
                idx_base += commands.idx_buffer.size()
        layer_pass.end()
        self.device.queue.submit([encoder.finish()])
        self.rects = gui_rects(draw_data, width, height)
        self._write_rects(rect_vertices(self.rects, width, height))
        if live_bytes:
            self._live_buffer = self._upload(self._live_buffer, b"".join(live_bytes))

    def _write_rects(self, data: bytes) -> None:
        self._rect_vertices = len(data) // 8
        if data:
            self._rect_buffer = self._upload(self._rect_buffer, data)

    def _upload(self, buffer: Any, data: bytes) -> Any:
        """``data`` written into the vertex buffer ``buffer``, or into a new one when it does not fit."""
        if buffer is None or buffer.size < len(data):
            if buffer is not None:
                buffer.destroy()
            buffer = self.device.create_buffer(
                size=max(len(data), 4096), usage=wgpu.BufferUsage.VERTEX | wgpu.BufferUsage.COPY_DST)
        self.device.queue.write_buffer(buffer, 0, data)
        return buffer

    # --- every frame: the layer over the frame -------------------------------------------------------
    def composite(self, render_pass: Any, width: int, height: int) -> None:
        """Draw the live images and the GUI layer at the end of the renderer's ``render_pass`` (a frame of
        ``width`` x ``height``)."""
        if not self.rects or self._size != (width, height):
            return  # resized since the last GUI frame: the next one draws the layer at the new size
        live = [entry for entry in self._live if entry[0] in self.backend._texture_views]
        if live:  # under the layer, whose holes show them
            render_pass.set_pipeline(self.live_pipeline)
            render_pass.set_bind_group(0, self.backend._bind_group)
            render_pass.set_vertex_buffer(0, self._live_buffer)
            for tex_id, (x0, y0, x1, y1), first, count in live:
                render_pass.set_bind_group(1, self._texture_group(tex_id))
                render_pass.set_scissor_rect(x0, y0, x1 - x0, y1 - y0)
                render_pass.draw(count, 1, first, 0)
            render_pass.set_scissor_rect(0, 0, width, height)
        render_pass.set_pipeline(self.composite_pipeline)
        render_pass.set_bind_group(0, self._layer_group)
        render_pass.set_vertex_buffer(0, self._rect_buffer)
        render_pass.draw(self._rect_vertices)

    def release(self) -> None:
        """Free the GUI target and layer, ImGui's textures and the backend's buffers."""
        backend = self.backend
        for texture in backend._textures.values():
            texture.destroy()
        backend._textures.clear()
        backend._texture_views.clear()
        self._texture_groups.clear()
        for buffer in (backend._vertex_buffer, backend._index_buffer, backend._uniform_buffer, self._live_buffer,
                       self._rect_buffer):
            if buffer is not None:
                buffer.destroy()
        if self._layer is not None:
            self._layer.destroy()
        self._layer = self._rect_buffer = self._live_buffer = None
        for tex in imgui.get_platform_io().textures:
            tex.set_tex_id(0)
            tex.set_status(imgui.ImTextureStatus.destroyed)
