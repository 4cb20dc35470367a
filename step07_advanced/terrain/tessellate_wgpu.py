"""WebGPU's stand-in for the tessellator: a compute pass that writes every patch's triangles into a storage
buffer, run on the renderer's own device every frame before the frame is drawn (the queue keeps that order).

The vertex buffer is a named buffer of the renderer's buffer library (``renderer.buffers``), so the terrain's
material binds it for the vertex shader to pull from; the per-patch levels go to a small buffer of their own
that tests and the study read back.
"""

from __future__ import annotations

from types import ModuleType
from typing import Any

import numpy as np
import wgpu

from gandalf_core.render.shader_files import load_shader
from gandalf_core.resources import TextureData

from .patches import GUARANTEED_MAX_LEVEL, TerrainParams, check_levels
from .shaders import TESSELLATE_INCLUDES, TESSELLATE_PARAMS, WGSL_TESSELLATE, impl_shader_dir

WORKGROUP_SIZE = 64
VERTEX_BUFFER = "terrain_vertices"


class WGPUTessellator:
    """Builds the compute pipeline; :meth:`run` tessellates for one camera position."""

    def __init__(self, renderer: Any, impl: ModuleType, params: TerrainParams, heightmap: TextureData) -> None:
        # The same range as OpenGL's guaranteed one: the vertex budget grows with its square.
        check_levels(params.min_level, params.max_level, GUARANTEED_MAX_LEVEL, "the compute tessellator's budget")
        device = renderer.device
        self.device, self.params = device, params
        self.patch_count = params.patches * params.patches
        budget = params.budget
        self.vertex_count = self.patch_count * 6 * budget * budget
        self.vertices = renderer.buffers.build(VERTEX_BUFFER, self.vertex_count * 16)
        usage = wgpu.BufferUsage
        self.levels = device.create_buffer(size=self.patch_count * 32, usage=usage.STORAGE | usage.COPY_SRC)
        self.uniforms = device.create_buffer(size=TESSELLATE_PARAMS.size, usage=usage.UNIFORM | usage.COPY_DST)
        pixels = heightmap.pixels
        self.texture = device.create_texture(size=(pixels.shape[1], pixels.shape[0], 1), format="rgba8unorm",
                                             usage=wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST)
        device.queue.write_texture({"texture": self.texture}, pixels.tobytes(),
                                   {"bytes_per_row": pixels.shape[1] * 4, "rows_per_image": pixels.shape[0]},
                                   (pixels.shape[1], pixels.shape[0], 1))
        source = load_shader(WGSL_TESSELLATE, None, "wgsl", [impl_shader_dir(impl)], TESSELLATE_INCLUDES)
        module = device.create_shader_module(code=source.text, label=WGSL_TESSELLATE.name)
        self.pipeline = device.create_compute_pipeline(layout="auto", compute={"module": module,
                                                                              "entry_point": "cs_main"})
        self.bind_group = device.create_bind_group(layout=self.pipeline.get_bind_group_layout(0), entries=[
            {"binding": 0, "resource": {"buffer": self.uniforms}},
            {"binding": 1, "resource": self.texture.create_view()},
            {"binding": 2, "resource": {"buffer": self.vertices}},
            {"binding": 3, "resource": {"buffer": self.levels}},
        ])

    # --8<-- [start:run]
    def run(self, eye: np.ndarray) -> None:
        """One compute pass for the camera at ``eye``: (budget² / 64) × patches² work groups."""
        p = self.params
        values = {"eye": (*eye, 1.0), "lod": (*p.lod, 0.0), "grid": (p.size, p.height_scale, p.patches, p.budget)}
        self.device.queue.write_buffer(self.uniforms, 0, TESSELLATE_PARAMS.pack(values))
        encoder = self.device.create_command_encoder()
        compute = encoder.begin_compute_pass()
        compute.set_pipeline(self.pipeline)
        compute.set_bind_group(0, self.bind_group)
        compute.dispatch_workgroups(-(-p.budget * p.budget // WORKGROUP_SIZE), self.patch_count)
        compute.end()
        self.device.queue.submit([encoder.finish()])
    # --8<-- [end:run]

    def read_levels(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(outer (P², 4), inner (P²,), segments n (P²,)) as the last pass computed them."""
        data = np.frombuffer(self.device.queue.read_buffer(self.levels), dtype=np.float32).reshape(-1, 2, 4)
        return data[:, 0].astype(np.float64), data[:, 1, 0].astype(np.float64), data[:, 1, 1].astype(np.int64)

    def read_vertices(self) -> np.ndarray:
        """(P², 6·L², 4) float32: what the last pass wrote, (u, v, world y, 1) or zeros in unused slots."""
        data = np.frombuffer(self.device.queue.read_buffer(self.vertices), dtype=np.float32)
        return data.reshape(self.patch_count, -1, 4).copy()

    def release(self) -> None:
        for obj in (self.levels, self.uniforms, self.texture):
            obj.destroy()
