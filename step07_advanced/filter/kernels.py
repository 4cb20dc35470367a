"""What both GPU filters share: the operations, the work-group shapes, the radius limit and the input checks.

The tiled blur keeps a tile of ``TILE`` pixels along the pass direction plus an apron of ``radius`` pixels on each
side, for ``ROWS`` lines, in workgroup memory as vec4<f32> (16 bytes). The array is sized for the largest
radius at compile time: ``(TILE + 2 · MAX_RADIUS) · ROWS · 16`` bytes = 8 KiB, half of WebGPU's default
``maxComputeWorkgroupStorageSize`` (16 KiB; OpenGL 4.3 guarantees 32 KiB of GL_MAX_COMPUTE_SHARED_MEMORY_SIZE).
"""

from __future__ import annotations

import numpy as np

#: The filters a GPU filter object runs (:meth:`run`'s ``op``): the separable blur (two passes of the student's
#: ``blur_pass``), the naive 2-D blur, the tiled separable blur, Sobel edges, and single passes of ``blur_pass``.
OPERATIONS = ("separable", "naive", "tiled", "sobel", "horizontal", "vertical")
#: The blurs among them.
BLURS = ("separable", "naive", "tiled", "horizontal", "vertical")
#: Work-group shape of the per-pixel kernels (blur pass, naive 2-D, Sobel).
GROUP = (16, 16)
#: The tiled kernel: pixels per tile along the pass direction and lines per work group.
TILE, ROWS = 64, 4
#: The largest supported kernel radius (the weight table holds 2 · MAX_RADIUS + 1 floats).
MAX_RADIUS = 32
#: Bytes of one texel in workgroup memory (vec4 of f32).
TEXEL_BYTES = 16


def shared_bytes(max_radius: int = MAX_RADIUS) -> int:
    """Workgroup memory of the tiled kernel: (TILE + 2·max_radius) · ROWS texels of 16 bytes."""
    return (TILE + 2 * max_radius) * ROWS * TEXEL_BYTES


def largest_radius_for(limit_bytes: int) -> int:
    """The largest radius whose tile + apron fits ``limit_bytes`` of workgroup memory (96 for 16 KiB)."""
    return (limit_bytes // (ROWS * TEXEL_BYTES) - TILE) // 2


def check_shared_memory(limit_bytes: int, limit_name: str) -> None:
    """Raise when the device's workgroup memory cannot hold the tiled kernel's tile for MAX_RADIUS."""
    need = shared_bytes()
    if limit_bytes < need:
        raise RuntimeError(
            f"the tiled blur needs {need} bytes of workgroup memory ((TILE {TILE} + 2 * MAX_RADIUS {MAX_RADIUS}) "
            f"* ROWS {ROWS} * {TEXEL_BYTES} B), but {limit_name} is {limit_bytes}")


def check_radius(radius: object) -> int:
    """``radius`` as an int in 0..MAX_RADIUS, or a ValueError naming the limit."""
    if isinstance(radius, bool) or not isinstance(radius, (int, np.integer)):
        raise ValueError(f"radius must be an int, got {radius!r}")
    r = int(radius)
    if r < 0 or r > MAX_RADIUS:
        raise ValueError(
            f"radius {r} is outside 0..{MAX_RADIUS} (MAX_RADIUS: the weight table holds 2 * {MAX_RADIUS} + 1 taps "
            f"and the tiled kernel's tile + apron, {shared_bytes()} bytes, is sized for it)")
    return r


def check_op(op: str) -> str:
    if op not in OPERATIONS:
        raise ValueError(f"op {op!r} is not one of {', '.join(OPERATIONS)}")
    return op


def check_weights(weights: object, radius: int) -> np.ndarray:
    """A weight table given by the caller (instead of the GPU's ``gaussian_weight``): float32, 2·radius + 1."""
    w = np.asarray(weights, dtype=np.float64)
    if w.shape != (2 * radius + 1,) or not np.all(np.isfinite(w)):
        raise ValueError(f"weights must be {2 * radius + 1} finite floats for radius {radius}, got shape {w.shape}")
    return w.astype(np.float32)


def check_image(image: object, max_size: int, limit_name: str) -> np.ndarray:
    """An (H, W, 4) uint8 RGBA image no larger than ``max_size`` per side, C-contiguous; else a clear error."""
    if not isinstance(image, np.ndarray):
        raise TypeError(f"image must be a numpy array of shape (H, W, 4) uint8 (RGBA8), got {type(image).__name__}")
    if image.dtype != np.uint8 or image.ndim != 3 or image.shape[2] != 4:
        raise ValueError(f"image must be RGBA8: a uint8 array of shape (H, W, 4), got {image.dtype} {image.shape} "
                         "(convert with TextureData.from_array(...).pixels)")
    h, w = image.shape[:2]
    if h < 1 or w < 1:
        raise ValueError(f"image is empty: shape {image.shape}")
    if max(h, w) > max_size:
        raise ValueError(f"image {w}x{h} is larger than the device's 2-D texture limit {limit_name} = {max_size}")
    return np.ascontiguousarray(image)


def groups(width: int, height: int, op: str, direction: tuple[int, int] = (1, 0)) -> tuple[int, int]:
    """Work groups to dispatch for an image: ceil-divided, so sizes that are no multiple of the group work too."""
    if op == "tiled":
        along, across = (width, height) if direction == (1, 0) else (height, width)
        return -(-along // TILE), -(-across // ROWS)
    return -(-width // GROUP[0]), -(-height // GROUP[1])
