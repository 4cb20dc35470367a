"""GPU time per pass and per draw, in both APIs: a :class:`GpuTimer` writes a GPU timestamp where a labelled span
begins and ends, and :meth:`GpuTimer.results` gives each label's milliseconds once the GPU has run the work.

* OpenGL: ``glQueryCounter(GL_TIMESTAMP)`` queries (OpenGL 3.3 core, ARB_timer_query). Timestamps, not
  ``GL_TIME_ELAPSED`` queries (moderngl's ``ctx.query(time=True)``), because elapsed-time queries cannot nest and a
  pass holds draws: a timer of every pass and every draw needs both at once. A test can still time the whole frame
  with an elapsed-time query around the timestamps (another query target), as an independent check.
* WebGPU: timestamps written into the command stream (``write_timestamp`` on the encoder and inside passes), which
  needs the device to have been requested with the engine's
  :data:`~gandalf_core.render.gpu_timing.TIMESTAMP_FEATURES` (``GANDALF_GPU_TIMING=1``, see
  :mod:`gandalf_core.render.gpu_timing`); without them :attr:`GpuTimer.available` is False and
  :attr:`GpuTimer.reason` says why.

Costs nothing unless a timer is made: no query object exists before. The labels are the caller's; a label used
twice adds up. A typical use (what the frame capture does; a benchmark can do the same)::

    timer = gpu_timer(renderer)
    timer.begin("opaque", where)   # where: the WebGPU encoder or pass encoder the draws go into (ignored by GL)
    ...                            # the draws
    timer.end(where)
    timer.resolve(encoder)         # WebGPU: before the encoder is finished; GL: nothing
    ms = timer.results()           # {"opaque": 0.42}, after the frame was submitted

On a software rasteriser (llvmpipe, lavapipe) the timestamps are real but mark when the work was recorded and
rasterised by the CPU's threads, so a per-draw split is coarse; on a GPU they time the GPU's work.
"""

from __future__ import annotations

from typing import Any

from gandalf_core.render.gpu_timing import TIMESTAMP_FEATURES, TIMING_VARIABLE

#: WebGPU's largest query set: at most this many timestamps (half as many spans) per timed frame.
MAX_TIMESTAMPS = 4096


class GpuTimer:
    """Labelled GPU spans; see the module's docstring. Subclasses write the timestamps."""

    #: Whether this device can time anything; when False, :attr:`reason` says why and every call does nothing.
    available = False
    reason = ""

    def __init__(self) -> None:
        self._open: list[tuple[str, int]] = []  # (label, index of its start timestamp)
        self._spans: list[tuple[str, int, int]] = []  # (label, start, end)
        self._count = 0

    def begin(self, label: str, where: Any = None) -> None:
        """Start the span ``label``: a timestamp before the commands that follow (in ``where``, for WebGPU)."""
        if self.available:
            index = self._stamp(where)
            if index is not None:
                self._open.append((label, index))

    def end(self, where: Any = None) -> None:
        """End the innermost open span."""
        if self.available and self._open:
            label, start = self._open.pop()
            index = self._stamp(where)
            if index is not None:
                self._spans.append((label, start, index))

    def stamp(self, where: Any = None) -> int | None:
        """Write one timestamp now (in ``where``, for WebGPU) and return its index (None when unavailable)."""
        return self._stamp(where) if self.available else None

    def reserve(self, count: int = 2) -> list[int] | None:
        """Indices of ``count`` timestamps that something else writes (a WebGPU pass's ``timestamp_writes``)."""
        if not self.available or self._count + count > MAX_TIMESTAMPS:
            return None
        first, self._count = self._count, self._count + count
        return list(range(first, first + count))

    def span(self, label: str, start: int | None, end: int | None) -> None:
        """Count the time between timestamps ``start`` and ``end`` under ``label``."""
        if start is not None and end is not None:
            self._spans.append((label, start, end))

    def labels(self) -> list[str]:
        """The labels of the finished spans, in the order they ended."""
        return [label for label, _s, _e in self._spans]

    def resolve(self, encoder: Any = None) -> None:
        """WebGPU: copy the timestamps into a readable buffer (record it before the encoder is finished)."""

    def results(self) -> dict[str, float]:
        """Milliseconds per label (a label used twice adds up); waits for the GPU. Empty when unavailable."""
        if not self.available or not self._spans:
            return {}
        stamps = self._read(self._count)
        out: dict[str, float] = {}
        for label, start, end in self._spans:
            out[label] = out.get(label, 0.0) + max(0, int(stamps[end]) - int(stamps[start])) / 1e6
        return out

    def reset(self) -> None:
        """Forget the spans (the query objects are kept for the next frame)."""
        self._open, self._spans, self._count = [], [], 0

    def release(self) -> None:
        """Free the query objects."""

    # --- per API ---------------------------------------------------------------------------------
    def _stamp(self, where: Any) -> int | None:
        raise NotImplementedError

    def _read(self, count: int) -> list[int]:
        raise NotImplementedError


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


class WGPUTimer(GpuTimer):
    """Timestamps written with wgpu-native's ``write_timestamp`` into one query set, resolved into a buffer."""

    def __init__(self, device: Any, adapter: Any = None) -> None:
        super().__init__()
        self.device = device
        missing = [f for f in TIMESTAMP_FEATURES if f not in device.features]
        if missing:
            offered = adapter is not None and set(TIMESTAMP_FEATURES) <= set(adapter.features)
            name = adapter.info.get("device", "this adapter") if adapter is not None else "this adapter"
            self.reason = (f"the WebGPU device lacks {', '.join(repr(f) for f in missing)}: "
                           + (f"{name} offers them; start with {TIMING_VARIABLE}=1 to request them" if offered
                              else f"{name} does not offer them (a browser never offers timestamps inside passes)"))
            return
        import wgpu
        from wgpu.backends.wgpu_native import extras

        self._write = extras.write_timestamp
        self._set = device.create_query_set(type="timestamp", count=MAX_TIMESTAMPS, label="gpu timer")
        self._buffer = device.create_buffer(size=MAX_TIMESTAMPS * 8,
                                            usage=wgpu.BufferUsage.QUERY_RESOLVE | wgpu.BufferUsage.COPY_SRC)
        self.available = True
        self.reason = f"WebGPU timestamp queries on {adapter.info.get('device', '?') if adapter else 'this device'}"

    def _stamp(self, where: Any) -> int | None:
        if where is None or self._count >= MAX_TIMESTAMPS:
            return None
        index = self._count
        self._write(where, self._set, index)
        self._count += 1
        return index

    def resolve(self, encoder: Any = None) -> None:
        if self.available and self._count and encoder is not None:
            encoder.resolve_query_set(self._set, 0, self._count, self._buffer, 0)

    def _read(self, count: int) -> list[int]:
        import numpy as np

        data = self.device.queue.read_buffer(self._buffer, 0, count * 8)
        return np.frombuffer(data, dtype=np.uint64).tolist()

    def release(self) -> None:
        if self.available:
            self._set.destroy()
            self._buffer.destroy()
            self.available = False


def gpu_timer(renderer: Any) -> GpuTimer:
    """A timer for ``renderer``'s context or device (check :attr:`GpuTimer.available`)."""
    if renderer.backend == "opengl":
        return GLTimer(renderer.ctx)
    return WGPUTimer(renderer.device, getattr(renderer, "adapter", None))
