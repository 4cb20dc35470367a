"""The WebGPU renderer: a wgpu device, an ``rgba8unorm-srgb`` offscreen target, optional window surface.

Each frame: one write of the frame uniforms, one write of all instance data, one render pass with one
instanced draw per (material, mesh) batch, after a depth-only shadow pass when a light casts shadows.
Pipelines are cached by what really selects them (shader, vertex layout, cull/depth/blend state):
changing a material's colour never builds one.
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np
import wgpu

from ...resources import MaterialData, ResourceError
from ...resources.assets import Assets
from ..attributes import mesh_has
from ..base import NOT_RECORDING, Renderer
from ..capabilities import FLOOR, Needs
from ..errors import ShaderCompileError
from ..frame import FRAME_FLOATS, INSTANCE_STRIDE, LIGHTS_BLOCK_BYTES, SHADOW_MAP_SIZE, SKY_STATE, DrawBatch, FrameData
from ..gpu_memory import buffer_size, wgpu_texture_bytes
from ..shader_files import engine_shader_files, load_shader
from ..texture_checks import check_target_size
from .device import request_device
from .libs import BufferLib, MaterialLib, MeshLib, ShaderLib, TextureLib, WGPUMaterial, WGPUMesh, WGPUShader
from .validation import attribute_of, first_cause, missing_input

COLOR_FORMAT = "rgba8unorm-srgb"
DEPTH_FORMAT = "depth32float"
_BLEND = {
    "alpha": {"color": {"src_factor": "src-alpha", "dst_factor": "one-minus-src-alpha", "operation": "add"},
              "alpha": {"src_factor": "one", "dst_factor": "one-minus-src-alpha", "operation": "add"}},
    "additive": {"color": {"src_factor": "src-alpha", "dst_factor": "one", "operation": "add"},
                 "alpha": {"src_factor": "one", "dst_factor": "one", "operation": "add"}},
}


class WebGPURenderer(Renderer):
    """wgpu render context. ``window`` is a :class:`gandalf_core.app.window.Window` or None (headless)."""

    backend = "webgpu"

    def __init__(self, width: int, height: int, window: Any = None, needs: Needs = FLOOR) -> None:
        super().__init__(width, height, window)
        self._surface = None
        #: In a window, frames are drawn straight onto the surface texture (no offscreen target and blit) unless
        #: an overlay needs the offscreen frame; GANDALF_PRESENT=blit turns this off.
        self.present_direct = window is not None and os.environ.get("GANDALF_PRESENT", "").lower() != "blit"
        if window is not None:
            from wgpu.utils.glfw_present_info import get_glfw_present_info

            self._surface = wgpu.gpu.get_canvas_context(get_glfw_present_info(window.handle, vsync=False))
        self.adapter, self.device = request_device(self._surface, needs)
        if self._surface is not None:
            # The blit samples the sRGB frame as linear light; an -srgb surface encodes it back unchanged.
            preferred = self._surface.get_preferred_format(self.adapter)
            self._surface_format = preferred if preferred.endswith("-srgb") else f"{preferred}-srgb"
            # COPY_SRC so that a frame drawn straight onto the surface can still be read back.
            surface_usage = wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC
            try:
                self._surface.configure(device=self.device, format=self._surface_format, usage=surface_usage)
            except ValueError:  # this surface offers no sRGB variant: frames go through the blit, which encodes
                self._surface_format = preferred
                self._surface.configure(device=self.device, format=self._surface_format)
                self.present_direct = False
            self._surface.set_physical_size(*window.framebuffer_size)
            self._present = _PresentBlit(self.device, self._surface_format)
        # Group 0 is the engine's, shared by every pipeline: frame uniforms (0), lights (1), the shadow map (2) with
        # its comparison sampler (3), which shaders declare by including shadow.wgsl, and the instance rows (4),
        # which vertex shaders read by instance index through instance.wgsl.
        visible = wgpu.ShaderStage.VERTEX | wgpu.ShaderStage.FRAGMENT
        self.frame_layout = self.device.create_bind_group_layout(entries=[
            {"binding": 0, "visibility": visible, "buffer": {"type": "uniform"}},
            {"binding": 1, "visibility": visible, "buffer": {"type": "uniform"}},
            {"binding": 2, "visibility": wgpu.ShaderStage.FRAGMENT,
             "texture": {"sample_type": "depth", "view_dimension": "2d"}},
            {"binding": 3, "visibility": wgpu.ShaderStage.FRAGMENT, "sampler": {"type": "comparison"}},
            {"binding": 4, "visibility": wgpu.ShaderStage.VERTEX, "buffer": {"type": "read-only-storage"}},
        ], label="frame")
        uniform = wgpu.BufferUsage.UNIFORM | wgpu.BufferUsage.COPY_DST
        self._frame_buffer = self.device.create_buffer(size=FRAME_FLOATS * 4, usage=uniform)
        self._lights_buffer = self.device.create_buffer(size=LIGHTS_BLOCK_BYTES, usage=uniform)
        self._shadow_sampler = self.device.create_sampler(
            compare="less-equal", mag_filter="linear", min_filter="linear",
            address_mode_u="clamp-to-edge", address_mode_v="clamp-to-edge",
        )
        # Without a shadow-casting light the group holds a 1x1 stand-in map: no pass, no real map.
        self._no_shadow_map = self.device.create_texture(
            size=(1, 1, 1), format=DEPTH_FORMAT, usage=wgpu.TextureUsage.TEXTURE_BINDING, label="no shadow map"
        )
        self._no_shadow_view = self._no_shadow_map.create_view()
        # Before the first instance is drawn, group 0 binds one row of zeros.
        self._no_instances = self.device.create_buffer(size=INSTANCE_STRIDE, usage=wgpu.BufferUsage.STORAGE)
        #: Group 0 as bound with and without the shadow map, for the instance buffer the draws read now.
        self._frame_groups: dict[bool, Any] = {}
        self._frame_groups_for: Any = None  # that buffer
        #: The most bytes of instance rows one storage binding holds on this device.
        self._max_instance_bytes = int(self.device.limits["max-storage-buffer-binding-size"])
        self._shadow: tuple[Any, Any] | None = None  # the map and its view
        self._sky_materials: dict[str, Any] = {}
        self.textures = TextureLib(self.device, self.stats)
        self.shaders = ShaderLib(self.device, self.stats)
        self.meshes = MeshLib(self.device, self.stats)
        #: Storage buffers by name: filled by the app's compute code, read by materials that name them.
        self.buffers = BufferLib(self.device, self.stats)
        self.materials = MaterialLib(self.device, self.shaders, self.textures, self.stats, self.buffers)
        self._pipelines: dict[tuple[Any, ...], Any] = {}
        #: What each pipeline was created with (by id): its primitive, depth-stencil and colour target states, which
        #: a frame capture shows (a GPU pipeline cannot be read back).
        self.pipeline_states: dict[int, dict[str, Any]] = {}
        # Released or replaced textures take the bind groups that use them along (rebuilt on their next use).
        self.textures.on_forget.append(self._forget_materials_using)
        self.textures.on_forget.append(lambda name: self._sky_materials.pop(name, None))
        # A shader rebuilt from new text: the pipelines made with its old module go (each key starts with its name).
        self.shaders.on_forget.append(
            lambda name: [self._pipelines.pop(k) for k in list(self._pipelines) if k[0] == name])
        self._instance_buffer: Any = None
        self._drawn_instances: Any = None  # the instance rows the draws read (moved or not)
        #: The colour format the frame being recorded is drawn in (pipelines are built per format).
        self._target_format = COLOR_FORMAT
        #: A surface texture drawn and submitted but not yet presented (see :meth:`_present_pending`).
        self._pending_surface: Any = None
        self._create_targets()

    def _check_instance_binding(self, count: int) -> None:
        """The vertex shaders read the instance rows as one storage binding: no more than the device binds."""
        limit = self._max_instance_bytes
        if count * INSTANCE_STRIDE > limit:
            raise ValueError(f"{count} instances need {count * INSTANCE_STRIDE} bytes of instance rows, more than this "
                             f"device binds as one storage buffer (max-storage-buffer-binding-size {limit}); draw "
                             "fewer entities, or request a device with a higher limit")

    def frame_group(self, shadowed: bool) -> Any:
        """Group 0 for the draws: the frame's blocks, the shadow map (``shadowed``) or its 1x1 stand-in, and the
        instance rows the draws read this frame (made again only when that buffer changes)."""
        rows = self._drawn_instances if self._drawn_instances is not None else self._no_instances
        if self._frame_groups_for is not rows:
            self._frame_groups, self._frame_groups_for = {}, rows
        group = self._frame_groups.get(shadowed)
        if group is None:
            shadow_view = self._shadow[1] if shadowed and self._shadow is not None else self._no_shadow_view
            group = self._frame_groups[shadowed] = self.device.create_bind_group(layout=self.frame_layout, entries=[
                {"binding": 0, "resource": {"buffer": self._frame_buffer}},
                {"binding": 1, "resource": {"buffer": self._lights_buffer}},
                {"binding": 2, "resource": shadow_view},
                {"binding": 3, "resource": self._shadow_sampler},
                {"binding": 4, "resource": {"buffer": rows, "offset": 0,
                                            "size": min(rows.size, self._max_instance_bytes)}},
            ])
        return group

    # --8<-- [start:targets]
    def _create_targets(self) -> None:
        check_target_size(self.width, self.height, int(self.device.limits["max-texture-dimension-2d"]))
        usage = wgpu.TextureUsage
        self._color = self.device.create_texture(
            size=(self.width, self.height, 1), format=COLOR_FORMAT,
            usage=usage.RENDER_ATTACHMENT | usage.COPY_SRC | usage.TEXTURE_BINDING,
        )
        self._depth = self.device.create_texture(
            size=(self.width, self.height, 1), format=DEPTH_FORMAT,
            usage=usage.RENDER_ATTACHMENT | usage.COPY_SRC,  # COPY_SRC: read back by the texture viewer
        )
        self.color_view = self._color.create_view()
        self.depth_view = self._depth.create_view()
    # --8<-- [end:targets]

    # --- a frame ------------------------------------------------------------------------------------
    def render(self, data: FrameData, assets: Assets) -> None:
        self.stats["draw_calls"] = 0
        self._present_pending()
        surface_texture = self._surface.get_current_texture() if self._surface is not None else None
        direct = surface_texture is not None and self._can_draw_direct(surface_texture)
        target_view = surface_texture.create_view() if direct else self.color_view
        self._target_format = self._surface_format if direct else COLOR_FORMAT
        queue = self.device.queue
        queue.write_buffer(self._frame_buffer, 0, data.frame)
        if self._lights_changed(data.lights):
            queue.write_buffer(self._lights_buffer, 0, data.lights)
        if data.batches:
            self._check_instance_binding(len(data.instances))
            self._upload_instances(data)
        # Resolve everything before recording, so a missing resource fails before a pass is open.
        draws = [(batch, material, mesh, self._pipeline(material, mesh, data.reverse_z, batch.mirrored))
                 for batch, material, mesh in self.resolve_draws(data, assets)]
        sky = self._sky_draw(data.skybox, assets, data.reverse_z) if data.skybox is not None else None
        encoder = self.device.create_command_encoder()
        recorder = self.recorder  # the frame-capture hook (see Renderer.recorder), or None
        if recorder is not None:
            recorder.begin_frame(data.frame, data.lights, encoder)
        self._drawn_instances = self._instance_buffer
        if data.instance_pass is not None and data.batches:  # GPU work over the rows: the draws read its output
            self._drawn_instances = data.instance_pass.record(self, encoder, self._instance_buffer,
                                                              len(data.instances))
        frame_group = self.frame_group(False)
        if data.shadows:
            frame_group = self._draw_shadow_map(encoder, draws)
        target = f"frame {self.width}x{self.height} ({self._target_format}, {DEPTH_FORMAT})"
        # --8<-- [start:clear]
        rpass = encoder.begin_render_pass(
            color_attachments=[{
                "view": target_view, "clear_value": tuple(float(x) for x in data.clear_color),
                "load_op": "clear", "store_op": "store",
            }],
            depth_stencil_attachment={
                "view": self.depth_view, "depth_clear_value": 0.0 if data.reverse_z else 1.0,
                "depth_load_op": "clear", "depth_store_op": "store",
            },
            timestamp_writes=recorder.begin_target(target, encoder) if recorder is not None else None,
        )
        rpass.set_bind_group(0, frame_group)
        # --8<-- [end:clear]

        def draw_sky() -> None:
            pipeline, bind_group = sky
            rpass.set_pipeline(pipeline)
            rpass.set_bind_group(1, bind_group)
            with NOT_RECORDING if recorder is None else recorder.draw(
                    "sky", rpass, self.pass_shader("sky"), reverse_z=data.reverse_z, sky=data.skybox,
                    pipeline=pipeline):
                rpass.draw(3)
            self.stats["draw_calls"] += 1

        for batch, material, mesh, (pipeline, attributes) in draws:
            if batch.transparent and sky is not None:  # the sky goes behind blended surfaces
                draw_sky()
                sky = None
            rpass.set_pipeline(pipeline)
            if material.bind_group is not None:
                rpass.set_bind_group(1, material.bind_group)
            if recorder is None:
                self._draw_batch(rpass, material.shader, mesh, attributes, batch)
            else:  # a frame capture: one record per draw
                with recorder.draw("transparent" if batch.transparent else "opaque", rpass, material.shader, batch,
                                   material, mesh, data.reverse_z, pipeline=pipeline):
                    self._draw_batch(rpass, material.shader, mesh, attributes, batch)
        if sky is not None:
            draw_sky()
        with recorder.overlay(rpass) if recorder is not None and self.overlays else NOT_RECORDING:
            for overlay in self.overlays:  # last, in the same pass: no second pass over the frame
                overlay(self, rpass)
        if recorder is not None:
            recorder.end_target(rpass)
        rpass.end()
        if recorder is not None:
            recorder.end_frame(encoder)
        if surface_texture is not None and not direct:
            self._present.draw(encoder, self.color_view, surface_texture.create_view())
        queue.submit([encoder.finish()])
        if direct:
            self._pending_surface = surface_texture  # presented when the next frame starts
        elif surface_texture is not None:
            self._surface.present()

    # --8<-- [start:direct]
    def _can_draw_direct(self, surface_texture: Any) -> bool:
        """Whether this frame is drawn straight onto the window's surface texture instead of the offscreen target.

        Direct: the frame's passes draw into the surface texture (an ``-srgb`` format, so the shaders' linear
        colours are encoded once, as on the offscreen target) and no blit follows; the present is deferred to
        the next frame so that read-back still sees this one. Not with overlays (the editor draws over the
        offscreen frame), nor when the surface's size differs from the depth target's.
        """
        return (self.present_direct and not self.overlays
                and tuple(surface_texture.size[:2]) == (self.width, self.height))

    def _present_pending(self) -> None:
        """Show the surface texture of the last direct frame. Deferred so that read-back still sees it."""
        if self._pending_surface is not None and self._surface is not None:
            self._pending_surface = None
            self._surface.present()
    # --8<-- [end:direct]

    def _draw_batch(self, rpass: Any, shader: WGPUShader, mesh: WGPUMesh, attributes: tuple[str, ...],
                    batch: DrawBatch) -> None:
        """One instanced draw of ``batch``: the mesh's buffer with ``attributes``; the batch's instance rows start
        at its first instance, which the vertex shader's instance index counts from (group 0 binds the rows)."""
        if attributes:
            vbo, _layout = self.meshes.vertex_buffer(mesh, attributes)
            rpass.set_vertex_buffer(0, vbo)
        first = batch.first_instance
        if mesh.data.indirect is not None:  # the count a compute pass wrote; the instances are the batch's
            if first and "indirect-first-instance" not in self.device.features:
                raise ResourceError(f"mesh '{mesh.name}'", "indirect",
                                    f"this device lacks WebGPU's 'indirect-first-instance' feature, so an indirectly "
                                    f"drawn mesh can only draw the frame's first instances (its batch starts at row "
                                    f"{first}); draw it from a scene of its own")
            buffer = self.indirect_buffer(mesh.name, mesh.data)
            self.device.queue.write_buffer(buffer, 4, np.array([batch.count, 0, first], dtype=np.uint32).tobytes())
            rpass.draw_indirect(buffer, 0)
        elif mesh.index_buffer is not None:
            rpass.set_index_buffer(mesh.index_buffer, "uint32")
            rpass.draw_indexed(mesh.count, batch.count, 0, 0, first)
        else:
            rpass.draw(mesh.count, batch.count, 0, first)
        self.stats["draw_calls"] += 1

    # --8<-- [start:shadow_pass]
    def _draw_shadow_map(self, encoder: Any, draws: list[tuple[Any, ...]]) -> Any:
        """Record the shadow pass (every opaque batch, depth only, from the light) and return the frame
        bind group that binds the map for the main pass. The map, shader and pipelines are built on first use."""
        if self._shadow is None:
            texture = self.device.create_texture(
                size=(SHADOW_MAP_SIZE, SHADOW_MAP_SIZE, 1), format=DEPTH_FORMAT,
                usage=wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.TEXTURE_BINDING
                | wgpu.TextureUsage.COPY_SRC, label="shadow map",
            )
            view = texture.create_view()
            self._shadow = (texture, view)
            self._frame_groups.pop(True, None)
            self.stats["shadow_maps_created"] += 1
        _texture, view = self._shadow
        shader = self.pass_shader("shadow")
        recorder = self.recorder
        target = f"shadow map {SHADOW_MAP_SIZE}x{SHADOW_MAP_SIZE} ({DEPTH_FORMAT})"
        rpass = encoder.begin_render_pass(color_attachments=[], depth_stencil_attachment={
            "view": view, "depth_clear_value": 1.0, "depth_load_op": "clear", "depth_store_op": "store",
        }, timestamp_writes=recorder.begin_target(target, encoder) if recorder is not None else None)
        # The stand-in group: the map itself must not be bound while this pass writes it.
        rpass.set_bind_group(0, self.frame_group(False))
        for batch, material, mesh, _pipeline in draws:
            if batch.transparent:
                continue
            pipeline, attributes = self._shadow_pipeline(shader, mesh)
            rpass.set_pipeline(pipeline)
            if recorder is None:
                self._draw_batch(rpass, shader, mesh, attributes, batch)
            else:
                with recorder.draw("shadow", rpass, shader, batch, material, mesh, pipeline=pipeline):
                    self._draw_batch(rpass, shader, mesh, attributes, batch)
        if recorder is not None:
            recorder.end_target(rpass)
        rpass.end()
        self.stats["shadow_passes"] += 1
        return self.frame_group(True)

    def _shadow_pipeline(self, shader: WGPUShader, mesh: WGPUMesh) -> tuple[Any, tuple[str, ...]]:
        """The depth-only pipeline for ``mesh``'s position layout (one for all meshes of the same layout)."""
        attributes = mesh_has(mesh.data)
        key = (shader.name, attributes)
        pipeline = self._pipelines.get(key)
        if pipeline is None:
            buffers = self._buffer_layouts(mesh, attributes)
            # Both faces cast, so open meshes and single planes throw shadows too.
            primitive = {"topology": "triangle-list", "cull_mode": "none"}
            depth = {"format": DEPTH_FORMAT, "depth_write_enabled": True, "depth_compare": "less-equal"}
            pipeline = self._pipelines[key] = self._checked(shader, mesh, lambda: self.device.create_render_pipeline(
                layout=self.device.create_pipeline_layout(bind_group_layouts=[self.frame_layout]),
                vertex={"module": shader.module, "entry_point": shader.vertex_entry, "buffers": buffers},
                fragment={"module": shader.module, "entry_point": shader.fragment_entry, "targets": []},
                primitive=primitive, depth_stencil=depth, label="shadow pipeline",
            ))
            self.pipeline_states[id(pipeline)] = {"primitive": primitive, "depth_stencil": depth, "targets": []}
            self.stats["pipelines_created"] += 1
        return pipeline, attributes
    # --8<-- [end:shadow_pass]

    def _sky_draw(self, texture_name: str, assets: Assets, reverse_z: bool) -> tuple[Any, Any]:
        """The sky pass's pipeline and bind group, built on first use (only scenes with a skybox pay for it)."""
        texture = self.resolve_sky(texture_name, assets)
        shader = self.pass_shader("sky")
        material = self._sky_materials.get(texture_name)
        if material is None:
            material = self.device.create_bind_group(layout=self._sky_layout(), entries=[
                {"binding": 0, "resource": texture.view}, {"binding": 1, "resource": texture.sampler},
            ])
            self._sky_materials[texture_name] = material
        key = (shader.name, reverse_z, self._target_format)
        pipeline = self._pipelines.get(key)
        if pipeline is None:
            pipeline = self._pipelines[key] = self._create_pipeline(shader, [], SKY_STATE, reverse_z,
                                                                    self._sky_layout())
        return pipeline, material

    def _frame_gpu_memory(self) -> dict[str, int]:
        return {"frame targets": wgpu_texture_bytes(self._color) + wgpu_texture_bytes(self._depth),
                "shadow map": wgpu_texture_bytes(self._shadow[0]) if self._shadow is not None else 0,
                "instances": buffer_size(self._instance_buffer),
                "frame uniforms": sum(buffer_size(b) for b in (self._frame_buffer, self._lights_buffer,
                                                               self._no_instances))
                + wgpu_texture_bytes(self._no_shadow_map)}

    def _renew_instance_buffer(self, capacity: int | None) -> None:
        if capacity is None:
            return
        if self._instance_buffer is not None:
            self._instance_buffer.destroy()
        self._instance_buffer = self.device.create_buffer(
            # A storage buffer: the vertex shaders fetch the rows by instance index (group 0), and a GPU pass over
            # them (FrameData.instance_pass) reads them too.
            size=capacity, usage=wgpu.BufferUsage.COPY_DST | wgpu.BufferUsage.STORAGE
        )

    def _write_instances(self, rows: np.ndarray, offset: int) -> None:
        self.device.queue.write_buffer(self._instance_buffer, offset, rows)

    def _pipeline(self, material: WGPUMaterial, mesh: WGPUMesh, reverse_z: bool,
                  mirrored: bool = False) -> tuple[Any, tuple[str, ...]]:
        shader = material.shader
        attributes = mesh_has(mesh.data)
        data = material.data
        key = (*data.pipeline_key(), material.layout_key, attributes, reverse_z, mirrored, self._target_format)
        pipeline = self._pipelines.get(key)
        if pipeline is None:
            buffers = self._buffer_layouts(mesh, attributes)
            pipeline = self._pipelines[key] = self._checked(shader, mesh, lambda: self._create_pipeline(
                shader, buffers, data, reverse_z, material.group_layout, mirrored))
        return pipeline, attributes

    def _buffer_layouts(self, mesh: WGPUMesh, attributes: tuple[str, ...]) -> list[Any]:
        """The vertex buffer layouts of a draw: the mesh's interleaved ``attributes`` (none for an indirectly drawn
        mesh, whose shader pulls its vertices). The instance rows are no vertex buffer: group 0 binds them."""
        if not attributes:
            return []
        _vbo, layout = self.meshes.vertex_buffer(mesh, attributes)
        return [self._vertex_layout(layout)]

    def _sky_layout(self) -> Any:
        return self.shaders.group_layout(("texture-cube", "sampler"))

    @staticmethod
    def _checked(shader: WGPUShader, mesh: WGPUMesh, create: Any) -> Any:
        """``create()``, with naga's complaint about a vertex input the mesh lacks as an error naming both."""
        try:
            return create()
        except wgpu.GPUError as exc:
            missing = missing_input(str(exc))
            name = attribute_of(missing[1]) if missing is not None and missing[0] == "vertex" else None
            if name is not None:
                raise ResourceError(f"mesh '{mesh.name}'", f"{name}s", f"shader '{shader.name}' "
                                    f"({shader.source.filename}) needs attribute '{name}' (@location({missing[1]})), "
                                    "but the mesh has none (give it, or call with_normals/with_tangents)") from None
            raise ShaderCompileError(f"shader '{shader.name}' ({shader.source.filename}): {first_cause(str(exc))}") \
                from None

    @staticmethod
    def _vertex_layout(layout: Any) -> dict[str, Any]:
        return {
            "array_stride": layout.stride, "step_mode": "vertex",
            "attributes": [{"format": a.wgpu_format, "offset": a.offset_bytes, "shader_location": a.location}
                           for a in layout.attributes],
        }

    def _create_pipeline(self, shader: WGPUShader, buffers: list[dict[str, Any]], data: MaterialData,
                         reverse_z: bool, group_layout: Any, mirrored: bool = False) -> Any:
        layouts = [self.frame_layout] + ([group_layout] if group_layout is not None else [])
        target: dict[str, Any] = {"format": self._target_format}
        if data.blend != "opaque":
            target["blend"] = _BLEND[data.blend]
        compare = ("greater-equal" if reverse_z else "less-equal") if data.depth_test else "always"
        # A mirrored instance's triangles wind the other way round on screen.
        primitive = {"topology": "triangle-list", "front_face": "cw" if mirrored else "ccw", "cull_mode": data.cull}
        depth = {"format": DEPTH_FORMAT, "depth_write_enabled": data.depth_write, "depth_compare": compare}
        pipeline = self.device.create_render_pipeline(
            layout=self.device.create_pipeline_layout(bind_group_layouts=layouts),
            vertex={"module": shader.module, "entry_point": shader.vertex_entry, "buffers": buffers},
            fragment={"module": shader.module, "entry_point": shader.fragment_entry, "targets": [target]},
            primitive=primitive, depth_stencil=depth, label=f"{shader.name} pipeline",
        )
        self.pipeline_states[id(pipeline)] = {"primitive": primitive, "depth_stencil": depth, "targets": [target]}
        self.stats["pipelines_created"] += 1
        return pipeline

    # --- read-back, resize, release -------------------------------------------------------------------
    @property
    def frame_texture(self) -> Any:
        """The texture the current (or last) frame is drawn into: the window's surface texture while one is
        pending, else the offscreen target (the WebGPU twin of the OpenGL renderer's ``framebuffer``)."""
        return self._frame_texture()[0]

    def _frame_texture(self) -> tuple[Any, bool]:
        """The texture holding the last frame, and whether its bytes are in BGRA order."""
        if self._pending_surface is not None:
            return self._pending_surface, self._surface_format.startswith("bgra")
        return self._color, False

    def read_pixels(self) -> np.ndarray:
        texture, bgra = self._frame_texture()
        data = self.device.queue.read_texture(
            {"texture": texture, "origin": (0, 0, 0), "mip_level": 0},
            {"offset": 0, "bytes_per_row": self.width * 4, "rows_per_image": self.height},
            (self.width, self.height, 1),
        )
        pixels = np.frombuffer(data, dtype=np.uint8).reshape(self.height, self.width, 4)
        return pixels[..., [2, 1, 0, 3]] if bgra else pixels.copy()

    def read_pixel(self, x: int, y: int) -> np.ndarray:
        texture, bgra = self._frame_texture()
        data = self.device.queue.read_texture(
            {"texture": texture, "origin": (int(x), int(y), 0), "mip_level": 0},
            {"offset": 0, "bytes_per_row": 4, "rows_per_image": 1},
            (1, 1, 1),
        )
        pixel = np.frombuffer(data, dtype=np.uint8)
        return pixel[[2, 1, 0, 3]] if bgra else pixel.copy()

    def resize(self, width: int, height: int) -> None:
        if (width, height) == (self.width, self.height) or width <= 0 or height <= 0:
            return
        self._color.destroy()
        self._depth.destroy()
        self.width, self.height = int(width), int(height)
        self._create_targets()
        if self._surface is not None:
            self._surface.set_physical_size(*self.window.framebuffer_size)

    def live_objects(self) -> int:
        """GPU objects this renderer holds now (for leak tests)."""
        libraries = (self.textures, self.shaders, self.meshes, self.materials, self.buffers)
        return (len(self._pipelines) + len(self._sky_materials) + (self._shadow is not None)
                + sum(len(lib) for lib in libraries))

    def release(self) -> None:
        self._present_pending()  # a surface texture must not outlive its device unpresented
        for lib in (self.materials, self.buffers, self.meshes, self.shaders, self.textures):
            lib.release()
        self._pipelines.clear()
        self.pipeline_states.clear()
        self._sky_materials.clear()
        if self._instance_buffer is not None:
            self._instance_buffer.destroy()
        self._no_instances.destroy()
        self._frame_groups, self._frame_groups_for = {}, None
        for attached in self.attachments.values():
            attached.release()
        if self._shadow is not None:
            self._shadow[0].destroy()
            self._shadow = None
        self._no_shadow_map.destroy()
        self._frame_buffer.destroy()
        self._lights_buffer.destroy()
        self._color.destroy()
        self._depth.destroy()
        self.device.destroy()


class _PresentBlit:
    """Draws the offscreen target onto the window's surface texture with a full-screen triangle."""

    def __init__(self, device: Any, surface_format: str) -> None:
        (path,) = engine_shader_files("present", "wgsl")
        module = device.create_shader_module(code=load_shader(path).text, label=path.name)
        self.device = device
        self.pipeline = device.create_render_pipeline(
            layout="auto",
            vertex={"module": module, "entry_point": "vs_main"},
            fragment={"module": module, "entry_point": "fs_main", "targets": [{"format": surface_format}]},
            primitive={"topology": "triangle-list"},
        )
        self.sampler = device.create_sampler()

    def draw(self, encoder: Any, source_view: Any, target_view: Any) -> None:
        bind_group = self.device.create_bind_group(
            layout=self.pipeline.get_bind_group_layout(0),
            entries=[{"binding": 0, "resource": source_view}, {"binding": 1, "resource": self.sampler}],
        )
        rpass = encoder.begin_render_pass(color_attachments=[
            {"view": target_view, "load_op": "clear", "store_op": "store", "clear_value": (0, 0, 0, 1)}
        ])
        rpass.set_pipeline(self.pipeline)
        rpass.set_bind_group(0, bind_group)
        rpass.draw(3)
        rpass.end()
