"""Getting a wgpu adapter and device, offscreen or for a window surface."""

from __future__ import annotations

import os
import tempfile
from typing import Any

import wgpu

from ..capabilities import FLOOR, Needs, check, webgpu_offer
from ..gpu_timing import timing_features
from .type_parsing import parse_only_mentioned_typedefs


def _quiet_runtime_dir() -> None:
    # lavapipe warns when XDG_RUNTIME_DIR is unset; a private mode-700 folder silences it.
    if "XDG_RUNTIME_DIR" not in os.environ:
        path = os.path.join(tempfile.gettempdir(), f"gandalf-xdg-{os.getuid()}")
        os.makedirs(path, mode=0o700, exist_ok=True)
        os.environ["XDG_RUNTIME_DIR"] = path


def depth_through_gl_range(adapter: Any) -> bool:
    """True when the adapter stores depth through OpenGL's clip range: wgpu's OpenGL backend turns WebGPU's clip
    depth z in [0, w] into OpenGL's 2z - w in every vertex shader, and the viewport maps it back to [0, 1].
    The sum (2z/w - 1) + 1 rounds away the bits a float32 has below 1, so a stored depth near 0 is only as
    precise as one near 1: reverse-Z gains nothing there."""
    return adapter.info.get("backend_type") == "OpenGL"


#: Optional WebGPU features the renderer uses where the adapter offers them (and explains the lack of where not).
ENGINE_FEATURES = ("indirect-first-instance",)


def request_device(canvas_context: Any = None, needs: Needs = FLOOR) -> tuple[Any, Any]:
    """Return ``(adapter, device)``; with a canvas context the adapter must be able to present to it.

    The device has WebGPU's default limits and, of the optional features, the engine's own where the adapter offers
    them (:data:`ENGINE_FEATURES`) plus what ``needs`` states (a
    :class:`~gandalf_core.render.capabilities.CapabilityError` when the adapter lacks it): what runs here then
    runs on every implementation that offers the same."""
    _quiet_runtime_dir()
    parse_only_mentioned_typedefs()
    if canvas_context is not None:
        adapter = wgpu.gpu.request_adapter_sync(canvas=canvas_context, power_preference="high-performance")
    else:
        adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    if adapter is None:
        raise RuntimeError(
            "no WebGPU adapter found: install a Vulkan driver (on Debian: mesa-vulkan-drivers libvulkan1)"
        )
    check(needs, webgpu_offer(adapter))
    # GPU timing (gpu_timing.py) only when asked for: a device without it behaves as a browser's would. The engine's
    # vertex shaders read their instance rows by instance index, so an indirect draw of a batch that does not start
    # at row 0 needs 'indirect-first-instance' (ENGINE_FEATURES): asked for where offered; where not, such a draw is
    # refused with an error that says so (WebGPURenderer._draw_batch).
    engine = [f for f in ENGINE_FEATURES if f in adapter.features]
    features = list(dict.fromkeys([*needs.features, *engine, *timing_features(adapter.features)]))
    return adapter, adapter.request_device_sync(required_features=features,
                                                required_limits=needs.device_limits(adapter.limits))
