"""The GPU-driven motion pass on WebGPU: a compute pipeline (WGSL) reads the frame's instance buffer and the
motion rows as storage buffers and writes the moved rows into a storage buffer that the renderer then binds in group 0
for the draws (their vertex shaders fetch the rows by instance index). Recorded in the frame's command encoder, before
the render passes."""

from __future__ import annotations

from typing import Any

import wgpu

from gandalf_core.render.frame import INSTANCE_STRIDE
from gandalf_core.render.gpu_memory import buffer_size
from gandalf_core.render.shader_files import load_shader
from step07_advanced.editor.frame_inspector.capture import compute_recorded

from .motion import KERNEL, PARAMS_INCLUDES, PARAMS_LAYOUT, SHADER_DIR, WORKGROUP, MotionFrame


class WGPUMotionPass:
    """Built on the first frame that has GPU-driven motion: the pipeline, the motion rows and the output buffer."""

    def __init__(self, device: Any, stats: Any) -> None:
        self.device = device
        self.stats = stats
        source = load_shader(SHADER_DIR / f"{KERNEL}.wgsl", None, "wgsl", generated=PARAMS_INCLUDES)
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
        self.params = device.create_buffer(size=max(PARAMS_LAYOUT.size, 16),
                                           usage=wgpu.BufferUsage.UNIFORM | wgpu.BufferUsage.COPY_DST)
        self.motion: Any = None
        self.moved: Any = None
        self.version: tuple[object, int] | None = None
        self._group: tuple[Any, Any, int, Any] | None = None  # (instances, motion, bytes bound, bind group)

    def record(self, encoder: Any, instances: Any, count: int, frame: MotionFrame) -> Any:
        """Record the pass that moves ``count`` rows of ``instances``; the buffer the draws read them from."""
        self._check_limits(instances, count)
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
            self.moved = self.device.create_buffer(size=instances.size, usage=wgpu.BufferUsage.STORAGE)
            self.stats["buffers_created"] += 1
            self._group = None
        size = count * INSTANCE_STRIDE  # bound as used, not the buffer's whole (power-of-two) capacity
        if self._group is None or self._group[:3] != (instances, self.motion, size):
            group = self.device.create_bind_group(layout=self.layout, entries=[
                {"binding": 0, "resource": {"buffer": self.params}},
                {"binding": 1, "resource": {"buffer": instances, "offset": 0, "size": size}},
                {"binding": 2, "resource": {"buffer": self.motion, "offset": 0, "size": rows.nbytes}},
                {"binding": 3, "resource": {"buffer": self.moved, "offset": 0, "size": size}},
            ])
            self._group = (instances, self.motion, size, group)
        queue.write_buffer(self.params, 0, PARAMS_LAYOUT.pack({"time": frame.time, "count": count}))
        compute = encoder.begin_compute_pass()
        compute.set_pipeline(self.pipeline)
        compute.set_bind_group(0, self._group[3])
        groups = -(-count // WORKGROUP)
        with compute_recorded(self.device, "motion", (groups,), shader=f"{KERNEL}.wgsl",
                              buffers=[("instances", size), ("motion", rows.nbytes), ("moved", size)],
                              where=compute):  # listed and timed in a frame capture
            compute.dispatch_workgroups(groups)
        compute.end()
        self.stats["motion_passes"] += 1
        return self.moved

    def _check_limits(self, instances: Any, count: int) -> None:
        """The device's limits on one dispatch and one storage binding, as errors that say what to do."""
        limits = self.device.limits
        groups = -(-count // WORKGROUP)
        if groups > limits["max-compute-workgroups-per-dimension"]:
            raise ValueError(f"GPU-driven motion: {count} instances need {groups} workgroups of {WORKGROUP}, more than "
                             f"this device dispatches at once ({limits['max-compute-workgroups-per-dimension']}); "
                             "move fewer entities on the GPU, or split them over several scenes")
        size = count * INSTANCE_STRIDE
        if size > limits["max-storage-buffer-binding-size"]:
            raise ValueError(f"GPU-driven motion: the instance rows ({size} bytes) are more than this device "
                             f"binds as one storage buffer ({limits['max-storage-buffer-binding-size']} bytes); "
                             "request a device with a higher max_storage_buffer_binding_size, or move fewer entities")

    def gpu_bytes(self) -> int:
        """Bytes of its buffers (the renderer's ``gpu_memory()`` reports them under the kernel's name)."""
        return sum(buffer_size(b) for b in (self.motion, self.moved, self.params))

    def release(self) -> None:
        for obj in (self.motion, self.moved, self.params):
            if obj is not None:
                obj.destroy()
