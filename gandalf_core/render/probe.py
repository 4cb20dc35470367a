"""What this machine offers in each API, probed once per process: the newest headless OpenGL context the engine
gets, and the WebGPU adapter it picks (:func:`offer_here`). The doctor and the test skips ask here."""

from __future__ import annotations

import functools

from .capabilities import Offer, opengl_offer, webgpu_offer


@functools.cache
def offer_here(api: str) -> Offer:
    """What this machine offers in ``api`` ('opengl' or 'webgpu'); a machine without it offers an empty ``Offer``
    (OpenGL version 0, no adapter name)."""
    if api == "opengl":
        from .opengl.renderer import _standalone_context

        try:
            ctx = _standalone_context()
        except Exception:  # noqa: BLE001 - no EGL / no driver: nothing is offered
            return Offer("opengl", "no OpenGL context")
        try:
            return opengl_offer(ctx)
        finally:
            ctx.release()
    import wgpu

    from .webgpu.device import _quiet_runtime_dir

    _quiet_runtime_dir()
    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    return webgpu_offer(adapter) if adapter is not None else Offer("webgpu", "no adapter")
