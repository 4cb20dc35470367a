"""The path tracing kernel on OpenGL: a GLSL 4.30 compute shader on the renderer's moderngl context.

The scene's arrays go to shader storage buffers (bindings 0-4), the per-dispatch values to a std140 uniform
block (binding 4: 0 and 1 are the engine's Frame and Lights), and the accumulation buffer (binding 5) is the
renderer's own ``renderer.buffers`` entry that the display material reads. ``ctx.memory_barrier()`` after each
dispatch makes the kernel's writes visible to the draw that follows (and to the next dispatch).
"""

from __future__ import annotations

from types import ModuleType

import moderngl
import numpy as np

from gandalf_core.render.capabilities import require_opengl, standalone_opengl

from .scene import PackedScene
from .shaders import PARAMS_BINDING, PARAMS_LAYOUT, explain_error, kernel_source

#: Compute shaders arrived in OpenGL 4.3.
REQUIRED_VERSION = 430
GROUP = 8


class GLPathTracer:
    """One sample per pixel per :meth:`dispatch` into ``accum`` (``width`` × ``height`` vec4, rgb sum + count)."""

    backend = "opengl"

    def __init__(self, ctx: moderngl.Context, impl: ModuleType, accum: moderngl.Buffer, width: int,
                 height: int) -> None:
        require_opengl(ctx, REQUIRED_VERSION, "compute shaders", "the path tracer")
        if accum.size < width * height * 16:
            raise ValueError(f"the accumulation buffer holds {accum.size} bytes; {width}x{height} pixels need "
                             f"{width * height * 16}")
        src = kernel_source("opengl", impl)
        try:
            self.program = ctx.compute_shader(src.text)
        except moderngl.Error as exc:
            raise RuntimeError(explain_error(src, str(exc))) from None
        self.ctx, self.accum, self.width, self.height = ctx, accum, int(width), int(height)
        self.params = ctx.buffer(reserve=PARAMS_LAYOUT.size)
        self.buffers: list[moderngl.Buffer] = []
        self.packed: PackedScene | None = None
        self.owns_context = False

    @classmethod
    def standalone(cls, impl: ModuleType, width: int, height: int) -> GLPathTracer:
        """A kernel on its own headless GL 4.3 context with its own accumulation buffer (the study: NVIDIA's EGL
        gives exactly the 3.3 the renderer asks for, so the renderer's context may have no compute shaders)."""
        ctx = standalone_opengl(REQUIRED_VERSION, "compute shaders", "the path tracer")
        accum = ctx.buffer(reserve=width * height * 16)
        accum.clear()
        tracer = cls(ctx, impl, accum, width, height)
        tracer.owns_context = True
        return tracer

    @property
    def device_name(self) -> str:
        return str(self.ctx.info.get("GL_RENDERER", "?"))

    def load(self, packed: PackedScene) -> None:
        """Upload the scene's arrays (replacing the previous scene's)."""
        for buf in self.buffers:
            buf.release()
        self.buffers = [self.ctx.buffer(np.ascontiguousarray(a, np.float32).tobytes())
                        for a in (packed.spheres, packed.materials, packed.triangles, packed.nodes, packed.sky)]
        self.packed = packed

    def clear(self) -> None:
        """Zero the accumulation (a new picture starts)."""
        self.accum.clear()

    # --8<-- [start:dispatch]
    def dispatch(self, sample_index: int, seed: int | None = None) -> None:
        """Add sample ``sample_index`` of every pixel to the accumulation."""
        if self.packed is None:
            raise RuntimeError("load a scene before dispatching the path tracer")
        self.params.write(self.packed.params(sample_index, self.width, self.height, seed))
        self.params.bind_to_uniform_block(PARAMS_BINDING)
        for binding, buf in enumerate(self.buffers):
            buf.bind_to_storage_buffer(binding)
        self.accum.bind_to_storage_buffer(5)
        self.program.run(group_x=-(-self.width // GROUP), group_y=-(-self.height // GROUP))
        self.ctx.memory_barrier()  # the display (or the next sample) reads what this one wrote
    # --8<-- [end:dispatch]

    def finish(self) -> None:
        """Wait until the GPU has done everything dispatched so far."""
        self.ctx.finish()

    def read(self) -> np.ndarray:
        """The accumulation, (height, width, 4) float32, top row first (rgb: sums, a: sample count)."""
        data = self.accum.read(size=self.width * self.height * 16)
        return np.frombuffer(data, np.float32).reshape(self.height, self.width, 4).copy()

    def release(self) -> None:
        for obj in (*self.buffers, self.params, self.program):
            obj.release()
        self.buffers = []
        if self.owns_context:
            self.accum.release()
            self.ctx.release()
            self.owns_context = False
