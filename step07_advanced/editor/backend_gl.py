"""Draws ImGui's draw data with moderngl: into a cached GUI layer, composited over the OpenGL renderer's frame.

ImGui colours are sRGB values and ImGui blends them as they are. The frame is an sRGB target with
GL_FRAMEBUFFER_SRGB enabled, which would encode the GUI's colours a second time; the layer is therefore drawn
with GL_FRAMEBUFFER_SRGB disabled (bytes in = bytes out) with the WebGPU backend's blend state (colour:
src-alpha / one-minus-src-alpha, alpha: one / one-minus-src-alpha), so both backends store the same bytes in it.
The composite runs with the renderer's state (GL_FRAMEBUFFER_SRGB on): the layer decoded to linear light, blended
"over" the frame (one / one-minus-src-alpha), encoded by the target; live images are drawn as bytes, with the flag
off. See :mod:`step07_advanced.editor.gui_layer` for the layer and its holes for live images.
"""

from __future__ import annotations

from typing import Any

import moderngl
import numpy as np
from imgui_bundle import imgui

from .gui_layer import clip_box, command_vertices, gui_rects, merged_draw_lists, rect_vertices

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
uniform bool u_hole;  // a live image's place in the layer: transparent
in vec2 v_uv;
in vec4 v_color;
out vec4 f_color;
void main() {
    f_color = u_hole ? vec4(0.0) : v_color * texture(u_texture, v_uv);
}
"""

_COMPOSITE_VERTEX = """
#version 330
in vec2 in_position;  // a corner of a window rectangle, in clip space
void main() {
    gl_Position = vec4(in_position, 0.0, 1.0);
}
"""

_COMPOSITE_FRAGMENT = """
#version 330
uniform sampler2D u_layer;
out vec4 f_color;
vec3 srgb_to_linear(vec3 c) {
    return mix(pow((c + 0.055) / 1.055, vec3(2.4)), c / 12.92, lessThanEqual(c, vec3(0.04045)));
}
void main() {
    vec4 l = texelFetch(u_layer, ivec2(gl_FragCoord.xy), 0);  // premultiplied sRGB bytes and coverage
    vec3 colour = l.a > 0.0 ? min(l.rgb / l.a, vec3(1.0)) : vec3(0.0);  // 8-bit rims: <= 1
    f_color = vec4(srgb_to_linear(colour) * l.a, l.a);
}
"""


class GLGuiRenderer:
    """Owns the GUI's GL objects (program, buffers, ImGui's textures); call :meth:`release` to free them."""

    def __init__(self, ctx: moderngl.Context) -> None:
        self.ctx = ctx
        self.program = ctx.program(vertex_shader=_VERTEX, fragment_shader=_FRAGMENT)
        self.program["u_texture"].value = 0
        self.program["u_hole"].value = False
        self.composite_program = ctx.program(vertex_shader=_COMPOSITE_VERTEX, fragment_shader=_COMPOSITE_FRAGMENT)
        self.composite_program["u_layer"].value = 0
        self._rect_vbo: moderngl.Buffer | None = None
        self._rect_vao: moderngl.VertexArray | None = None
        self._rect_vertices = 0
        self._layer: moderngl.Texture | None = None
        self._layer_fbo: moderngl.Framebuffer | None = None
        self.rects: list[tuple[int, int, int, int]] = []
        #: Live images of the last GUI frame: (texture id, clip box, first vertex, vertex count).
        self._live: list[tuple[int, tuple[int, int, int, int], int, int]] = []
        self._live_vbo: moderngl.Buffer | None = None
        self._live_vao: moderngl.VertexArray | None = None
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
                self._ibo, index_element_size=4,  # merged_draw_lists' uint32 indices
            )
        return self._vao

    # --- a GUI frame: the layer -----------------------------------------------------------------------
    def _target(self, width: int, height: int) -> moderngl.Framebuffer:
        if self._layer is None or self._layer.size != (width, height):
            if self._layer is not None:
                self._layer_fbo.release()
                self._layer.release()
            self._layer = self.ctx.texture((width, height), 4)
            self._layer_fbo = self.ctx.framebuffer([self._layer])
        return self._layer_fbo

    def draw_layer(self, draw_data: Any, width: int, height: int) -> None:
        """Draw ``draw_data`` into the transparent GUI layer (the frame is left alone)."""
        if draw_data.textures is not None:
            for tex in draw_data.textures:
                if tex.status != imgui.ImTextureStatus.ok:
                    self._update_texture(tex)
        ctx = self.ctx
        frame_fbo = ctx.fbo  # the frame's: bound again at the end, for composite()
        fbo = self._target(width, height)
        fbo.use()
        ctx.disable_direct(GL_FRAMEBUFFER_SRGB)
        fbo.clear(0.0, 0.0, 0.0, 0.0)
        self.rects, self._live = [], []
        if draw_data.cmd_lists_count == 0:
            ctx.enable_direct(GL_FRAMEBUFFER_SRGB)
            frame_fbo.use()
            return
        sx, sy = draw_data.display_size
        self.program["u_scale"].value = (2.0 / sx, -2.0 / sy)
        ctx.disable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        ctx.enable(moderngl.BLEND)
        ctx.blend_equation = moderngl.FUNC_ADD
        ctx.blend_func = (moderngl.SRC_ALPHA, moderngl.ONE_MINUS_SRC_ALPHA, moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA)
        fbo.viewport = (0, 0, width, height)
        live_bytes: list[bytes] = []
        first = 0
        bound: Any = None  # the texture bound last: bound again only when it changes
        scissor: tuple[int, int, int, int] | None = None  # likewise the scissor box
        vertex_bytes, index_array, starts = merged_draw_lists(draw_data)
        vao = self._buffers(max(len(vertex_bytes), 1), max(index_array.nbytes, 1))
        self._vbo.orphan()  # fresh storage: the driver need not wait for the GPU to finish with the old
        self._vbo.write(vertex_bytes)
        self._ibo.orphan()
        self._ibo.write(index_array.tobytes())
        try:
            for commands, start in zip(draw_data.cmd_lists, starts):
                for command in commands.cmd_buffer:
                    box = clip_box(command, width, height)
                    if box is None:
                        continue
                    if box != scissor:  # most commands of a window share its clip rectangle
                        x0, y0, x1, y1 = scissor = box
                        fbo.scissor = (x0, height - y1, x1 - x0, y1 - y0)  # GL's origin is bottom-left
                    tex_id = command.tex_ref.get_tex_id()
                    texture = self.textures.get(tex_id)
                    hole = texture is None
                    if hole:  # a live image: a hole here, the image drawn into the frame every frame
                        texture = self.user_textures[tex_id]
                        live_bytes.append(command_vertices(commands, command))
                        self._live.append((tex_id, box, first, command.elem_count))
                        first += command.elem_count
                        ctx.disable(moderngl.BLEND)
                        self.program["u_hole"].value = True
                    if texture is not bound:
                        texture.use(location=0)
                        bound = texture
                    vao.render(moderngl.TRIANGLES, vertices=command.elem_count, first=start + command.idx_offset)
                    if hole:
                        self.program["u_hole"].value = False
                        ctx.enable(moderngl.BLEND)
        finally:
            fbo.scissor = None
            ctx.disable(moderngl.BLEND)
            ctx.enable_direct(GL_FRAMEBUFFER_SRGB)
            frame_fbo.use()
        self.rects = gui_rects(draw_data, width, height)
        self._write_rects(rect_vertices(self.rects, width, height))
        if live_bytes:
            self._write_live(b"".join(live_bytes))

    def _write_rects(self, data: bytes) -> None:
        self._rect_vertices = len(data) // 8
        if data:
            self._rect_vbo, self._rect_vao = self._upload(self._rect_vbo, self._rect_vao, data, self.composite_program,
                                                          ("2f", "in_position"))

    def _write_live(self, data: bytes) -> None:
        self._live_vbo, self._live_vao = self._upload(self._live_vbo, self._live_vao, data, self.program,
                                                      ("2f 2f 4f1", "in_position", "in_uv", "in_color"))

    def _upload(self, vbo: moderngl.Buffer | None, vao: moderngl.VertexArray | None, data: bytes,
                program: moderngl.Program, layout: tuple[str, ...]) -> tuple[moderngl.Buffer, moderngl.VertexArray]:
        """``data`` written into ``vbo``, or into a new buffer (and vertex array over it) when it does not fit."""
        if vbo is None or vbo.size < len(data):
            if vbo is not None:
                vao.release()
                vbo.release()
            vbo = self.ctx.buffer(reserve=max(len(data), 4096), dynamic=True)
            vao = self.ctx.vertex_array(program, [(vbo, *layout)])
        vbo.write(data)
        return vbo, vao

    # --- every frame: the layer over the frame -------------------------------------------------------
    def composite(self, fbo: moderngl.Framebuffer) -> None:
        """Draw the live images, then the GUI layer, over what ``fbo`` (bound, GL_FRAMEBUFFER_SRGB on) holds."""
        if not self.rects or self._layer is None:
            return
        ctx = self.ctx
        width, height = fbo.size
        if (width, height) != self._layer.size:
            return  # resized since the last GUI frame: the next one draws the layer at the new size
        ctx.disable(moderngl.DEPTH_TEST | moderngl.CULL_FACE | moderngl.BLEND)
        if self._live:  # as bytes (under the layer, whose holes show them)
            ctx.disable_direct(GL_FRAMEBUFFER_SRGB)
            try:
                for tex_id, (x0, y0, x1, y1), first, count in self._live:
                    texture = self.user_textures.get(tex_id)
                    if texture is None:
                        continue
                    fbo.scissor = (x0, height - y1, x1 - x0, y1 - y0)
                    texture.use(location=0)
                    self._live_vao.render(moderngl.TRIANGLES, vertices=count, first=first)
            finally:
                fbo.scissor = None
                ctx.enable_direct(GL_FRAMEBUFFER_SRGB)
        ctx.enable(moderngl.BLEND)
        ctx.blend_equation = moderngl.FUNC_ADD
        ctx.blend_func = (moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA, moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA)
        self._layer.use(location=0)
        self._rect_vao.render(moderngl.TRIANGLES, vertices=self._rect_vertices)
        ctx.disable(moderngl.BLEND)

    def _release_buffers(self) -> None:
        for obj in (self._vao, self._vbo, self._ibo):
            if obj is not None:
                obj.release()
        self._vao = self._vbo = self._ibo = None

    def release(self) -> None:
        """Free the programs, the buffers, the layer and every texture ImGui asked for."""
        self._release_buffers()
        for obj in (self._live_vao, self._live_vbo, self._rect_vao, self._rect_vbo, self._layer_fbo, self._layer):
            if obj is not None:
                obj.release()
        self.composite_program.release()
        for texture in self.textures.values():
            texture.release()
        self.textures.clear()
        self.program.release()
