"""The path tracing kernel on WebGPU: a WGSL compute pipeline on the renderer's wgpu device.

One bind group holds everything: the per-dispatch values (a uniform buffer), the scene's arrays (read-only
storage buffers) and the accumulation buffer (read-write storage), which is the renderer's own
``renderer.buffers`` entry that the display material reads. Each dispatch is its own command buffer submitted
before the frame's render pass: the queue runs them in order, so the display sees every sample (no barrier call).
"""

from __future__ import annotations

from types import ModuleType
from typing import Any

import numpy as np
import wgpu

from .scene import PackedScene
from .shaders import PARAMS_LAYOUT, explain_error, kernel_source

GROUP = 8


class WGPUPathTracer:
    """One sample per pixel per :meth:`dispatch` into ``accum`` (``width`` × ``height`` vec4, rgb sum + count)."""

    backend = "webgpu"

    def __init__(self, device: Any, impl: ModuleType, accum: Any, width: int, height: int) -> None:
        if accum.size < width * height * 16:
            raise ValueError(f"the accumulation buffer holds {accum.size} bytes; {width}x{height} pixels need "
                             f"{width * height * 16}")
        src = kernel_source("webgpu", impl)
        try:
            module = device.create_shader_module(code=src.text, label=src.filename)
        except wgpu.GPUError as exc:
            raise RuntimeError(explain_error(src, str(exc))) from None
        stage = wgpu.ShaderStage.COMPUTE
        entries = [{"binding": 0, "visibility": stage, "buffer": {"type": "uniform"}}]
        entries += [{"binding": b, "visibility": stage, "buffer": {"type": "read-only-storage"}} for b in range(1, 6)]
        entries.append({"binding": 6, "visibility": stage, "buffer": {"type": "storage"}})
        self.layout = device.create_bind_group_layout(entries=entries, label="path tracer")
        self.pipeline = device.create_compute_pipeline(
            layout=device.create_pipeline_layout(bind_group_layouts=[self.layout]),
            compute={"module": module, "entry_point": "cs_main"}, label="path tracer")
        self.device, self.accum, self.width, self.height = device, accum, int(width), int(height)
        usage = wgpu.BufferUsage
        self.params = device.create_buffer(size=PARAMS_LAYOUT.size,
                                           usage=usage.UNIFORM | usage.COPY_DST | usage.COPY_SRC)
        self.buffers: list[Any] = []
        self.bind_group = None
        self.packed: PackedScene | None = None
        self.owns_accum = False

    @classmethod
    def standalone(cls, impl: ModuleType, width: int, height: int) -> WGPUPathTracer:
        """A kernel on its own headless device with its own accumulation buffer (the study)."""
        from gandalf_core.render.webgpu.device import request_device

        adapter, device = request_device()[:2]
        usage = wgpu.BufferUsage
        accum = device.create_buffer(size=width * height * 16, usage=usage.STORAGE | usage.COPY_SRC | usage.COPY_DST)
        tracer = cls(device, impl, accum, width, height)
        tracer.adapter = adapter
        tracer.owns_accum = True
        return tracer

    @property
    def device_name(self) -> str:
        info = getattr(getattr(self, "adapter", None), "info", None) or {}
        return str(info.get("device", "?"))

    def load(self, packed: PackedScene) -> None:
        """Upload the scene's arrays (replacing the previous scene's)."""
        for buf in self.buffers:
            buf.destroy()
        usage = wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.COPY_DST
        self.buffers = [self.device.create_buffer_with_data(data=np.ascontiguousarray(a, np.float32).tobytes(),
                                                            usage=usage)
                        for a in (packed.spheres, packed.materials, packed.triangles, packed.nodes, packed.sky)]
        resources = [self.params, *self.buffers, self.accum]
        self.bind_group = self.device.create_bind_group(layout=self.layout, entries=[
            {"binding": b, "resource": {"buffer": buf}} for b, buf in enumerate(resources)])
        self.packed = packed

    def clear(self) -> None:
        """Zero the accumulation (a new picture starts)."""
        encoder = self.device.create_command_encoder()
        encoder.clear_buffer(self.accum, 0, self.width * self.height * 16)
        self.device.queue.submit([encoder.finish()])

    # --8<-- [start:dispatch]
    def dispatch(self, sample_index: int, seed: int | None = None) -> None:
        """Add sample ``sample_index`` of every pixel to the accumulation."""
        if self.packed is None:
            raise RuntimeError("load a scene before dispatching the path tracer")
        queue = self.device.queue
        queue.write_buffer(self.params, 0, self.packed.params(sample_index, self.width, self.height, seed))
        encoder = self.device.create_command_encoder()
        compute = encoder.begin_compute_pass()
        compute.set_pipeline(self.pipeline)
        compute.set_bind_group(0, self.bind_group)
        compute.dispatch_workgroups(-(-self.width // GROUP), -(-self.height // GROUP))
        compute.end()
        queue.submit([encoder.finish()])  # before the frame's render pass: the queue keeps the order
    # --8<-- [end:dispatch]

    def finish(self) -> None:
        """Wait until the GPU has done everything submitted so far (a small read-back: see STACK.md F4)."""
        self.device.queue.read_buffer(self.params)

    def read(self) -> np.ndarray:
        """The accumulation, (height, width, 4) float32, top row first (rgb: sums, a: sample count)."""
        data = self.device.queue.read_buffer(self.accum, 0, self.width * self.height * 16)
        return np.frombuffer(data, np.float32).reshape(self.height, self.width, 4).copy()

    def release(self) -> None:
        for buf in (*self.buffers, self.params):
            buf.destroy()
        self.buffers = []
        if self.owns_accum:
            self.accum.destroy()
            self.owns_accum = False
