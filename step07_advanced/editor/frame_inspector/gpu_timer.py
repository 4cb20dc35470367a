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
twice adds up. Each API's timer is in :mod:`.gpu_timer_gl` and :mod:`.gpu_timer_wgpu`;
:func:`~.capture.gpu_timer` makes the one of a renderer. A typical use (what the frame capture does; a benchmark
can do the same)::

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
