"""Rendering: backend-neutral pieces here; ``render.opengl`` and ``render.webgpu`` import their GPU library."""

from __future__ import annotations

from typing import Any

from .base import BACKENDS, Renderer, UnknownBackendError, check_backend
from .capabilities import FLOOR, CapabilityError, Needs
from .render_system import RenderSystem


def create_renderer(backend: str, width: int, height: int, window: Any = None, needs: Needs = FLOOR) -> Renderer:
    """Create the renderer of ``backend`` ('opengl' or 'webgpu'), importing its GPU library only now; a
    :class:`~.capabilities.CapabilityError` when the context or adapter lacks what ``needs`` states."""
    backend = check_backend(backend)
    if backend == "opengl":
        from .opengl import OpenGLRenderer

        return OpenGLRenderer(width, height, window, needs)
    from .webgpu import WebGPURenderer

    return WebGPURenderer(width, height, window, needs)


__all__ = ["BACKENDS", "CapabilityError", "Needs", "RenderSystem", "Renderer", "UnknownBackendError", "check_backend",
           "create_renderer"]
