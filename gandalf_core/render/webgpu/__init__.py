"""The WebGPU (wgpu-py) backend."""

from .renderer import WebGPURenderer

__all__ = ["WebGPURenderer"]
