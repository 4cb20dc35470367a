"""Draws ImGui's draw data with moderngl into the OpenGL renderer's framebuffer.

ImGui colours are sRGB values and ImGui blends them as they are. The frame is an sRGB target with
GL_FRAMEBUFFER_SRGB enabled, which would encode the GUI's colours a second time; the GUI is therefore
drawn with GL_FRAMEBUFFER_SRGB disabled (bytes in = bytes out) and the flag is restored afterwards.
The blend state matches the WebGPU backend exactly (colour: src-alpha / one-minus-src-alpha,
alpha: one / one-minus-src-alpha), so both backends store the same bytes.
"""

from __future__ import annotations

import ctypes
from typing import Any

import moderngl
import numpy as np
from imgui_bundle import imgui

GL_FRAMEBUFFER_SRGB = 0x8DB9

_VERTEX = """
#version 330
uniform vec2 u_scale;
in vec2 in_position;
in vec2 in_uv;
in vec4 in_color;
out vec2 v_uv;
out vec4 v_color;
void main() {
    v_uv = in_uv;
    v_color = in_color;
    // Pixels (origin top-left, y down) to clip space (y up).
    gl_Position = vec4(in_position * u_scale + vec2(-1.0, 1.0), 0.0, 1.0);
}
"""

_FRAGMENT = """
#version 330
uniform sampler2D u_texture;
in vec2 v_uv;
in vec4 v_color;
out vec4 f_color;
void main() {
    f_color = v_color * texture(u_texture, v_uv);
}
"""


