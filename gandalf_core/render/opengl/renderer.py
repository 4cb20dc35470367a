"""The OpenGL renderer: a moderngl context (EGL offscreen, or a glfw window) and an sRGB offscreen target.

Each frame: one write of the frame uniform block, one write of all instance data (which the vertex shaders read
through a buffer texture, by instance index), then one instanced draw call per (material, mesh) batch. With a
shadow-casting light, a depth-only pass from the light draws the opaque batches into the shadow map first.
"""

from __future__ import annotations

import os
from typing import Any

import moderngl
import numpy as np

from ...resources import MaterialData, ResourceError
from ...resources.assets import Assets
from ..attributes import mesh_attributes
from ..base import NOT_RECORDING, Renderer
from ..capabilities import FLOOR, GL_FLOOR, CapabilityError, Needs, check, opengl_offer
from ..frame import FRAME_FLOATS, INSTANCE_FLOATS, LIGHTS_BLOCK_BYTES, SHADOW_MAP_SIZE, SKY_STATE, DrawBatch, FrameData
from ..gpu_memory import buffer_size, gl_texture_bytes
from ..texture_checks import check_target_size
from . import raw_gl
from .libs import (
    ENGINE_SAMPLERS,
    GL_SRGB8_ALPHA8,
    BufferLib,
    GLMaterial,
    GLMesh,
    GLShader,
    MaterialLib,
    MeshLib,
    ShaderLib,
    TextureLib,
    make_current,
)

GL_FRAMEBUFFER_SRGB = 0x8DB9
GL_TEXTURE_CUBE_MAP_SEAMLESS = 0x884F


#: OpenGL versions an offscreen context asks for, newest first: some drivers (NVIDIA's EGL) give exactly the version
#: asked for, and step 07 needs 4.x (tessellation 4.0, compute and storage buffers 4.3, clip control 4.5).
GL_VERSIONS = (460, 450, 430, 410, 330)


_found_version: list[int] = []  # the version that worked first, so later contexts ask for it straight away


def _standalone_context() -> moderngl.Context:
    """The newest headless (EGL) context the driver gives, 4.6 down to the renderer's minimum, 3.3."""
    for version in (_found_version or list(GL_VERSIONS[:-1])):
        try:
            ctx = moderngl.create_standalone_context(backend="egl", require=version)
        except Exception:  # noqa: BLE001 - glcontext raises plain Exceptions for an unsupported version
            continue
        _found_version[:] = [version]
        return ctx
    return moderngl.create_standalone_context(backend="egl", require=GL_VERSIONS[-1])


