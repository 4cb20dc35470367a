"""Rendering: backend-neutral pieces here; ``render.opengl`` and ``render.webgpu`` import their GPU library."""

from __future__ import annotations

from typing import Any

from .base import BACKENDS, Renderer, UnknownBackendError, check_backend
from .render_system import RenderSystem


def create_renderer(backend: str, width: int, height: int, window: Any = None) -> Renderer:
    """Create the renderer of ``backend`` ('opengl' or 'webgpu'), importing its GPU library only now."""
    backend = check_backend(backend)
    if backend == "opengl":
        from .opengl import OpenGLRenderer

        return OpenGLRenderer(width, height, window)
    from .webgpu import WebGPURenderer

    return WebGPURenderer(width, height, window)


__all__ = ["BACKENDS", "RenderSystem", "Renderer", "UnknownBackendError", "check_backend", "create_renderer"]