class GLGuiRenderer:
    """Owns the GUI's GL objects (program, buffers, ImGui's textures); call :meth:`release` to free them."""

    def __init__(self, ctx: moderngl.Context) -> None:
        self.ctx = ctx
        self.program = ctx.program(vertex_shader=_VERTEX, fragment_shader=_FRAGMENT)
        self.program["u_texture"].value = 0
        self._vbo: moderngl.Buffer | None = None
        self._ibo: moderngl.Buffer | None = None
        self._vao: moderngl.VertexArray | None = None
        self.textures: dict[int, moderngl.Texture] = {}
        #: Textures a panel shows (the viewport's), by id: owned by whoever registered them.
        self.user_textures: dict[int, moderngl.Texture] = {}
        io = imgui.get_io()
        io.backend_flags |= imgui.BackendFlags_.renderer_has_textures
        limit = ctx.info["GL_MAX_TEXTURE_SIZE"]
        imgui.get_platform_io().renderer_texture_max_width = limit
        imgui.get_platform_io().renderer_texture_max_height = limit

    # --- ImGui's textures (the font atlas, created and grown by ImGui) ------------------------------
    def _update_texture(self, tex: Any) -> None:
        status = tex.status
        if status == imgui.ImTextureStatus.want_create:
            pixels = tex.get_pixels_array()
            texture = self.ctx.texture((tex.width, tex.height), 4, pixels.tobytes())
            texture.filter = (moderngl.LINEAR, moderngl.LINEAR)
            texture.repeat_x = texture.repeat_y = False
            self.textures[texture.glo] = texture
            tex.set_tex_id(texture.glo)
            tex.set_status(imgui.ImTextureStatus.ok)
        elif status == imgui.ImTextureStatus.want_updates:
            texture = self.textures[tex.get_tex_id()]
            pixels = tex.get_pixels_array().reshape(tex.height, tex.width, 4)
            for r in tex.updates:
                block = np.ascontiguousarray(pixels[r.y:r.y + r.h, r.x:r.x + r.w])
                texture.write(block.tobytes(), viewport=(r.x, r.y, r.w, r.h))
            tex.set_status(imgui.ImTextureStatus.ok)
        elif status == imgui.ImTextureStatus.want_destroy and tex.unused_frames > 0:
            texture = self.textures.pop(tex.get_tex_id(), None)
            if texture is not None:
                texture.release()
            tex.set_tex_id(0)
            tex.set_status(imgui.ImTextureStatus.destroyed)

    def texture_ref(self, texture: moderngl.Texture) -> tuple[int, Any]:
        """Register a texture a panel shows with ``imgui.image``: (key for :meth:`forget_texture`, ImTextureRef)."""
        self.user_textures[texture.glo] = texture
        return texture.glo, imgui.ImTextureRef(texture.glo)

    def forget_texture(self, key: int) -> None:
        self.user_textures.pop(key, None)

    def _buffers(self, vertex_bytes: int, index_bytes: int) -> moderngl.VertexArray:
        # Grown by powers of two; the vertex array is rebuilt only when a buffer is replaced.
        if self._vbo is None or self._vbo.size < vertex_bytes or self._ibo.size < index_bytes:
            self._release_buffers()
            self._vbo = self.ctx.buffer(reserve=1 << max(16, (vertex_bytes - 1).bit_length()), dynamic=True)
            self._ibo = self.ctx.buffer(reserve=1 << max(16, (index_bytes - 1).bit_length()), dynamic=True)
            self._vao = self.ctx.vertex_array(
                self.program, [(self._vbo, "2f 2f 4f1", "in_position", "in_uv", "in_color")],
                self._ibo, index_element_size=imgui.INDEX_SIZE,
            )
        return self._vao

    # --- a frame ------------------------------------------------------------------------------------
    def render(self, draw_data: Any, fbo: moderngl.Framebuffer) -> None:
        """Draw ``draw_data`` over what ``fbo`` holds (``fbo`` must be bound)."""
        if draw_data.textures is not None:
            for tex in draw_data.textures:
                if tex.status != imgui.ImTextureStatus.ok:
                    self._update_texture(tex)
        width, height = fbo.size
        if draw_data.cmd_lists_count == 0 or width <= 0 or height <= 0:
            return
        ctx = self.ctx
        sx, sy = draw_data.display_size
        self.program["u_scale"].value = (2.0 / sx, -2.0 / sy)
        ctx.disable_direct(GL_FRAMEBUFFER_SRGB)
        ctx.disable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        ctx.enable(moderngl.BLEND)
        ctx.blend_equation = moderngl.FUNC_ADD
        ctx.blend_func = (moderngl.SRC_ALPHA, moderngl.ONE_MINUS_SRC_ALPHA, moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA)
        fbo.viewport = (0, 0, width, height)
        try:
            for commands in draw_data.cmd_lists:
                vtx_bytes = commands.vtx_buffer.size() * imgui.VERTEX_SIZE
                idx_bytes = commands.idx_buffer.size() * imgui.INDEX_SIZE
                vao = self._buffers(vtx_bytes, idx_bytes)
                self._vbo.write(ctypes.string_at(commands.vtx_buffer.data_address(), vtx_bytes))
                self._ibo.write(ctypes.string_at(commands.idx_buffer.data_address(), idx_bytes))
                for command in commands.cmd_buffer:
                    x0, y0, x1, y1 = command.clip_rect
                    x0, y0 = max(int(x0), 0), max(int(y0), 0)
                    x1, y1 = min(int(x1), width), min(int(y1), height)
                    if x1 <= x0 or y1 <= y0:
                        continue
                    fbo.scissor = (x0, height - y1, x1 - x0, y1 - y0)  # GL's origin is bottom-left
                    tex_id = command.tex_ref.get_tex_id()
                    (self.textures.get(tex_id) or self.user_textures[tex_id]).use(location=0)
                    vao.render(moderngl.TRIANGLES, vertices=command.elem_count, first=command.idx_offset)
        finally:
            fbo.scissor = None
            ctx.disable(moderngl.BLEND)
            ctx.enable_direct(GL_FRAMEBUFFER_SRGB)

    def _release_buffers(self) -> None:
        for obj in (self._vao, self._vbo, self._ibo):
            if obj is not None:
                obj.release()
        self._vao = self._vbo = self._ibo = None

    def release(self) -> None:
        """Free the program, the buffers and every texture ImGui asked for."""
        self._release_buffers()
        for texture in self.textures.values():
            texture.release()
        self.textures.clear()
        self.program.release()
