"""The GPU timer on OpenGL: ``glQueryCounter(GL_TIMESTAMP)`` queries (see :mod:`.gpu_timer`)."""

from __future__ import annotations

from typing import Any

from .gpu_timer import GpuTimer


class GLTimer(GpuTimer):
    """``glQueryCounter(GL_TIMESTAMP)`` queries on a moderngl context (made current before each call)."""

    _GL_TIMESTAMP = 0x8E28
    _GL_QUERY_RESULT = 0x8866
    _GL_QUERY_COUNTER_BITS = 0x8864

    def __init__(self, ctx: Any) -> None:
        super().__init__()
        import ctypes

        from gandalf_core.render.opengl import raw_gl
        from gandalf_core.render.opengl.libs import make_current

        self.ctx, self._ctypes, self._make_current = ctx, ctypes, make_current
        self._ids: list[int] = []
        uint_p = ctypes.POINTER(ctypes.c_uint)
        try:
            self._gen = raw_gl.gl_function("glGenQueries", (ctypes.c_int, uint_p))
            self._delete = raw_gl.gl_function("glDeleteQueries", (ctypes.c_int, uint_p))
            self._counter = raw_gl.gl_function("glQueryCounter", (ctypes.c_uint, ctypes.c_uint))
            self._result = raw_gl.gl_function("glGetQueryObjectui64v", (ctypes.c_uint, ctypes.c_uint,
                                                                          ctypes.POINTER(ctypes.c_uint64)))
            query_iv = raw_gl.gl_function("glGetQueryiv", (ctypes.c_uint, ctypes.c_uint,
                                                             ctypes.POINTER(ctypes.c_int)))
        except RuntimeError:
            self.reason = "this OpenGL library exports no timer queries (glQueryCounter)"
            return
        make_current(ctx)
        bits = ctypes.c_int()
        query_iv(self._GL_TIMESTAMP, self._GL_QUERY_COUNTER_BITS, ctypes.byref(bits))
        if bits.value <= 0:
            self.reason = f"{ctx.info.get('GL_RENDERER', 'this driver')} has no GL_TIMESTAMP counter"
            return
        self.available = True
        self.reason = f"GL_TIMESTAMP queries ({bits.value} bits) on {ctx.info.get('GL_RENDERER', '?')}"

    def _stamp(self, where: Any) -> int | None:
        index = self._count
        if index >= len(self._ids):
            grow = max(64, len(self._ids))
            ids = (self._ctypes.c_uint * grow)()
            self._make_current(self.ctx)
            self._gen(grow, ids)
            self._ids.extend(ids)
        self._counter(self._ids[index], self._GL_TIMESTAMP)
        self._count += 1
        return index

    def _read(self, count: int) -> list[int]:
        self._make_current(self.ctx)
        value = self._ctypes.c_uint64()
        out = []
        for query in self._ids[:count]:
            self._result(query, self._GL_QUERY_RESULT, self._ctypes.byref(value))
            out.append(value.value)
        return out

    def release(self) -> None:
        if self._ids:
            self._make_current(self.ctx)
            self._delete(len(self._ids), (self._ctypes.c_uint * len(self._ids))(*self._ids))
            self._ids = []
