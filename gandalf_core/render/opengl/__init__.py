"""The OpenGL (moderngl) backend."""

from .renderer import OpenGLRenderer

__all__ = ["OpenGLRenderer"]
