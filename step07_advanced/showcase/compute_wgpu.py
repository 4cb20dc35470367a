"""The particle kernel on WebGPU: a compute pipeline (WGSL) over a storage buffer, with wgpu.

WebGPU separates what OpenGL keeps in global state: a bind group layout says which buffers the kernel sees,
a bind group binds the actual buffers, a compute pass in a command encoder records the dispatch, and the
queue submits it. ``queue.read_buffer`` copies the particles back (through a mappable staging buffer).
"""

from __future__ import annotations

from types import ModuleType
from typing import Any

import numpy as np
import wgpu

from gandalf_core.render.shader_files import load_shader
from step07_advanced.editor.frame_inspector.capture import compute_recorded

from .particles import WORKGROUP_SIZE, SimParams
from .shaders import COMPUTE_WGSL, SIM_INCLUDES, SIM_LAYOUT, impl_shader_dir


class WGPUParticleKernel:
    """``state`` (N, 2, 4) float32 lives in a storage buffer; :meth:`step` runs one compute pass."""

    def __init__(self, device: Any, impl: ModuleType, state: np.ndarray) -> None:
        source = load_shader(COMPUTE_WGSL, None, "wgsl", [impl_shader_dir(impl)], SIM_INCLUDES)
        self.device = device
        self.count = int(state.shape[0])
        usage = wgpu.BufferUsage
        self.particles = device.create_buffer_with_data(
            data=np.ascontiguousarray(state, dtype=np.float32).tobytes(),
            usage=usage.STORAGE | usage.COPY_SRC | usage.COPY_DST)
        self.params = device.create_buffer(size=SIM_LAYOUT.size, usage=usage.UNIFORM | usage.COPY_DST)
        layout = device.create_bind_group_layout(entries=[
            {"binding": 0, "visibility": wgpu.ShaderStage.COMPUTE, "buffer": {"type": "uniform"}},
            {"binding": 1, "visibility": wgpu.ShaderStage.COMPUTE, "buffer": {"type": "storage"}},
        ])
        self.bind_group = device.create_bind_group(layout=layout, entries=[
            {"binding": 0, "resource": {"buffer": self.params}},
            {"binding": 1, "resource": {"buffer": self.particles}},
        ])
        module = device.create_shader_module(code=source.text, label=str(COMPUTE_WGSL.name))
        self.pipeline = device.create_compute_pipeline(
            layout=device.create_pipeline_layout(bind_group_layouts=[layout]),
            compute={"module": module, "entry_point": "cs_main"}, label="particles")

    def step(self, params: SimParams) -> None:
        queue = self.device.queue
        queue.write_buffer(self.params, 0, params.pack())
        encoder = self.device.create_command_encoder()
        compute = encoder.begin_compute_pass()
        compute.set_pipeline(self.pipeline)
        compute.set_bind_group(0, self.bind_group)
        groups = -(-self.count // WORKGROUP_SIZE)
        with compute_recorded(self.device, "particles", (groups,), shader=COMPUTE_WGSL.name,
                              buffers=[("particles", self.particles.size)], where=compute):  # listed in a capture
            compute.dispatch_workgroups(groups)
        compute.end()
        queue.submit([encoder.finish()])

    def read(self) -> np.ndarray:
        data = self.device.queue.read_buffer(self.particles)
        return np.frombuffer(data, dtype=np.float32).reshape(self.count, 2, 4).copy()

    def release(self) -> None:
        self.particles.destroy()
        self.params.destroy()
