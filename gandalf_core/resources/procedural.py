"""Procedural textures: checkerboard, gradient, value noise, a solid colour and a sky cube map.

Everything here is deterministic (noise uses a seeded numpy generator), so generated textures can be compared
against reference images. Colours are given as 3 or 4 floats in [0, 1], in the texture's encoding: for the
default ``srgb=True`` that is what a colour picker shows. Extra keyword ``settings`` (srgb, wrap, filter, mipmaps,
name) go to :class:`~gandalf_core.resources.texture_data.TextureData`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from gandalf_core.resources.errors import ResourceError
from gandalf_core.resources.texture_data import CubeTextureData, TextureData, cube_face_directions, linear_to_srgb

Color = Sequence[float]


def _rgba(texture: str, field: str, color: Color) -> np.ndarray:
    """Validate a colour of 3 or 4 floats in [0, 1]; 3 components get alpha 1."""
    label = f"texture '{texture}'"
    try:
        c = np.asarray(color, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError) as exc:
        raise ResourceError(label, field, f"{color!r} is not a colour of 3 or 4 floats") from exc
    if c.size not in (3, 4):
        raise ResourceError(label, field, f"expected 3 or 4 components, got {c.size}")
    if not np.all(np.isfinite(c)) or c.min() < 0.0 or c.max() > 1.0:
        raise ResourceError(label, field, f"components must be finite and in [0, 1], got {tuple(c.tolist())}")
    return np.append(c, 1.0) if c.size == 3 else c


def _int(texture: str, field: str, value: int, minimum: int) -> int:
    if isinstance(value, bool) or int(value) != value or value < minimum:
        raise ResourceError(f"texture '{texture}'", field, f"must be an integer >= {minimum}, got {value!r}")
    return int(value)


def solid(color: Color, size: int = 1, **settings: Any) -> TextureData:
    """A ``size`` x ``size`` texture of one colour (a 1x1 white texture is the usual 'no texture' default)."""
    settings.setdefault("name", "solid")
    n = _int(settings["name"], "size", size, 1)
    c = _rgba(settings["name"], "color", color)
    return TextureData.from_array(np.broadcast_to(c, (n, n, 4)), **settings)


def checkerboard(
    size: int = 256,
    squares: int = 8,
    color_a: Color = (1.0, 1.0, 1.0),
    color_b: Color = (0.0, 0.0, 0.0),
    **settings: Any,
) -> TextureData:
    """A ``size`` x ``size`` checkerboard of ``squares`` x ``squares`` squares; the top-left square is ``color_a``.

    Defaults to ``filter="nearest"`` so the squares stay crisp when magnified.
    """
    settings.setdefault("name", "checkerboard")
    settings.setdefault("filter", "nearest")
    name = settings["name"]
    n = _int(name, "size", size, 1)
    k = _int(name, "squares", squares, 1)
    a, b = _rgba(name, "color_a", color_a), _rgba(name, "color_b", color_b)
    cell = np.arange(n) * k // n
    odd = (cell[:, None] + cell[None, :]) % 2 == 1
    return TextureData.from_array(np.where(odd[..., None], b, a), **settings)


def gradient(
    size: int = 256,
    start: Color = (0.0, 0.0, 0.0),
    end: Color = (1.0, 1.0, 1.0),
    direction: str = "vertical",
    **settings: Any,
) -> TextureData:
    """A linear ramp from ``start`` to ``end``: top to bottom (``"vertical"``) or left to right (``"horizontal"``).

    The stored values are interpolated directly (in the texture's encoding), like a gradient tool in a paint
    program; defaults to ``wrap="clamp"`` so the ends do not bleed into each other.
    """
    settings.setdefault("name", "gradient")
    settings.setdefault("wrap", "clamp")
    name = settings["name"]
    n = _int(name, "size", size, 1)
    a, b = _rgba(name, "start", start), _rgba(name, "end", end)
    if direction not in ("vertical", "horizontal"):
        raise ResourceError(f"texture '{name}'", "direction", f"{direction!r} is not 'vertical' or 'horizontal'")
    t = (np.arange(n) + 0.5) / n
    ramp = a + t[:, None] * (b - a)  # (n, 4)
    img = np.broadcast_to(ramp[:, None, :], (n, n, 4)) if direction == "vertical" else np.broadcast_to(ramp, (n, n, 4))
    return TextureData.from_array(img, **settings)


def _lattice_coords(n: int, cells: int, shift: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Smoothstep weights and the two wrapped lattice indices for ``n`` texel centres over ``cells`` cells."""
    x = (np.arange(n) + 0.5) / n * cells - 0.5 + shift
    i0 = np.floor(x).astype(np.int64)
    f = x - i0
    return f * f * (3.0 - 2.0 * f), i0 % cells, (i0 + 1) % cells


def value_noise(size: int = 256, seed: int = 0, cells: int = 8, octaves: int = 4, **settings: Any) -> TextureData:
    """Tileable grey fractal value noise in [0, 1], the same for the same arguments.

    Octave ``o`` interpolates random lattice values on a ``cells * 2**o`` grid with smoothstep weights and
    adds them with amplitude ``0.5**o``; the lattice wraps, so the texture repeats seamlessly. Defaults to
    ``srgb=False``: noise is usually data (height, roughness), not colour.
    """
    settings.setdefault("name", "value_noise")
    settings.setdefault("srgb", False)
    name = settings["name"]
    n = _int(name, "size", size, 1)
    c0 = _int(name, "cells", cells, 1)
    count = _int(name, "octaves", octaves, 1)
    rng = np.random.default_rng(_int(name, "seed", seed, 0))
    total = np.zeros((n, n))
    amplitude_sum = 0.0
    for o in range(count):
        c = c0 * 2**o
        lattice = rng.random((c, c))
        # A random shift per octave and axis keeps the octaves' lattice lines from lining up into visible seams;
        # the lattice wraps, so any shift still tiles.
        shift = rng.random(2)
        fy, iy0, iy1 = _lattice_coords(n, c, shift[0])
        fx, ix0, ix1 = _lattice_coords(n, c, shift[1])
        rows = lattice[iy0] * (1.0 - fy)[:, None] + lattice[iy1] * fy[:, None]
        layer = rows[:, ix0] * (1.0 - fx)[None, :] + rows[:, ix1] * fx[None, :]
        amplitude = 0.5**o
        total += amplitude * layer
        amplitude_sum += amplitude
    return TextureData.from_array(total / amplitude_sum, **settings)


def _smoothstep(e0: float, e1: float, x: np.ndarray) -> np.ndarray:
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def sky_cube(size: int = 128, sun_direction: Sequence[float] = (0.35, 0.45, -0.82), **settings: Any) -> CubeTextureData:
    """A daylight sky cube map: blue zenith fading to a pale horizon, a dusky ground and a soft sun.

    ``sun_direction`` points from the viewer towards the sun (normalised here; the default sits ahead of a
    camera looking down -Z, up and to the right). Shading is done in linear light and stored sRGB-encoded.
    """
    settings.setdefault("name", "sky")
    label = f"cube texture '{settings['name']}'"
    n = _int(settings["name"], "size", size, 1)
    sun = np.asarray(sun_direction, dtype=np.float64).reshape(-1)
    length = float(np.linalg.norm(sun)) if sun.size == 3 and np.all(np.isfinite(sun)) else 0.0
    if length <= 1e-12:
        raise ResourceError(label, "sun_direction", f"expected a non-zero finite 3-vector, got {sun_direction!r}")
    sun = sun / length
    d = cube_face_directions(n)  # (6, n, n, 3)
    y = d[..., 1:2]
    zenith, horizon = np.array([0.08, 0.24, 0.62]), np.array([0.60, 0.74, 0.90])
    ground_far, ground_near = np.array([0.30, 0.29, 0.27]), np.array([0.10, 0.09, 0.08])
    sky = horizon + (zenith - horizon) * np.sqrt(np.clip(y, 0.0, 1.0))
    ground = ground_far + (ground_near - ground_far) * _smoothstep(0.0, 0.4, -y)
    colour = np.where(y >= 0.0, sky, ground)
    cos_sun = np.clip(np.sum(d * sun, axis=-1, keepdims=True), -1.0, 1.0)
    # A disc of about 2 degrees radius with a soft rim, plus a wide warm glow around it.
    disc = _smoothstep(np.cos(np.radians(2.2)), np.cos(np.radians(1.6)), cos_sun)
    glow = 0.35 * np.clip(cos_sun, 0.0, 1.0) ** 48 + 0.12 * np.clip(cos_sun, 0.0, 1.0) ** 6
    sunlight = np.array([1.0, 0.92, 0.75])
    colour = colour + glow * sunlight * (y > -0.05)
    colour = colour * (1.0 - disc) + disc * np.array([1.0, 0.98, 0.92])
    rgb = linear_to_srgb(colour)
    rgba = np.concatenate([rgb, np.ones(rgb.shape[:-1] + (1,))], axis=-1)
    return CubeTextureData.from_arrays(list(rgba), **settings)
