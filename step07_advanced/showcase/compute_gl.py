"""The particle kernel on OpenGL: a compute shader (GLSL 4.30) over a shader storage buffer, with moderngl.

OpenGL runs compute in the same context as drawing: ``ctx.compute_shader`` compiles it, buffers are bound to
indexed binding points (``bind_to_uniform_block`` / ``bind_to_storage_buffer``), ``run(groups)`` dispatches,
and ``buffer.read()`` waits for the GPU and copies the particles back.
"""

from __future__ import annotations

from types import ModuleType

import moderngl
import numpy as np

from gandalf_core.render.capabilities import require_opengl
from gandalf_core.render.shader_files import load_shader
from step07_advanced.editor.frame_inspector.capture import compute_recorded

from .particles import WORKGROUP_SIZE, SimParams
from .shaders import COMPUTE_GLSL, SIM_BINDING, SIM_INCLUDES, SIM_LAYOUT, impl_shader_dir

#: Compute shaders arrived in OpenGL 4.3; the render shaders only need 3.3.
REQUIRED_VERSION = 430


class GLParticleKernel:
    """``state`` (N, 2, 4) float32 lives in a storage buffer; :meth:`step` runs one kernel dispatch."""

    def __init__(self, ctx: moderngl.Context, impl: ModuleType, state: np.ndarray) -> None:
        require_opengl(ctx, REQUIRED_VERSION, "compute shaders", "the particle kernel")
        source = load_shader(COMPUTE_GLSL, "compute", "glsl", [impl_shader_dir(impl)], SIM_INCLUDES)
        self.ctx = ctx
        self.program = ctx.compute_shader(source.text)
        self.count = int(state.shape[0])
        self.particles = ctx.buffer(np.ascontiguousarray(state, dtype=np.float32).tobytes())
        self.params = ctx.buffer(reserve=SIM_LAYOUT.size)

    def step(self, params: SimParams) -> None:
        self.params.write(params.pack())
        self.params.bind_to_uniform_block(SIM_BINDING)  # the kernel's SimParams block
        self.particles.bind_to_storage_buffer(1)
        groups = -(-self.count // WORKGROUP_SIZE)
        with compute_recorded(self.ctx, "particles", (groups,), shader=COMPUTE_GLSL.name,
                              buffers=[("particles", self.particles.size)]):  # listed in a frame capture
            self.program.run(group_x=groups)
        # Make the kernel's writes visible to the next dispatch and to the read-back.
        self.ctx.memory_barrier()

    def read(self) -> np.ndarray:
        return np.frombuffer(self.particles.read(), dtype=np.float32).reshape(self.count, 2, 4).copy()

    def release(self) -> None:
        for obj in (self.particles, self.params, self.program):
            obj.release()