class OpenGLRenderer(Renderer):
    """moderngl render context. ``window`` is a :class:`gandalf_core.app.window.Window` or None (headless)."""

    backend = "opengl"

    def __init__(self, width: int, height: int, window: Any = None, needs: Needs = FLOOR) -> None:
        super().__init__(width, height, window)
        if window is None:
            self.ctx = _standalone_context()
        else:
            self.ctx = moderngl.create_context(require=GL_FLOOR)
        try:
            check(needs, opengl_offer(self.ctx))  # before anything is built on a context that cannot run the part
        except CapabilityError:
            if window is None:
                self.ctx.release()
            raise
        self.textures = TextureLib(self.ctx, self.stats)
        self.shaders = ShaderLib(self.ctx, self.stats)
        self.meshes = MeshLib(self.ctx, self.stats)
        #: Storage buffers by name: filled by the app's compute code, read by materials that name them.
        self.buffers = BufferLib(self.ctx, self.stats)
        self.materials = MaterialLib(self.shaders, self.textures, self.stats, self.buffers)
        self._frame_ubo = self.ctx.buffer(reserve=FRAME_FLOATS * 4)
        self._lights_ubo = self.ctx.buffer(reserve=LIGHTS_BLOCK_BYTES)
        self._sky: tuple[GLShader, moderngl.VertexArray] | None = None
        self._shadow: tuple[moderngl.Texture, moderngl.Framebuffer] | None = None
        self._instance_buffer: moderngl.Buffer | None = None
        self._drawn_instances: moderngl.Buffer | None = None  # the instance rows the draws read (moved or not)
        self.make_current()  # the buffer texture is made through raw GL calls, in this renderer's context
        #: The texture through which the vertex shaders fetch the drawn instance rows (instance.glsl).
        self._instance_rows = raw_gl.BufferTexture()
        self._max_instance_texels = raw_gl.get_integer(raw_gl.GL_MAX_TEXTURE_BUFFER_SIZE)
        self._vaos: dict[tuple[str, str], moderngl.VertexArray] = {}
        # Released or replaced resources take what refers to them along (rebuilt on their next use).
        self.meshes.on_forget.append(self._forget_vertex_arrays)
        self.shaders.on_forget.append(self._forget_vertex_arrays)
        self.textures.on_forget.append(self._forget_materials_using)
        self._state: tuple[Any, ...] | None = None
        self._fbo: moderngl.Framebuffer | None = None
        self._zero_to_one = False  # glClipControl's depth mode now (OpenGL's default: [-1, 1])
        # Filter across cube faces, as WebGPU always does (no seams in skyboxes and reflections).
        self.ctx.enable_direct(GL_TEXTURE_CUBE_MAP_SEAMLESS)
        #: In a window whose framebuffer encodes sRGB, frames are drawn straight into it (no offscreen target and
        #: copy); reverse-Z frames still use the offscreen target for its float depth. GANDALF_PRESENT=blit
        #: turns this off.
        self.present_direct = window is not None and self._screen_encodes_srgb()
        self._target: moderngl.Framebuffer | None = None  # what the last frame was drawn into
        self._pending_swap = False
        self._create_targets()

    # --- targets ----------------------------------------------------------------------------------
    # --8<-- [start:targets]
    def _create_targets(self) -> None:
        size = (self.width, self.height)
        limit = min(int(self.ctx.info["GL_MAX_TEXTURE_SIZE"]), int(self.ctx.info["GL_MAX_RENDERBUFFER_SIZE"]),
                    *(int(v) for v in self.ctx.info["GL_MAX_VIEWPORT_DIMS"]))
        check_target_size(*size, limit)
        # An sRGB colour target: shaders work in linear light and GL encodes on write, as WebGPU's
        # rgba8unorm-srgb does, so both backends store the same bytes.
        self._color = self.ctx.texture(size, 4, internal_format=GL_SRGB8_ALPHA8)
        self._depth = self.ctx.depth_texture(size)
        if raw_gl.supported(self.ctx.version_code, self.ctx.extensions):
            # 32-bit float depth, as WebGPU's depth32float: with reverse-Z the same precision in both APIs.
            raw_gl.make_float_depth(self._depth.glo, *size)
        self._fbo = self.ctx.framebuffer([self._color], self._depth)
    # --8<-- [end:targets]

    @property
    def framebuffer(self) -> moderngl.Framebuffer:
        """The framebuffer the current (or last) frame is drawn into: the offscreen sRGB target, or the window's
        own framebuffer when frames are presented directly."""
        return self._target if self._target is not None else self._fbo

    def _screen_encodes_srgb(self) -> bool:
        """Whether the window's framebuffer encodes linear colours to sRGB on write (GL_FRAMEBUFFER_SRGB), as the
        offscreen target does: then both give the same bytes and frames can be drawn into the window directly."""
        if os.environ.get("GANDALF_PRESENT", "").lower() == "blit":
            return False
        screen = self.ctx.screen
        screen.use()
        self.ctx.enable_direct(GL_FRAMEBUFFER_SRGB)
        screen.clear(0.2, 0.2, 0.2, 1.0, viewport=(0, 0, 1, 1))
        value = screen.read(viewport=(0, 0, 1, 1), components=4)[0]
        self.ctx.disable_direct(GL_FRAMEBUFFER_SRGB)
        return abs(value - 124) <= 1  # linear 0.2 encodes to sRGB 124; a plain framebuffer keeps 51

    def _release_targets(self) -> None:
        for obj in (self._fbo, self._color, self._depth):
            obj.release()
        if self._target is self._fbo:
            self._target = None

    def depth_range_for(self, reverse_z: bool) -> str:
        """Reverse-Z frames use clip depth [0, 1] (glClipControl) and the float depth buffer: real precision."""
        if reverse_z and not raw_gl.supported(self.ctx.version_code, self.ctx.extensions):
            raise RuntimeError(f"reverse-Z needs OpenGL 4.5 or ARB_clip_control; this context is "
                               f"{self.ctx.info.get('GL_VERSION', self.ctx.version_code)}")
        return "webgpu" if reverse_z else "opengl"

    def _clip_depth(self, zero_to_one: bool) -> None:
        if zero_to_one != self._zero_to_one:
            raw_gl.set_zero_to_one(zero_to_one)
            self._zero_to_one = zero_to_one

    def make_current(self) -> None:
        """Make this renderer's context the current one. Several renderers (several Applications, a compute
        helper's context) may live in one process and GL calls go to whichever context is current, so every entry
        point that issues them starts here."""
        make_current(self.ctx)

    # --- a frame ------------------------------------------------------------------------------------
    def render(self, data: FrameData, assets: Assets) -> None:
        self.make_current()
        self.stats["draw_calls"] = 0
        self._frame_ubo.write(data.frame)
        self._frame_ubo.bind_to_uniform_block(0)
        if self._lights_changed(data.lights):
            self._lights_ubo.write(data.lights)
        self._lights_ubo.bind_to_uniform_block(1)
        if data.batches:
            self._upload_instances(data)
        self._drawn_instances = self._instance_buffer
        if data.instance_pass is not None and data.batches:  # GPU work over the rows: the draws read its output
            self._drawn_instances = data.instance_pass.run(self, self._instance_buffer, len(data.instances))
        # Resolve (build on first use) everything before any pass: building a texture uses moderngl's
        # scratch texture unit, which on some drivers is the unit the shadow map is bound to.
        draws = self.resolve_draws(data, assets)
        sky = self._prepare_sky(data.skybox, assets) if data.skybox is not None else None
        if self._drawn_instances is not None:
            self._bind_instance_rows(len(data.instances) if data.batches else 0)
        recorder = self.recorder  # the frame-capture hook (see Renderer.recorder), or None
        if recorder is not None:
            recorder.begin_frame(self._frame_ubo.read(), self._lights_ubo.read())
        if data.shadows:
            self._clip_depth(False)  # the shadow map is projected for OpenGL's [-1, 1]
            self._draw_shadow_map(draws)
        self._clip_depth(data.reverse_z)
        if self._pending_swap:  # the previous frame, drawn into the window, is shown now
            self.window.swap_buffers()
            self._pending_swap = False
        direct = self.present_direct and not data.reverse_z
        if direct:
            self.ctx.screen.viewport = (0, 0, self.width, self.height)
        self._target = self.ctx.screen if direct else self._fbo
        # --8<-- [start:clear]
        fbo = self._target
        fbo.use()
        self.ctx.enable_direct(GL_FRAMEBUFFER_SRGB)
        fbo.depth_mask = True
        r, g, b, a = (float(x) for x in data.clear_color)
        if recorder is not None:
            recorder.begin_target(f"frame {self.width}x{self.height} (GL_SRGB8_ALPHA8, depth)")
        fbo.clear(r, g, b, a, depth=0.0 if data.reverse_z else 1.0)
        # --8<-- [end:clear]
        self._state = None
        for batch, material, mesh in draws:
            if batch.transparent and sky is not None:  # the sky goes behind blended surfaces
                self._draw_sky(sky, data.reverse_z, data.skybox)
                sky = None
            self._apply_state(material.data, data.reverse_z, batch.mirrored)
            material.apply()
            if recorder is None:
                self._draw_batch(material.shader, mesh, batch)
            else:  # a frame capture: one record per draw
                with recorder.draw("transparent" if batch.transparent else "opaque", None, material.shader, batch,
                                   material, mesh, data.reverse_z):
                    self._draw_batch(material.shader, mesh, batch)
        if sky is not None:
            self._draw_sky(sky, data.reverse_z, data.skybox)
        self._clip_depth(False)  # overlays and other GL code expect OpenGL's default
        with recorder.overlay() if recorder is not None and self.overlays else NOT_RECORDING:
            for overlay in self.overlays:
                overlay(self)
                self._state = None  # an overlay may change any GL state
        if recorder is not None:
            recorder.end_target()
            recorder.end_frame()
        self._present()

    def _bind_instance_rows(self, count: int) -> None:
        """Point the instance-row texture at the buffer the draws read (attached again each frame: the store may
        have been orphaned or moved) and bind it at its reserved unit."""
        if count * INSTANCE_FLOATS // 4 > self._max_instance_texels:
            raise ValueError(f"{count} instances need {count * INSTANCE_FLOATS // 4} texels of instance rows, more "
                             f"than this OpenGL driver's buffer textures hold (GL_MAX_TEXTURE_BUFFER_SIZE "
                             f"{self._max_instance_texels}); draw fewer entities")
        self._instance_rows.attach(self._drawn_instances.glo)
        self.use_instance_rows()

    def use_instance_rows(self) -> None:
        """Bind the instance-row texture at its reserved unit again (for draws replayed after the frame)."""
        self._instance_rows.use(ENGINE_SAMPLERS["u_instance_rows"])

    def _draw_batch(self, shader: GLShader, mesh: GLMesh, batch: DrawBatch) -> None:
        """One instanced draw of ``batch`` with ``shader``: its rows start at ``u_first_instance`` in the instance
        buffer texture (gl_InstanceID counts from 0 in every draw)."""
        vao = self._vertex_array(shader, mesh)
        if "u_first_instance" in shader.uniforms:
            shader.program["u_first_instance"].value = batch.first_instance
        # --8<-- [start:patches]
        if shader.patch_vertices is not None:  # a tessellation program draws patches, never triangles
            self.ctx.patch_vertices = shader.patch_vertices
            vao.render(moderngl.PATCHES, vertices=mesh.count, instances=batch.count)
        elif mesh.data.indirect is not None:  # the count a compute pass wrote; the instances are the batch's
            buffer = self.indirect_buffer(mesh.name, mesh.data)
            buffer.write(np.array([batch.count, 0, 0], dtype=np.uint32).tobytes(), offset=4)
            vao.render_indirect(buffer, moderngl.TRIANGLES, count=1)
        else:
            vao.render(moderngl.TRIANGLES, vertices=mesh.count, instances=batch.count)
        # --8<-- [end:patches]
        self.stats["draw_calls"] += 1

    # --8<-- [start:shadow_pass]
    def _draw_shadow_map(self, draws: list[tuple[DrawBatch, GLMaterial, GLMesh]]) -> None:
        """The shadow pass: every opaque batch, depth only, from the light into the shadow map; then the
        map is bound for the main pass. The map, its framebuffer and the shader are built on first use."""
        if self._shadow is None:
            size = (SHADOW_MAP_SIZE, SHADOW_MAP_SIZE)
            texture = self.ctx.depth_texture(size)
            # A comparing sampler (sampler2DShadow): texture() returns lit (1) or not (0) per texel, and
            # linear filtering blends four such results.
            texture.compare_func = "<="
            texture.filter = (moderngl.LINEAR, moderngl.LINEAR)
            texture.repeat_x = texture.repeat_y = False
            self._shadow = (texture, self.ctx.framebuffer(depth_attachment=texture))
            self.stats["shadow_maps_created"] += 1
        texture, framebuffer = self._shadow
        shader = self.pass_shader("shadow")
        framebuffer.use()
        if self.recorder is not None:
            self.recorder.begin_target(f"shadow map {SHADOW_MAP_SIZE}x{SHADOW_MAP_SIZE} (depth)")
        framebuffer.depth_mask = True
        framebuffer.clear(depth=1.0)
        ctx = self.ctx
        ctx.disable(moderngl.BLEND | moderngl.CULL_FACE)  # both faces cast: open meshes and planes too
        ctx.enable(moderngl.DEPTH_TEST)
        ctx.depth_func = "<="
        recorder = self.recorder
        for batch, material, mesh in draws:
            if batch.transparent:
                continue
            if recorder is None:
                self._draw_batch(shader, mesh, batch)
            else:
                with recorder.draw("shadow", None, shader, batch, material, mesh):
                    self._draw_batch(shader, mesh, batch)
        if recorder is not None:
            recorder.end_target()
        texture.use(location=ENGINE_SAMPLERS["u_shadow_map"])
        self.stats["shadow_passes"] += 1
    # --8<-- [end:shadow_pass]

    def _prepare_sky(self, texture_name: str, assets: Assets) -> tuple[moderngl.VertexArray, Any]:
        """The sky pass's vertex array (built on first use) and its cube texture."""
        if self._sky is None:
            shader = self.pass_shader("sky")
            self._sky = (shader, self.ctx.vertex_array(shader.program, []))
        return self._sky[1], self.resolve_sky(texture_name, assets)

    def _draw_sky(self, sky: tuple[moderngl.VertexArray, Any], reverse_z: bool, name: str = "") -> None:
        """A full-screen triangle at the far plane, after the opaque geometry."""
        vao, texture = sky
        self._apply_state(SKY_STATE, reverse_z)
        texture.use(location=0)
        with NOT_RECORDING if self.recorder is None else self.recorder.draw("sky", None, self._sky[0],
                                                                            reverse_z=reverse_z, sky=name):
            vao.render(moderngl.TRIANGLES, vertices=3)
        self.stats["draw_calls"] += 1

    def _frame_gpu_memory(self) -> dict[str, int]:
        # The buffer texture over the instance rows is a view of the instance buffer: no storage of its own.
        return {"frame targets": gl_texture_bytes(self._color) + gl_texture_bytes(self._depth),
                "shadow map": gl_texture_bytes(self._shadow[0]) if self._shadow is not None else 0,
                "instances": buffer_size(self._instance_buffer),
                "frame uniforms": buffer_size(self._frame_ubo) + buffer_size(self._lights_ubo)}

    def _renew_instance_buffer(self, capacity: int | None) -> None:
        if capacity is None:
            # Fresh storage for this frame's data, so the driver need not wait for last frame's draws.
            self._instance_buffer.orphan()
            return
        if self._instance_buffer is not None:
            self._instance_buffer.release()
        self._instance_buffer = self.ctx.buffer(reserve=capacity, dynamic=True)

    def _write_instances(self, rows: np.ndarray, offset: int) -> None:
        self._instance_buffer.write(rows, offset=offset)

    def _apply_state(self, data: MaterialData, reverse_z: bool, mirrored: bool = False) -> None:
        state = (data.cull, data.depth_test, data.depth_write, data.blend, reverse_z, mirrored)
        if state == self._state:
            return
        ctx = self.ctx
        if data.cull == "none":
            ctx.disable(moderngl.CULL_FACE)
        else:
            ctx.enable(moderngl.CULL_FACE)
            ctx.cull_face = data.cull
        # A mirrored instance's triangles wind the other way round on screen.
        ctx.front_face = "cw" if mirrored else "ccw"
        # The depth test stays on even when "off" (it then always passes): disabling GL_DEPTH_TEST would also
        # stop depth writes, which WebGPU's compare "always" keeps.
        ctx.enable(moderngl.DEPTH_TEST)
        ctx.depth_func = (">=" if reverse_z else "<=") if data.depth_test else "1"
        self._target.depth_mask = data.depth_write
        if data.blend == "opaque":
            ctx.disable(moderngl.BLEND)
        else:
            ctx.enable(moderngl.BLEND)
            # Separate alpha factors, as WebGPU's blend states: the target's alpha stays a coverage value.
            ctx.blend_func = (
                (moderngl.SRC_ALPHA, moderngl.ONE_MINUS_SRC_ALPHA, moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA)
                if data.blend == "alpha"
                else (moderngl.SRC_ALPHA, moderngl.ONE, moderngl.ONE, moderngl.ONE)
            )
        self._state = state

    def _present(self) -> None:
        if self.window is not None and self._target is self.ctx.screen:
            # Drawn into the window already: shown by the swap when the next frame starts, so that read_pixels
            # (app.capture) can still read this one from the back buffer.
            self._pending_swap = True
        elif self.window is not None:
            # Copy the already-encoded bytes as they are: no second sRGB conversion on the way out.
            self.ctx.disable_direct(GL_FRAMEBUFFER_SRGB)
            raw_gl.blit_color(self._fbo.glo, self.ctx.screen.glo, (self.width, self.height),
                                    self.ctx.screen.size)
            self.window.swap_buffers()

    def _forget_vertex_arrays(self, name: str) -> None:
        """Release the vertex arrays made for mesh or shader ``name`` (gone or rebuilt)."""
        for key in [k for k in self._vaos if name in k]:
            self._vaos.pop(key).release()

    def _vertex_array(self, shader: GLShader, mesh: GLMesh) -> moderngl.VertexArray:
        key = (shader.name, mesh.name)
        vao = self._vaos.get(key)
        if vao is None:
            names = mesh_attributes(shader.name, shader.attributes)
            if names and mesh.data.indirect is not None:
                raise ResourceError(f"mesh '{mesh.name}'", "indirect", f"shader '{shader.name}' reads the attributes "
                                    f"{list(names)}, but an indirectly drawn mesh's vertices are placeholders: the "
                                    "shader must pull its vertices itself (gl_VertexID)")
            content = []
            if names:
                vbo, layout = self.meshes.vertex_buffer(mesh, names)
                fmt = " ".join(a.gl_format for a in layout.attributes)
                content.append((vbo, fmt, *(shader.attributes[a.location] for a in layout.attributes)))
            vao = self.ctx.vertex_array(shader.program, content, mesh.index_buffer, index_element_size=4)
            self._vaos[key] = vao
            self.stats["vertex_arrays_created"] += 1
        return vao

    # --- read-back, resize, release -------------------------------------------------------------------
    def read_pixels(self) -> np.ndarray:
        self.make_current()
        if self._target is not None and self._target is self.ctx.screen:
            data = self._target.read(viewport=(0, 0, self.width, self.height), components=4)
        else:
            data = self._fbo.read(components=4, attachment=0)
        image = np.frombuffer(data, dtype=np.uint8).reshape(self.height, self.width, 4)
        return np.ascontiguousarray(image[::-1])  # GL rows are bottom-up

    def read_pixel(self, x: int, y: int) -> np.ndarray:
        self.make_current()
        data = self.framebuffer.read(viewport=(int(x), self.height - 1 - int(y), 1, 1), components=4)
        return np.frombuffer(data, dtype=np.uint8).copy()

    def resize(self, width: int, height: int) -> None:
        if (width, height) == (self.width, self.height) or width <= 0 or height <= 0:
            return
        self.make_current()
        self._release_targets()
        self.width, self.height = int(width), int(height)
        self._create_targets()

    def live_objects(self) -> int:
        """GPU objects this renderer holds now (for leak tests)."""
        libraries = (self.textures, self.shaders, self.meshes, self.materials, self.buffers)
        return (len(self._vaos) + (self._sky is not None) + (self._shadow is not None)
                + sum(len(lib) for lib in libraries))

    def release(self) -> None:
        self.make_current()
        for vao in self._vaos.values():
            vao.release()
        self._vaos.clear()
        if self._sky is not None:
            self._sky[1].release()
            self._sky = None
        if self._shadow is not None:
            for obj in reversed(self._shadow):
                obj.release()
            self._shadow = None
        for lib in (self.materials, self.buffers, self.meshes, self.shaders, self.textures):
            lib.release()
        self._instance_rows.release()
        if self._instance_buffer is not None:
            self._instance_buffer.release()
        for attached in self.attachments.values():
            attached.release()
        self._frame_ubo.release()
        self._lights_ubo.release()
        self._release_targets()
        self.ctx.release()
