"""WebGPU's stand-in for the tessellator: a compute pass that writes every patch's triangles into a storage
buffer, run on the renderer's own device every frame before the frame is drawn (the queue keeps that order).

The patches' triangles are packed one after the other, and the pass writes their total as the vertex count of an
indirect draw: the frame draws exactly the vertices the level of detail produced, never the whole budget. The
vertex buffer and the draw's buffer are named buffers of the renderer's buffer library (``renderer.buffers``): the
terrain's material binds the first for the vertex shader to pull from, its mesh names the second
(``MeshData(indirect=...)``). The per-patch levels and first vertices go to small buffers of their own that tests
and the study read back.
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
DRAW_BUFFER = "terrain_draw"
#: The compute pass's three dispatches, in order (``tessellate.wgsl``).
ENTRY_POINTS = ("cs_levels", "cs_offsets", "cs_main")


class WGPUTessellator:
    """Builds the compute pipeline; :meth:`run` tessellates for one camera position."""

    def __init__(self, renderer: Any, impl: ModuleType, params: TerrainParams, heightmap: TextureData) -> None:
        # The same range as OpenGL's guaranteed one: the vertex budget grows with its square.
        check_levels(params.min_level, params.max_level, GUARANTEED_MAX_LEVEL, "the compute tessellator's budget")
        device = renderer.device
        self.device, self.params = device, params
        self.patch_count = params.patches * params.patches
        budget = params.budget
        #: The most vertices the pass can write (every patch at the max level): the vertex buffer's capacity.
        self.vertex_count = self.patch_count * 6 * budget * budget
        self.vertices = renderer.buffers.build(VERTEX_BUFFER, self.vertex_count * 16)
        self.draw = renderer.buffers.build(DRAW_BUFFER, 16)
        usage = wgpu.BufferUsage
        self.levels = device.create_buffer(size=self.patch_count * 32, usage=usage.STORAGE | usage.COPY_SRC)
        self.offsets = device.create_buffer(size=self.patch_count * 4, usage=usage.STORAGE | usage.COPY_SRC)
        self.uniforms = device.create_buffer(size=TESSELLATE_PARAMS.size, usage=usage.UNIFORM | usage.COPY_DST)
        pixels = heightmap.pixels
        self.texture = device.create_texture(size=(pixels.shape[1], pixels.shape[0], 1), format="rgba8unorm",
                                             usage=wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST)
        device.queue.write_texture({"texture": self.texture}, pixels.tobytes(),
                                   {"bytes_per_row": pixels.shape[1] * 4, "rows_per_image": pixels.shape[0]},
                                   (pixels.shape[1], pixels.shape[0], 1))
        source = load_shader(WGSL_TESSELLATE, None, "wgsl", [impl_shader_dir(impl)], TESSELLATE_INCLUDES)
        module = device.create_shader_module(code=source.text, label=WGSL_TESSELLATE.name)
        resources = {0: {"buffer": self.uniforms}, 1: self.texture.create_view(), 2: {"buffer": self.vertices},
                     3: {"buffer": self.levels}, 4: {"buffer": self.offsets}, 5: {"buffer": self.draw}}
        # Each entry point gets the bindings it uses ("auto" layouts hold only those).
        uses = {"cs_levels": (0, 1, 3), "cs_offsets": (0, 3, 4, 5), "cs_main": (0, 1, 2, 3, 4)}
        self.pipelines = []
        for entry in ENTRY_POINTS:
            pipeline = device.create_compute_pipeline(layout="auto", compute={"module": module, "entry_point": entry})
            group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=[
                {"binding": b, "resource": resources[b]} for b in uses[entry]])
            self.pipelines.append((pipeline, group))

    # --8<-- [start:run]
    def run(self, eye: np.ndarray) -> None:
        """One compute pass for the camera at ``eye``: the levels (patches² / 64 work groups), the first vertex of
        each patch and the draw's count (one), the vertices ((budget² / 64) × patches² work groups)."""
        p = self.params
        values = {"eye": (*eye, 1.0), "lod": (*p.lod, 0.0), "grid": (p.size, p.height_scale, p.patches, p.budget)}
        self.device.queue.write_buffer(self.uniforms, 0, TESSELLATE_PARAMS.pack(values))
        encoder = self.device.create_command_encoder()
        compute = encoder.begin_compute_pass()
        groups = ((-(-self.patch_count // WORKGROUP_SIZE), 1), (1, 1),
                  (-(-p.budget * p.budget // WORKGROUP_SIZE), self.patch_count))
        for (pipeline, bind_group), (x, y) in zip(self.pipelines, groups):  # each dispatch sees the last one's writes
            compute.set_pipeline(pipeline)
            compute.set_bind_group(0, bind_group)
            compute.dispatch_workgroups(x, y)
        compute.end()
        self.device.queue.submit([encoder.finish()])
    # --8<-- [end:run]

    def read_levels(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(outer (P², 4), inner (P²,), segments n (P²,)) as the last pass computed them."""
        data = np.frombuffer(self.device.queue.read_buffer(self.levels), dtype=np.float32).reshape(-1, 2, 4)
        return data[:, 0].astype(np.float64), data[:, 1, 0].astype(np.float64), data[:, 1, 1].astype(np.int64)

    def read_draw_count(self) -> int:
        """The vertex count the last pass wrote for the indirect draw: what the frame draws."""
        return int(np.frombuffer(self.device.queue.read_buffer(self.draw), dtype=np.uint32)[0])

    def read_vertices(self) -> np.ndarray:
        """(P², 6·L², 4) float32: what the last pass wrote, each patch's 6·n² vertices (u, v, world y, 1) unpacked
        into its budget's slots (cell (i, j) at (j·L + i)·6), zeros in the slots it did not use."""
        data = np.frombuffer(self.device.queue.read_buffer(self.vertices), dtype=np.float32).reshape(-1, 6, 4)
        offsets = np.frombuffer(self.device.queue.read_buffer(self.offsets), dtype=np.uint32)
        n_all = self.read_levels()[2]
        budget = self.params.budget
        out = np.zeros((self.patch_count, budget * budget, 6, 4), dtype=np.float32)
        for pid, (first, n) in enumerate(zip(offsets, n_all)):
            cj, ci = np.divmod(np.arange(n * n), n)
            out[pid, cj * budget + ci] = data[first // 6 + np.arange(n * n)]
        return out.reshape(self.patch_count, -1, 4)

    def release(self) -> None:
        for obj in (self.levels, self.offsets, self.uniforms, self.texture):
            obj.destroy()
