"""Procedural brick textures made with numpy: a height map, the normal map derived from it, and an albedo.

All three tile seamlessly. The height map (1 = brick face, 0 = bottom of the mortar joints) drives parallax
occlusion mapping; the normal map is its tangent-space gradient, encoded as ``rgb = n · 0.5 + 0.5`` with
green = up (glTF/OpenGL style); both are data, so they are stored with ``srgb=False``.
"""

from __future__ import annotations

import numpy as np

from gandalf_core.resources import TextureData, value_noise


def _check_size(size: int) -> int:
    if not isinstance(size, int) or size < 16 or size % 8:
        raise ValueError(f"size must be an int >= 16 and a multiple of 8, got {size!r}")
    return size


def brick_layout(size: int = 256, rows: int = 8, columns: int = 4) -> tuple[np.ndarray, np.ndarray]:
    """(distance in texels to the nearest joint (size, size), brick id per texel) for a running-bond wall."""
    n = _check_size(size)
    y, x = np.mgrid[0:n, 0:n].astype(np.float64) + 0.5
    brick_h, brick_w = n / rows, n / columns
    row = np.floor(y / brick_h)
    shifted = x + (row % 2) * brick_w / 2  # every other row is offset by half a brick
    col = np.floor(shifted / brick_w) % columns
    dy = np.minimum(y - row * brick_h, (row + 1) * brick_h - y)
    fx = np.mod(shifted, brick_w)
    dx = np.minimum(fx, brick_w - fx)
    return np.minimum(dx, dy), (row * columns + col).astype(np.int64)


def brick_height(size: int = 256, mortar: float = 0.035, bevel: float = 0.03) -> np.ndarray:
    """Heights in [0, 1], float64 (size, size): flat brick faces with a little noise, bevelled into the joints.

    ``mortar`` and ``bevel`` are fractions of the texture size.
    """
    distance, _ = brick_layout(size)
    half_joint, bevel_px = mortar * size / 2, max(bevel * size, 1e-6)
    t = np.clip((distance - half_joint) / bevel_px, 0.0, 1.0)
    profile = t * t * (3.0 - 2.0 * t)
    grain = value_noise(size, seed=7, cells=16, octaves=3).pixels[..., 0] / 255.0
    return np.clip(0.12 + 0.8 * profile + 0.08 * profile * grain, 0.0, 1.0)


def normal_map_from_height(height: np.ndarray, strength: float = 4.0) -> np.ndarray:
    """Tangent-space unit normals (H, W, 3) of the height field (wrapping central differences).

    ``strength`` is the relief depth in texels per unit of height. +x follows the columns (+u); +y points up the
    image (against the rows, -v), the glTF convention of :mod:`gandalf_core.resources.mesh_data`.
    """
    h = np.asarray(height, dtype=np.float64) * strength
    d_du = (np.roll(h, -1, axis=1) - np.roll(h, 1, axis=1)) / 2.0
    d_dv = (np.roll(h, -1, axis=0) - np.roll(h, 1, axis=0)) / 2.0
    # The surface z = h(u, up) with up = -v: its normal is (-dh/du, -dh/dup, 1) = (-dh/du, +dh/dv, 1).
    n = np.stack([-d_du, d_dv, np.ones_like(h)], axis=-1)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def encode_normals(normals: np.ndarray, name: str = "normal map") -> TextureData:
    """Unit normals (H, W, 3) as an ``srgb=False`` texture, ``rgb = n · 0.5 + 0.5``."""
    return TextureData.from_array(np.clip(np.asarray(normals) * 0.5 + 0.5, 0.0, 1.0), srgb=False, name=name)


def brick_textures(size: int = 256) -> dict[str, TextureData]:
    """``{"bricks_albedo", "bricks_normal", "bricks_height"}``: the three maps of one brick wall."""
    height = brick_height(size)
    distance, brick = brick_layout(size)
    rng = np.random.default_rng(11)
    tint = rng.uniform(0.8, 1.15, size=(int(brick.max()) + 1, 1))[brick]
    grain = value_noise(size, seed=3, cells=32, octaves=3).pixels[..., :1] / 255.0
    brick_rgb = np.array([0.62, 0.27, 0.18]) * tint * (0.85 + 0.3 * grain)
    mortar_rgb = np.array([0.72, 0.70, 0.66]) * (0.9 + 0.2 * grain)
    face = np.clip((distance[..., None] - 0.035 * size / 2) / 2.0, 0.0, 1.0)
    albedo = np.clip(mortar_rgb + (brick_rgb - mortar_rgb) * face, 0.0, 1.0)
    return {
        "bricks_albedo": TextureData.from_array(albedo, name="bricks_albedo"),
        "bricks_normal": encode_normals(normal_map_from_height(height), "bricks_normal"),
        "bricks_height": TextureData.from_array(height, srgb=False, name="bricks_height"),
    }
