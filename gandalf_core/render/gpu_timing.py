"""Which WebGPU device features GPU timing needs, and whether it is asked for: what the engine's device request
reads. The timer itself (timestamps per pass and per draw, in both APIs) belongs to the editor's frame inspector
(:mod:`step07_advanced.editor.frame_inspector.gpu_timer`), the one that times frames.

WebGPU timestamps written into the command stream (``write_timestamp`` on the encoder and inside passes) need the
device to have been requested with the features in :data:`TIMESTAMP_FEATURES`: native wgpu offers them on Vulkan,
Metal and DX12 (lavapipe and NVIDIA's driver included), a browser does not. A device is requested with them only
when timing is asked for (``GANDALF_GPU_TIMING=1``); a device without them behaves as a browser's would. OpenGL's
timer queries need nothing asked for in advance.
"""

from __future__ import annotations

import os
from typing import Any

#: The WebGPU features a timer of passes and draws needs (timestamps anywhere in the command stream).
TIMESTAMP_FEATURES = ("timestamp-query", "timestamp-query-inside-encoders", "timestamp-query-inside-passes")
#: Set to 1 to have WebGPU devices requested with :data:`TIMESTAMP_FEATURES` when the adapter has them.
TIMING_VARIABLE = "GANDALF_GPU_TIMING"


def timing_requested() -> bool:
    """Whether ``GANDALF_GPU_TIMING=1`` asks for GPU timing (WebGPU devices then get the timestamp features)."""
    return os.environ.get(TIMING_VARIABLE, "").strip() not in ("", "0")


def timing_features(adapter_features: Any) -> tuple[str, ...]:
    """The timestamp features to add to a device request: all of :data:`TIMESTAMP_FEATURES` when timing is asked
    for and the adapter has them, else none."""
    have = set(adapter_features)
    return TIMESTAMP_FEATURES if timing_requested() and have.issuperset(TIMESTAMP_FEATURES) else ()
