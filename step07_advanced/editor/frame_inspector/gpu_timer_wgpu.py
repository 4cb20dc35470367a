"""The GPU timer on WebGPU: timestamps written into the command stream (see :mod:`.gpu_timer`); the device needs
the engine's :data:`~gandalf_core.render.gpu_timing.TIMESTAMP_FEATURES`."""

from __future__ import annotations

from typing import Any

from gandalf_core.render.gpu_timing import TIMESTAMP_FEATURES, TIMING_VARIABLE

from .gpu_timer import MAX_TIMESTAMPS, GpuTimer


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
