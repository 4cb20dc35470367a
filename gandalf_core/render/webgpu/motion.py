"""The GPU-driven motion pass on WebGPU: a compute pipeline (WGSL) reads the frame's instance buffer and the
motion rows as storage buffers and writes the moved rows into a buffer the draws then bind as their instance
vertex buffer (usage STORAGE | VERTEX). Recorded in the frame's command encoder, before the render passes."""

from __future__ import annotations

from typing import Any

import numpy as np
import wgpu

from ..gpu_motion import KERNEL, WORKGROUP, MotionFrame
from ..shader_files import SNIPPETS_DIR, load_shader


class WGPUMotionPass:
    """Built on the first frame that has GPU-driven motion: the pipeline, the motion rows and the output buffer."""

    def __init__(self, device: Any, stats: Any) -> None:
        self.device = device
        self.stats = stats
        source = load_shader(SNIPPETS_DIR / f"{KERNEL}.wgsl", None, "wgsl")
        storage = wgpu.ShaderStage.COMPUTE
        self.layout = device.create_bind_group_layout(entries=[
            {"binding": 0, "visibility": storage, "buffer": {"type": "uniform"}},
            {"binding": 1, "visibility": storage, "buffer": {"type": "read-only-storage"}},
            {"binding": 2, "visibility": storage, "buffer": {"type": "read-only-storage"}},
            {"binding": 3, "visibility": storage, "buffer": {"type": "storage"}},
        ])
        module = device.create_shader_module(code=source.text, label=f"{KERNEL}.wgsl")
        self.pipeline = device.create_compute_pipeline(
            layout=device.create_pipeline_layout(bind_group_layouts=[self.layout]),
            compute={"module": module, "entry_point": "cs_main"}, label="motion")
        self.params = device.create_buffer(size=16, usage=wgpu.BufferUsage.UNIFORM | wgpu.BufferUsage.COPY_DST)
        self._params = np.zeros(4, dtype=np.float32)
        self.motion: Any = None
        self.moved: Any = None
        self.version: tuple[object, int] | None = None
        self._group: tuple[Any, Any, Any] | None = None  # (instances, motion, bind group)

    def record(self, encoder: Any, instances: Any, count: int, frame: MotionFrame) -> Any:
        """Record the pass that moves ``count`` rows of ``instances``; the buffer the draws read them from."""
        queue = self.device.queue
        rows = frame.rows
        if self.motion is None or self.motion.size < rows.nbytes:
            if self.motion is not None:
                self.motion.destroy()
            self.motion = self.device.create_buffer(size=max(rows.nbytes, 32),
                                                    usage=wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.COPY_DST)
            self.stats["buffers_created"] += 1
            self.version = None
        if self.version != frame.version:
            queue.write_buffer(self.motion, 0, rows)
            self.version = frame.version
        if self.moved is None or self.moved.size < instances.size:
            if self.moved is not None:
                self.moved.destroy()
            self.moved = self.device.create_buffer(size=instances.size,
                                                   usage=wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.VERTEX)
            self.stats["buffers_created"] += 1
            self._group = None
        if self._group is None or self._group[0] is not instances or self._group[1] is not self.motion:
            group = self.device.create_bind_group(layout=self.layout, entries=[
                {"binding": 0, "resource": {"buffer": self.params}},
                {"binding": 1, "resource": {"buffer": instances}},
                {"binding": 2, "resource": {"buffer": self.motion}},
                {"binding": 3, "resource": {"buffer": self.moved}},
            ])
            self._group = (instances, self.motion, group)
        params = self._params
        params[0] = frame.time
        params.view(np.uint32)[1] = count
        queue.write_buffer(self.params, 0, params)
        compute = encoder.begin_compute_pass()
        compute.set_pipeline(self.pipeline)
        compute.set_bind_group(0, self._group[2])
        compute.dispatch_workgroups(-(-count // WORKGROUP))
        compute.end()
        self.stats["motion_passes"] += 1
        return self.moved

    def release(self) -> None:
        for obj in (self.motion, self.moved, self.params):
            if obj is not None:
                obj.destroy()
