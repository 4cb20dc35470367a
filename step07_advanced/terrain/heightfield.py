"""The terrain's heightfield, backend-neutral: a fractal value-noise heightmap in numpy (float64), its 16-bit
encoding into an RGBA8 texture, and float64 twins of the exercise functions (``tess_level``,
``terrain_height``, ``terrain_normal``) that the tests and the study grade against.

Encoding: a height h in [0, 1] is stored as the 16-bit integer q = round(h · 65535), its high byte in red and its
low byte in green (blue 0, alpha 255), and decoded in the shaders as (256 · R + G) / 65535 with R, G the bytes.
8 bits alone would give visible terraces (3.2 world units / 255 ≈ 1.25 cm steps lit like cliffs); 16 bits are
smooth. The shaders read texels with ``texelFetch`` / ``textureLoad`` and interpolate themselves (the exercise),
so no filtering hardware touches the split bytes.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from gandalf_core.resources import TextureData
from gandalf_core.resources.errors import ResourceError

HEIGHT_LEVELS = 65535


def fractal_heights(size: int = 256, octaves: int = 6, seed: int = 7, persistence: float = 0.5) -> np.ndarray:
    """A (size, size) float64 heightmap in [0, 1]: ``octaves`` of smooth value noise, each twice as fine and
    ``persistence`` times as strong as the last, from a fixed seed (deterministic), then a gentle valley shape."""
    if not isinstance(size, int) or size < 2:
        raise ValueError(f"fractal_heights: size must be an int >= 2, got {size!r}")
    if not isinstance(octaves, int) or not 1 <= octaves <= 12:
        raise ValueError(f"fractal_heights: octaves must be an int in [1, 12], got {octaves!r}")
    rng = np.random.default_rng(seed)
    x = (np.arange(size) + 0.5) / size
    total = np.zeros((size, size))
    amplitude, cells = 1.0, 3
    for _ in range(octaves):
        lattice = rng.random((cells + 1, cells + 1))
        t = x * cells
        i = np.minimum(t.astype(np.int64), cells - 1)
        f = t - i
        f = f * f * (3.0 - 2.0 * f)  # smoothstep: no creases at the lattice lines
        rows = lattice[i][:, i] * (1 - f)[None, :] + lattice[i][:, i + 1] * f[None, :]
        rows_next = lattice[i + 1][:, i] * (1 - f)[None, :] + lattice[i + 1][:, i + 1] * f[None, :]
        total += amplitude * (rows * (1 - f)[:, None] + rows_next * f[:, None])
        amplitude *= persistence
        cells *= 2
    total = (total - total.min()) / (total.max() - total.min())
    # Lower the middle a little and raise the far side: a valley to look across, mountains behind it.
    v = x[:, None]
    u = x[None, :]
    shaped = total * (0.55 + 0.45 * (1.0 - v)) + 0.25 * (1.0 - v) ** 2 - 0.12 * np.exp(-((u - 0.5) / 0.2) ** 2)
    return (shaped - shaped.min()) / (shaped.max() - shaped.min())


def check_heights(heights: Any, name: str = "heights") -> np.ndarray:
    """Validate a heightmap: a square 2-D float array (at least 2×2) of finite values in [0, 1]. Returns it as
    float64; raises :class:`ResourceError` naming ``name`` otherwise."""
    label = f"heightmap '{name}'"
    if not isinstance(heights, np.ndarray):
        raise ResourceError(label, "heights", f"expected a numpy array, got {type(heights).__name__}")
    if heights.dtype.kind != "f":
        raise ResourceError(label, "heights", f"expected a float array of heights in [0, 1], got dtype {heights.dtype}")
    if heights.ndim != 2:
        raise ResourceError(label, "heights", f"expected a 2-D (N, N) array, got shape {heights.shape}")
    if heights.shape[0] != heights.shape[1] or heights.shape[0] < 2:
        detail = f"expected a square map of at least 2×2 texels, got shape {heights.shape}"
        raise ResourceError(label, "heights", detail)
    finite = np.isfinite(heights)
    if not finite.all():
        row, col = (int(i) for i in np.argwhere(~finite)[0])
        raise ResourceError(label, "heights", f"heights[{row}, {col}] = {heights[row, col]} is not finite")
    lo, hi = float(heights.min()), float(heights.max())
    if lo < 0.0 or hi > 1.0:
        raise ResourceError(label, "heights", f"values must lie in [0, 1], found [{lo:g}, {hi:g}]")
    return heights.astype(np.float64)


def quantize(heights: np.ndarray) -> np.ndarray:
    """The heights the GPU sees after the 16-bit encoding (float64)."""
    return np.rint(check_heights(heights) * HEIGHT_LEVELS) / HEIGHT_LEVELS


def encode_heights(heights: np.ndarray, name: str = "heightmap") -> TextureData:
    """The heightmap as an RGBA8 data texture (not sRGB, no mipmaps, nearest, clamped): R high byte, G low byte."""
    q = np.rint(check_heights(heights, name) * HEIGHT_LEVELS).astype(np.uint32)
    rgba = np.zeros(q.shape + (4,), dtype=np.uint8)
    rgba[..., 0] = q >> 8
    rgba[..., 1] = q & 0xFF
    rgba[..., 3] = 255
    return TextureData(rgba, srgb=False, wrap="clamp", filter="nearest", mipmaps=False, name=name)


# --- float64 twins of the exercise functions ------------------------------------------------------------------
def tess_level_np(a: np.ndarray, b: np.ndarray, eye: np.ndarray, lod: np.ndarray) -> np.ndarray:
    """``tess_level`` for rows of edges: clamp(scale · |b − a| / |eye − (a + b)/2|, min, max); max when the
    camera sits on the midpoint (distance < 1e-6). ``lod`` = (scale, min_level, max_level)."""
    a, b, eye, lod = (np.asarray(x, dtype=np.float64) for x in (a, b, eye, lod))
    d = np.linalg.norm(eye - 0.5 * (a + b), axis=-1)
    length = np.linalg.norm(b - a, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        level = np.clip(lod[..., 0] * length / np.where(d < 1e-6, 1.0, d), lod[..., 1], lod[..., 2])
    return np.where(d < 1e-6, lod[..., 2], level)


def height_np(heights: np.ndarray, uv: np.ndarray) -> np.ndarray:
    """``terrain_height``: bilinear interpolation between texel centres (u → column, v → row), clamped at the
    edges. ``uv`` has shape (..., 2)."""
    n = heights.shape[0]
    uv = np.asarray(uv, dtype=np.float64)
    st = uv * n - 0.5
    base = np.floor(st)
    f = st - base
    p0 = np.clip(base.astype(np.int64), 0, n - 1)
    p1 = np.clip(base.astype(np.int64) + 1, 0, n - 1)
    h00 = heights[p0[..., 1], p0[..., 0]]
    h10 = heights[p0[..., 1], p1[..., 0]]
    h01 = heights[p1[..., 1], p0[..., 0]]
    h11 = heights[p1[..., 1], p1[..., 0]]
    fx, fy = f[..., 0], f[..., 1]
    return (h00 * (1 - fx) + h10 * fx) * (1 - fy) + (h01 * (1 - fx) + h11 * fx) * fy


def normal_np(heights: np.ndarray, uv: np.ndarray, size: float, height_scale: float) -> np.ndarray:
    """``terrain_normal``: central differences one texel apart of ``height_np``, normalised."""
    uv = np.asarray(uv, dtype=np.float64)
    e = 1.0 / heights.shape[0]
    du = (height_np(heights, uv + [e, 0.0]) - height_np(heights, uv - [e, 0.0])) / (2 * e)
    dv = (height_np(heights, uv + [0.0, e]) - height_np(heights, uv - [0.0, e])) / (2 * e)
    k = height_scale / size
    n = np.stack([-k * du, np.ones_like(du), -k * dv], axis=-1)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)
