"""The GPU-driven motion pass on OpenGL: a compute shader (GLSL 4.30) reads the frame's instance buffer and the
motion rows as shader storage buffers and writes the moved rows into a buffer the draws then read their instance rows
from (a GL buffer is only bytes: the same object is a storage buffer here and a buffer texture's store there)."""

from __future__ import annotations

from typing import Any

import moderngl

from gandalf_core.render.capabilities import require_opengl
from gandalf_core.render.gpu_memory import buffer_size
from gandalf_core.render.shader_files import load_shader
from step07_advanced.editor.frame_inspector.capture import compute_recorded

from .motion import KERNEL, PARAMS_BINDING, PARAMS_INCLUDES, PARAMS_LAYOUT, SHADER_DIR, WORKGROUP, MotionFrame

GL_TEXTURE_FETCH_BARRIER_BIT, GL_SHADER_STORAGE_BARRIER_BIT = 0x00000008, 0x00002000


class GLMotionPass:
    """Built on the first frame that has GPU-driven motion: the kernel, the motion rows and the output buffer."""

    def __init__(self, ctx: moderngl.Context, stats: Any) -> None:
        require_opengl(ctx, 430, "compute shaders", "GPU-driven motion")
        self.ctx = ctx
        self.stats = stats
        self.program = ctx.compute_shader(load_shader(SHADER_DIR / f"{KERNEL}.comp", "compute", "glsl",
                                                           generated=PARAMS_INCLUDES).text)
        self.params = ctx.buffer(reserve=PARAMS_LAYOUT.size)
        self.motion: moderngl.Buffer | None = None
        self.moved: moderngl.Buffer | None = None
        self.version: tuple[object, int] | None = None

    def run(self, instances: moderngl.Buffer, count: int, frame: MotionFrame) -> moderngl.Buffer:
        """Move ``count`` instance rows of ``instances``; the buffer the draws read them from."""
        groups = -(-count // WORKGROUP)
        limit = int(self.ctx.info["GL_MAX_COMPUTE_WORK_GROUP_COUNT"][0])
        if groups > limit:
            raise ValueError(f"GPU-driven motion: {count} instances need {groups} workgroups of {WORKGROUP}, more than "
                             f"this context dispatches at once ({limit}); move fewer entities on the GPU")
        rows = frame.rows
        if self.version != frame.version or self.motion is None or self.motion.size < rows.nbytes:
            if self.motion is None or self.motion.size < rows.nbytes:
                if self.motion is not None:
                    self.motion.release()
                self.motion = self.ctx.buffer(reserve=max(rows.nbytes, 16))
                self.stats["buffers_created"] += 1
            self.motion.write(rows)
            self.version = frame.version
        if self.moved is None or self.moved.size < instances.size:
            if self.moved is not None:
                self.moved.release()
            self.moved = self.ctx.buffer(reserve=instances.size)
            self.stats["buffers_created"] += 1
        instances.bind_to_storage_buffer(0)
        self.motion.bind_to_storage_buffer(1)
        self.moved.bind_to_storage_buffer(2)
        self.params.write(PARAMS_LAYOUT.pack({"time": frame.time, "count": count}))
        self.params.bind_to_uniform_block(PARAMS_BINDING)
        with compute_recorded(self.ctx, "motion", (groups,), shader=f"{KERNEL}.comp",
                              buffers=[("instances", instances.size), ("motion", self.motion.size),
                                       ("moved", self.moved.size)]):  # listed and timed in a frame capture
            self.program.run(group_x=groups)
        # The draws read what the kernel wrote, through the instance rows' buffer texture (texelFetch) or as a
        # storage buffer: only those two caches need the barrier, not every one (GL_ALL_BARRIER_BITS).
        self.ctx.memory_barrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT)
        self.stats["motion_passes"] += 1
        return self.moved

    def gpu_bytes(self) -> int:
        """Bytes of its buffers (the renderer's ``gpu_memory()`` reports them under the kernel's name)."""
        return sum(buffer_size(b) for b in (self.motion, self.moved, self.params))

    def release(self) -> None:
        for obj in (self.motion, self.moved, self.params, self.program):
            if obj is not None:
                obj.release()
