"""Reference solution: a procedural brick texture."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from gandalf_core.resources import TextureData


def _int_at_least(name: str, value: Any, minimum: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"brick_texture: {name} must be an integer >= {minimum}, got {value!r}")
    return int(value)


def _colour(name: str, value: Sequence[float]) -> np.ndarray:
    c = np.asarray(value, dtype=np.float64).reshape(-1)
    if c.size != 3 or not np.all(np.isfinite(c)) or c.min() < 0.0 or c.max() > 1.0:
        raise ValueError(f"brick_texture: {name} must be 3 floats in [0, 1], got {value!r}")
    return c


def brick_texture(
    width: int = 128,
    height: int = 128,
    brick_size: tuple[int, int] = (32, 16),
    mortar: int = 2,
    brick_color: Sequence[float] = (0.62, 0.27, 0.18),
    mortar_color: Sequence[float] = (0.80, 0.78, 0.72),
    variation: float = 0.1,
    seed: int = 0,
    **settings: Any,
) -> TextureData:
    """A running-bond brick wall, ``width`` x ``height`` texels (see the exercise for the exact rules)."""
    w = _int_at_least("width", width, 1)
    h = _int_at_least("height", height, 1)
    if len(brick_size) != 2:
        raise ValueError(f"brick_texture: brick_size must be (width, height), got {brick_size!r}")
    bw = _int_at_least("brick_size[0]", brick_size[0], 1)
    bh = _int_at_least("brick_size[1]", brick_size[1], 1)
    m = _int_at_least("mortar", mortar, 0)
    if m >= min(bw, bh):
        raise ValueError(f"brick_texture: mortar {m} leaves no brick inside a {bw}x{bh} brick")
    if not (np.isfinite(variation) and 0.0 <= variation <= 1.0):
        raise ValueError(f"brick_texture: variation must be in [0, 1], got {variation!r}")
    brick, joint = _colour("brick_color", brick_color), _colour("mortar_color", mortar_color)
    settings.setdefault("name", "bricks")

    ys, xs = np.arange(h)[:, None], np.arange(w)[None, :]
    course = ys // bh
    shift = (course % 2) * (bw // 2)  # odd courses are offset by half a brick
    along = xs - shift
    is_mortar = (ys % bh < m) | (along % bw < m)
    # Column index modulo the bricks per course, so the brick cut by the right edge continues at the left one.
    columns = -(-w // bw)
    column = (along // bw) % columns
    factors = 1.0 + variation * (2.0 * np.random.default_rng(seed).random((-(-h // bh), columns)) - 1.0)
    shade = np.clip(brick[None, None, :] * factors[course, column][..., None], 0.0, 1.0)
    rgb = np.where(is_mortar[..., None], joint, shade)
    return TextureData.from_array(rgb, **settings)
