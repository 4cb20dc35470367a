"""What a renderer holds in GPU memory: the bytes of its buffers and textures, by kind.

The figures are what was asked of the API (a buffer's size; a texture's extent x its format's bytes a texel x its
levels and layers), the same way in OpenGL and WebGPU, so the two backends report the same scene alike. They are not
the driver's own accounting: a driver may round sizes up, compress a texture or keep an orphaned buffer's old storage
until the GPU is done with it. The window's own images (the default framebuffer, the swap chain) belong to the system
and are not counted.

:meth:`gandalf_core.render.base.Renderer.gpu_memory` sums these by kind; the benchmarks write it into their JSON.
"""

from __future__ import annotations

from typing import Any

#: Bytes a texel of each WebGPU texture format the engine and its steps use.
TEXEL_BYTES = {
    "r8unorm": 1, "rg8unorm": 2, "rgba8unorm": 4, "rgba8unorm-srgb": 4, "bgra8unorm": 4, "bgra8unorm-srgb": 4,
    "r16float": 2, "rg16float": 4, "rgba16float": 8, "r32float": 4, "rg32float": 8, "rgba32float": 16,
    "r32uint": 4, "rgba32uint": 16, "depth16unorm": 2, "depth24plus": 4, "depth24plus-stencil8": 4,
    "depth32float": 4,
}

#: Bytes a component of a moderngl texture's dtype.
_DTYPE_BYTES = {"f1": 1, "u1": 1, "i1": 1, "f2": 2, "u2": 2, "i2": 2, "f4": 4, "u4": 4, "i4": 4}

MIB = 1024 * 1024


def chain_bytes(width: int, height: int, texel: int, levels: int = 1, layers: int = 1) -> int:
    """Bytes of ``levels`` mip levels of a ``width`` x ``height`` image with ``layers`` layers (each level half the
    one above, rounded down, at least 1)."""
    total = 0
    for level in range(max(1, int(levels))):
        total += max(1, int(width) >> level) * max(1, int(height) >> level)
    return total * int(texel) * int(layers)


def wgpu_texture_bytes(texture: Any) -> int:
    """Bytes of a ``wgpu`` texture: its size (width, height, layers), format, levels and samples."""
    width, height, layers = texture.size
    fmt = str(texture.format)
    if fmt not in TEXEL_BYTES:
        raise ValueError(f"gpu_memory: no texel size known for texture format '{fmt}' (texture '{texture.label}')")
    return chain_bytes(width, height, TEXEL_BYTES[fmt], texture.mip_level_count, layers) * int(texture.sample_count)


def gl_texture_bytes(texture: Any) -> int:
    """Bytes of a moderngl 2D texture of one level (a render target, a shadow map). A depth texture counts 4 bytes
    a texel (32-bit float, or 24-bit depth in a 32-bit word). The texture library counts its textures from their
    data instead: moderngl's cube maps do not say their size or levels."""
    if getattr(texture, "depth", False) is True:
        texel = 4
    else:
        texel = int(texture.components) * _DTYPE_BYTES[str(texture.dtype)]
    return chain_bytes(texture.width, texture.height, texel)


def buffer_size(buffer: Any) -> int:
    """Bytes of a moderngl or wgpu buffer (both have ``size``); 0 for none."""
    return 0 if buffer is None else int(buffer.size)


def in_mib(report: dict[str, int]) -> dict[str, float]:
    """A :meth:`~gandalf_core.render.base.Renderer.gpu_memory` report in MiB, rounded to 0.001."""
    return {kind: round(n / MIB, 3) for kind, n in report.items()}


__all__ = ["MIB", "TEXEL_BYTES", "buffer_size", "chain_bytes", "gl_texture_bytes", "in_mib", "wgpu_texture_bytes"]
