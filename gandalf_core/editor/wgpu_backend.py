"""Draws ImGui's draw data with wgpu over the WebGPU renderer's ``rgba8unorm-srgb`` frame.

ImGui blends its sRGB colours as they are. An sRGB render target would blend in linear light instead,
so the GUI would look different from the OpenGL backend (which draws with GL_FRAMEBUFFER_SRGB off).
To store the same bytes as OpenGL, each frame:

1. copies the frame's bytes into a plain ``rgba8unorm`` texture (formats that differ only in sRGB-ness
   may be copied; the bytes are kept as they are),
2. draws the GUI there with wgpu's ImGui backend (gamma 1: the bytes are treated as the colours),
3. writes the result back with a pass that decodes each byte exactly to linear light, which the sRGB
   target encodes back to the same byte.

Steps 1 and 3 cover only the GUI's windows (the union of each draw list's clip rectangles); the rest of
the frame is never touched.
"""

from __future__ import annotations

from typing import Any

import wgpu
from imgui_bundle import imgui
from wgpu.utils.imgui.imgui_backend import ImguiWgpuBackend

GUI_FORMAT = "rgba8unorm"

_BLIT_WGSL = """
@group(0) @binding(0) var gui: texture_2d<f32>;

@vertex
fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let p = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4<f32>(p * 2.0 - 1.0, 0.0, 1.0);
}

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    return select(pow((c + 0.055) / 1.055, vec3<f32>(2.4)), c / 12.92, c <= vec3<f32>(0.04045));
}

@fragment
fn fs_main(@builtin(position) pos: vec4<f32>) -> @location(0) vec4<f32> {
    let c = textureLoad(gui, vec2<i32>(pos.xy), 0);
    return vec4<f32>(srgb_to_linear(c.rgb), c.a);
}
"""


def gui_rects(draw_data: Any, width: int, height: int) -> list[tuple[int, int, int, int]]:
    """(x, y, w, h) pixel rectangles that hold the GUI: per draw list (a window), its commands' clip rects' union."""
    rects = []
    for commands in draw_data.cmd_lists:
        x0, y0, x1, y1 = float(width), float(height), 0.0, 0.0
        for command in commands.cmd_buffer:
            cx0, cy0, cx1, cy1 = command.clip_rect
            x0, y0, x1, y1 = min(x0, cx0), min(y0, cy0), max(x1, cx1), max(y1, cy1)
        ix0, iy0 = max(int(x0), 0), max(int(y0), 0)
        ix1, iy1 = min(int(x1 + 0.999), width), min(int(y1 + 0.999), height)
        if ix1 > ix0 and iy1 > iy0:
            rects.append((ix0, iy0, ix1 - ix0, iy1 - iy0))
    return rects


class WGPUGuiRenderer:
    """Owns the GUI's wgpu objects; call :meth:`release` to free them."""

    def __init__(self, device: Any, target_format: str) -> None:
        self.device = device
        self.backend = ImguiWgpuBackend(device, GUI_FORMAT)
        module = device.create_shader_module(code=_BLIT_WGSL, label="editor blit")
        self.blit = device.create_render_pipeline(
            layout="auto",
            vertex={"module": module, "entry_point": "vs_main"},
            fragment={"module": module, "entry_point": "fs_main", "targets": [{"format": target_format}]},
            primitive={"topology": "triangle-list"},
            label="editor blit",
        )
        self._size: tuple[int, int] | None = None
        self._texture: Any = None
        self._bind_group: Any = None

    def texture_ref(self, view: Any) -> tuple[Any, Any]:
        """Register a texture view a panel shows with ``imgui.image``: (key for :meth:`forget_texture`, its ref)."""
        ref = self.backend.register_texture(view)
        return ref, ref

    def forget_texture(self, key: Any) -> None:
        self.backend._texture_views.pop(key.get_tex_id(), None)

    def _target(self, width: int, height: int) -> None:
        if self._size == (width, height):
            return
        if self._texture is not None:
            self._texture.destroy()
        usage = wgpu.TextureUsage
        self._texture = self.device.create_texture(
            size=(width, height, 1), format=GUI_FORMAT,
            usage=usage.RENDER_ATTACHMENT | usage.COPY_DST | usage.TEXTURE_BINDING, label="editor gui",
        )
        self._view = self._texture.create_view()
        self._bind_group = self.device.create_bind_group(
            layout=self.blit.get_bind_group_layout(0), entries=[{"binding": 0, "resource": self._view}]
        )
        self._size = (width, height)

    def render(self, draw_data: Any, encoder: Any, color_view: Any) -> None:
        """Record the GUI over ``color_view`` (the frame) on ``encoder``."""
        frame = color_view.texture
        width, height = frame.size[0], frame.size[1]
        rects = gui_rects(draw_data, width, height)
        if not rects:
            return
        self._target(width, height)
        # Only the GUI's windows make the round trip: the rest of the frame is never touched.
        for x, y, w, h in rects:
            encoder.copy_texture_to_texture(
                {"texture": frame, "mip_level": 0, "origin": (x, y, 0)},
                {"texture": self._texture, "mip_level": 0, "origin": (x, y, 0)},
                (w, h, 1),
            )
        gui_pass = encoder.begin_render_pass(color_attachments=[
            {"view": self._view, "load_op": "load", "store_op": "store"}
        ])
        self.backend.render(draw_data, gui_pass)
        gui_pass.end()
        blit_pass = encoder.begin_render_pass(color_attachments=[
            {"view": color_view, "load_op": "load", "store_op": "store"}
        ])
        blit_pass.set_pipeline(self.blit)
        blit_pass.set_bind_group(0, self._bind_group)
        for x, y, w, h in rects:
            blit_pass.set_scissor_rect(x, y, w, h)
            blit_pass.draw(3)
        blit_pass.end()

    def release(self) -> None:
        """Free the GUI target, ImGui's textures and the backend's buffers."""
        backend = self.backend
        for texture in backend._textures.values():
            texture.destroy()
        backend._textures.clear()
        backend._texture_views.clear()
        for buffer in (backend._vertex_buffer, backend._index_buffer, backend._uniform_buffer):
            if buffer is not None:
                buffer.destroy()
        if self._texture is not None:
            self._texture.destroy()
            self._texture = None
        for tex in imgui.get_platform_io().textures:
            tex.set_tex_id(0)
            tex.set_status(imgui.ImTextureStatus.destroyed)
