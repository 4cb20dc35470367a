"""What a storage buffer is built from, checked the same way for both backends' buffer libraries."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..resources import ResourceError


def buffer_bytes(name: str, data: Any) -> tuple[bytes | None, int]:
    """``(content, size)`` for ``renderer.buffers.build(name, data)``: the bytes of a numpy array, or ``None``
    and a size for an int (a zero-filled buffer). Sizes must be positive multiples of 4 bytes (both APIs'
    storage bindings address 4-byte words)."""
    label = f"buffer '{name}'"
    if isinstance(data, (int, np.integer)) and not isinstance(data, bool):
        content, size = None, int(data)
    elif isinstance(data, np.ndarray):
        if data.dtype.kind not in "iuf" or data.dtype.itemsize != 4:
            raise ResourceError(label, "data", f"expected 32-bit numbers (float32, int32, uint32), got {data.dtype}")
        content = np.ascontiguousarray(data).tobytes()
        size = len(content)
    else:
        raise ResourceError(label, "data", f"expected a numpy array or a size in bytes, got {type(data).__name__}")
    if size <= 0 or size % 4:
        raise ResourceError(label, "size", f"{size} bytes: a storage buffer needs a positive multiple of 4 bytes")
    return content, size
