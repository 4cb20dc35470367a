"""Image-based lighting, precomputed on the CPU in float64 numpy: the three maps of the split-sum approximation.

The environment is a procedural HDR-ish sky (:func:`sky_radiance`: linear radiance, a sun far brighter than 1)
or any :class:`~gandalf_core.resources.CubeTextureData`. From it:

* the **irradiance map** ``E(n)/π = 1/π ∫ L(l) max(n·l, 0) dω``: exact quadrature over a 32² cube of the
  environment (every texel weighted by its solid angle), stored at 16² per face;
* the **prefiltered environment**: level ``k`` of ``levels`` holds roughness ``k / (levels - 1)``, the GGX lobe
  around ``n = v = r`` integrated by importance sampling (Hammersley points, weights ``n·l``, Karis 2013),
  each sample reading a float mip level of the environment that matches its share of the lobe (filtered
  importance sampling: 64 such samples are about as accurate as 512 plain ones; see ``study.py``);
* the **BRDF lookup table** ``(A, B)(n·v, roughness)`` with ``∫ f_spec cos = F0·A + B`` (Smith-Schlick-GGX with
  ``k = α/2``), stored as R and G of a linear RGBA8 texture: column = n·v, row = roughness (top row first).

All three become 8-bit textures (sRGB for radiance, linear for the table): the prefiltered levels travel as
explicit mip levels (``CubeTextureData(levels=...)``), uploaded per level by both renderers.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from gandalf_core.resources import (
    CubeTextureData,
    ResourceError,
    TextureData,
    cube_face_directions,
    linear_to_srgb,
    srgb_to_linear,
)

Radiance = Callable[[np.ndarray], np.ndarray]

SUN_DIRECTION = np.array([0.45, 0.55, 0.70]) / np.linalg.norm([0.45, 0.55, 0.70])
#: Prefiltered levels: 128² (roughness 0) down to 4² (roughness 1).
PREFILTER_SIZE = 128
PREFILTER_LEVELS = 6
PREFILTER_SAMPLES = 64
IRRADIANCE_SIZE = 16
LUT_SIZE = 32
LUT_SAMPLES = 256
SKY_SIZE = 256
# Directions times samples per chunk: one vectorised step's arrays stay near the CPU's caches (~1.5 MB of float64
# each). Chunks of 2^21 (~50 MB arrays) made the whole build 2.5 times slower (3.6-5.7 s against 1.5 s, 2 cores).
_CHUNK = 1 << 16


def _smoothstep(e0: float, e1: float, x: np.ndarray) -> np.ndarray:
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


_ZENITH, _HORIZON = np.array([0.10, 0.28, 0.70]), np.array([0.75, 0.85, 0.98])
_GROUND_FAR, _GROUND_NEAR = np.array([0.32, 0.30, 0.27]), np.array([0.06, 0.055, 0.05])
# Rows: horizon, far ground, zenith - horizon, near - far ground, the sun's glow, the sun's disc.
_SKY_COLOURS = np.array([_HORIZON, _GROUND_FAR, _ZENITH - _HORIZON, _GROUND_NEAR - _GROUND_FAR,
                         [1.0, 0.85, 0.6], [16.0, 15.2, 13.6]])


def sky_radiance(d: np.ndarray) -> np.ndarray:
    """Linear radiance (..., 3) of the procedural sky for unit directions ``d`` (..., 3): a blue zenith over a
    pale horizon, a dark ground, a warm glow and a sun disc of about 3° radius with radiance 16 (HDR-ish)."""
    d = np.asarray(d, dtype=np.float64)
    y = d[..., 1]
    up = (y >= 0.0).astype(np.float64)
    c = np.clip(d @ SUN_DIRECTION, 0.0, 1.0)
    c8 = c * c
    c8 *= c8
    c8 *= c8  # cos^8, then cos^64 by squaring (much faster than **)
    c64 = c8 * c8
    c64 *= c64
    c64 *= c64
    # Scalar features per direction, then one matrix product gives the colour (fast on millions of samples).
    features = np.stack([
        up, 1.0 - up,
        up * np.sqrt(np.maximum(y, 0.0)), (1.0 - up) * _smoothstep(0.0, 0.35, -y),
        (0.6 * c64 + 0.15 * c8) * (y > -0.05),
        _smoothstep(np.cos(np.radians(3.2)), np.cos(np.radians(2.2)), c),
    ], axis=-1)
    return features @ _SKY_COLOURS


def cube_radiance(cube: CubeTextureData) -> Radiance:
    """The radiance of a cube map's level 0 as a function of direction (bilinear within a face, linear light).

    Raises :class:`ResourceError` naming the texture when ``cube`` is not a cube map.
    """
    if not isinstance(cube, CubeTextureData):
        name = getattr(cube, "name", type(cube).__name__)
        raise ResourceError(f"texture '{name}'", "environment",
                            f"image-based light needs a cube map (CubeTextureData), got {type(cube).__name__}")
    texels = cube.pixels[..., :3].astype(np.float64) / 255.0
    if cube.srgb:
        texels = srgb_to_linear(texels)

    def radiance(d: np.ndarray) -> np.ndarray:
        return sample_cube(texels, d)

    return radiance


def sample_cube(texels: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Bilinear lookup (within a face, clamped at its edges) of float cube texels (6, s, s, C) at directions
    ``d`` (..., 3), with the cube-map convention of :func:`~gandalf_core.resources.cube_face_directions`."""
    size = texels.shape[1]
    d = np.asarray(d, dtype=np.float64)
    flat = d.reshape(-1, 3)
    x, y, z = flat.T
    ax, ay, az = np.abs(flat).T
    face = np.where((ax >= ay) & (ax >= az), np.where(x > 0, 0, 1),
                    np.where(ay >= az, np.where(y > 0, 2, 3), np.where(z > 0, 4, 5)))
    ma = np.maximum(np.choose(face, [ax, ax, ay, ay, az, az]), 1e-300)
    sc = np.choose(face, [-z, z, x, x, x, -x])
    tc = np.choose(face, [-y, -y, z, -z, -y, -y])
    s = np.clip(((sc / ma + 1.0) * 0.5) * size - 0.5, 0.0, size - 1.0)
    t = np.clip(((tc / ma + 1.0) * 0.5) * size - 0.5, 0.0, size - 1.0)
    s0 = np.minimum(np.floor(s).astype(np.int64), max(size - 2, 0))
    t0 = np.minimum(np.floor(t).astype(np.int64), max(size - 2, 0))
    fs, ft = (s - s0)[:, None], (t - t0)[:, None]
    s1, t1 = np.minimum(s0 + 1, size - 1), np.minimum(t0 + 1, size - 1)
    top = texels[face, t0, s0] * (1 - fs) + texels[face, t0, s1] * fs
    bottom = texels[face, t1, s0] * (1 - fs) + texels[face, t1, s1] * fs
    return (top * (1 - ft) + bottom * ft).reshape(d.shape[:-1] + (texels.shape[-1],))


class RadianceMips:
    """A float64 cube mip chain of a radiance function (``size``² at level 0, each texel the mean of
    ``supersample``² samples, then 2×2 box averages): the source of filtered importance sampling."""

    def __init__(self, radiance: Radiance, size: int = 128, supersample: int = 2) -> None:
        fine = radiance(cube_face_directions(size * supersample))
        level = fine.reshape(6, size, supersample, size, supersample, 3).mean(axis=(2, 4))
        self.levels = [level]
        while level.shape[1] > 1:
            s = level.shape[1] // 2
            level = level.reshape(6, s, 2, s, 2, 3).mean(axis=(2, 4))
            self.levels.append(level)
        self.size = size


def hammersley(count: int) -> np.ndarray:
    """``count`` Hammersley points (count, 2) in [0, 1)²: (i / count, radical inverse of i in base 2)."""
    i = np.arange(count, dtype=np.uint64)
    bits = np.zeros(count, dtype=np.float64)
    scale, value = 0.5, i.copy()
    while np.any(value):
        bits += (value & np.uint64(1)).astype(np.float64) * scale
        value >>= np.uint64(1)
        scale *= 0.5
    return np.stack([i.astype(np.float64) / count, bits], axis=-1)


def _basis(n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unit tangent and bitangent (P, 3) perpendicular to the unit normals ``n`` (P, 3)."""
    up = np.where(np.abs(n[:, 2:3]) < 0.999, np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]))
    t = np.cross(up, n)
    t /= np.linalg.norm(t, axis=-1, keepdims=True)
    return t, np.cross(n, t)


# --8<-- [start:sampling]
def ggx_half_vectors(xi: np.ndarray, alpha: float) -> np.ndarray:
    """Tangent-space half vectors (M, 3) distributed by GGX's D(h)·(n·h) for the points ``xi`` (M, 2)."""
    phi = 2.0 * np.pi * xi[:, 0]
    cos_theta = np.sqrt((1.0 - xi[:, 1]) / (1.0 + (alpha * alpha - 1.0) * xi[:, 1]))
    sin_theta = np.sqrt(np.clip(1.0 - cos_theta**2, 0.0, 1.0))
    return np.stack([sin_theta * np.cos(phi), sin_theta * np.sin(phi), cos_theta], axis=-1)


def prefilter_directions(radiance: Radiance, n: np.ndarray, roughness: float, samples: int,
                         source: RadianceMips | None = None) -> np.ndarray:
    """The GGX-prefiltered radiance (P, 3) around the unit directions ``n`` (P, 3), with ``n = v = r``:
    ``Σ L(l) (n·l) / Σ (n·l)`` over ``samples`` importance-sampled half vectors (Karis' split sum).

    Without ``source`` each sample reads ``radiance`` itself (unbiased, but a small bright sun makes it noisy).
    With ``source`` it reads the mip level whose texels cover the sample's share of the lobe (filtered importance
    sampling, Křivánek & Colbert 2008): ``lod = ½ log2(Ω_sample / Ω_texel) + 1`` with
    ``Ω_sample = 1 / (M · pdf)``, ``pdf = D(h) / 4`` for n = v: far less noise, slightly more blur.
    """
    n = np.asarray(n, dtype=np.float64).reshape(-1, 3)
    if roughness <= 0.0:
        return radiance(n)
    alpha = roughness * roughness
    h_local = ggx_half_vectors(hammersley(samples), alpha)
    cos_h = h_local[:, 2]
    lookups: list[tuple[int, np.ndarray]] = []  # (level, per-sample weight) of the filtered route
    if source is not None:
        a2 = alpha * alpha
        pdf = a2 / (np.pi * (cos_h**2 * (a2 - 1.0) + 1.0) ** 2) / 4.0
        texel = 4.0 * np.pi / (6.0 * source.size**2)
        top = len(source.levels) - 1
        lod = np.clip(0.5 * np.log2(1.0 / (samples * pdf) / texel) + 1.0, 0.0, top)
        low = np.floor(lod).astype(int)
        frac = lod - low
        high = np.minimum(low + 1, top)
        for level in range(top + 1):
            w = np.where(low == level, 1.0 - frac, 0.0) + np.where(high == level, frac, 0.0)
            if np.any(w > 0.0):
                lookups.append((level, w))
    t, b = _basis(n)
    out = np.empty_like(n)
    step = max(1, _CHUNK // samples)
    weight = np.clip(2.0 * cos_h**2 - 1.0, 0.0, None)  # n·l for each sample (the same for every texel)
    for start in range(0, n.shape[0], step):
        sl = slice(start, start + step)
        frame = np.stack([t[sl], b[sl], n[sl]], axis=-1)  # (P, 3, 3), columns t, b, n
        h = np.einsum("pij,mj->pmi", frame, h_local)
        light = 2.0 * cos_h[None, :, None] * h - n[sl, None, :]
        if source is None:
            values = radiance(light)
        else:
            values = np.zeros(light.shape)
            for level, w in lookups:
                used = w > 0.0
                values[:, used] += w[used][None, :, None] * sample_cube(source.levels[level], light[:, used])
        out[sl] = np.einsum("m,pmc->pc", weight, values) / max(weight.sum(), 1e-12)
    return out
# --8<-- [end:sampling]


def prefilter_levels(radiance: Radiance, size: int = PREFILTER_SIZE, levels: int = PREFILTER_LEVELS,
                     samples: int = PREFILTER_SAMPLES, filtered: bool = True) -> list[np.ndarray]:
    """Linear radiance per level, (6, size >> k, size >> k, 3) float64, level k at roughness k / (levels - 1);
    ``filtered`` samples a :class:`RadianceMips` of the environment (see :func:`prefilter_directions`)."""
    if levels < 2 or size >> (levels - 1) < 1:
        raise ValueError(f"{levels} levels do not fit a {size}² cube (need 2 <= levels <= log2(size) + 1)")
    source = RadianceMips(radiance, size) if filtered else None
    out = []
    for k in range(levels):
        s = size >> k
        d = cube_face_directions(s).reshape(-1, 3)
        out.append(prefilter_directions(radiance, d, k / (levels - 1), samples, source).reshape(6, s, s, 3))
    return out


def _texel_solid_angles(size: int) -> np.ndarray:
    """Solid angle of every texel of a size² cube, (6, size, size)."""
    c = (np.arange(size, dtype=np.float64) + 0.5) / size * 2.0 - 1.0
    s, t = np.meshgrid(c, c)
    w = (2.0 / size) ** 2 / (1.0 + s * s + t * t) ** 1.5
    return np.broadcast_to(w, (6, size, size))


def irradiance_map(radiance: Radiance, size: int = IRRADIANCE_SIZE, source_size: int = 32,
                   supersample: int = 4) -> np.ndarray:
    """``E(n)/π`` (6, size, size, 3) in linear light: every direction's cosine-weighted sum over a
    ``source_size``² cube of the environment (each texel the mean of supersample² radiance samples)."""
    fine = cube_face_directions(source_size * supersample)
    values = radiance(fine).reshape(6, source_size, supersample, source_size, supersample, 3).mean(axis=(2, 4))
    dirs = cube_face_directions(source_size).reshape(-1, 3)
    weighted = values.reshape(-1, 3) * _texel_solid_angles(source_size).reshape(-1, 1)
    n = cube_face_directions(size).reshape(-1, 3)
    cosines = np.clip(n @ dirs.T, 0.0, None)
    return (cosines @ weighted / np.pi).reshape(6, size, size, 3)


def split_sum(n_dot_v: np.ndarray, roughness: float, samples: int = LUT_SAMPLES) -> np.ndarray:
    """(A, B) per n·v (S,) -> (S, 2) at one roughness: the mean over GGX-sampled half vectors of
    ``(1 - Fc) G_vis`` and ``Fc G_vis`` with ``G_vis = G v·h / (n·h n·v)``, ``Fc = (1 - v·h)^5``, Smith-Schlick-GGX
    with k = α/2 (α = roughness²)."""
    nv = np.asarray(n_dot_v, dtype=np.float64)
    alpha = roughness * roughness
    k = alpha / 2.0
    h = ggx_half_vectors(hammersley(samples), alpha)  # (M, 3), n = +z
    v = np.stack([np.sqrt(1.0 - nv * nv), np.zeros_like(nv), nv], axis=-1)  # (S, 3)
    v_dot_h = np.clip(v @ h.T, 0.0, 1.0)  # (S, M)
    n_dot_l = np.clip(2.0 * v_dot_h * h[None, :, 2] - nv[:, None], 0.0, 1.0)  # l.z = 2(v·h)h.z - v.z
    nv_col, nl = nv[:, None], np.maximum(n_dot_l, 1e-12)
    g = nv_col / (nv_col * (1.0 - k) + k) * (nl / (nl * (1.0 - k) + k))
    g_vis = np.where(n_dot_l > 0.0, g * v_dot_h / (h[None, :, 2] * nv_col), 0.0)
    fc = (1.0 - v_dot_h) ** 5
    return np.stack([((1.0 - fc) * g_vis).mean(axis=1), (fc * g_vis).mean(axis=1)], axis=-1)


def brdf_lut(size: int = LUT_SIZE, samples: int = LUT_SAMPLES) -> np.ndarray:
    """(A, B) of the split sum, (size, size, 2) float64: row j at roughness (j + 0.5) / size, column i at
    n·v = (i + 0.5) / size; ``∫ f_spec (n·l) dl = F0·A + B`` for a white environment (:func:`split_sum`)."""
    centres = (np.arange(size) + 0.5) / size
    return np.stack([split_sum(centres, r, samples) for r in centres])


def _encode_cube(linear: np.ndarray) -> np.ndarray:
    rgb = linear_to_srgb(np.clip(linear, 0.0, 1.0))
    rgba = np.concatenate([rgb, np.ones(rgb.shape[:-1] + (1,))], axis=-1)
    return np.rint(rgba * 255.0).astype(np.uint8)


def encode_prefiltered(levels: list[np.ndarray], name: str = "ibl_prefiltered") -> CubeTextureData:
    """Linear prefiltered levels (from :func:`prefilter_levels`) as one sRGB cube map with explicit mip levels."""
    chain = [_encode_cube(level) for level in levels]
    return CubeTextureData(tuple(chain[0]), levels=tuple(chain[1:]), name=name)


@dataclass(frozen=True)
class IBLMaps:
    """The textures of image-based light: ``sky`` (the background), ``irradiance``, ``prefiltered`` (one
    roughness per mip level) and ``brdf_lut``; ``levels`` is the prefiltered level count (max LOD + 1)."""

    sky: CubeTextureData
    irradiance: CubeTextureData
    prefiltered: CubeTextureData
    brdf_lut: TextureData
    levels: int


def build_ibl(environment: Radiance | CubeTextureData | None = None, samples: int = PREFILTER_SAMPLES,
              size: int = PREFILTER_SIZE, levels: int = PREFILTER_LEVELS, prefix: str = "ibl") -> IBLMaps:
    """The IBL textures of ``environment`` (a radiance function of direction, a cube map, or None for
    :func:`sky_radiance`). Anything else raises :class:`ResourceError` naming it."""
    if environment is None:
        radiance, sky_pixels = sky_radiance, None
    elif isinstance(environment, CubeTextureData):
        radiance, sky_pixels = cube_radiance(environment), environment.faces
    elif callable(environment) and not isinstance(environment, TextureData):
        radiance, sky_pixels = environment, None
    else:
        radiance = cube_radiance(environment)  # raises: not a cube map
    if sky_pixels is None:
        sky_pixels = tuple(_encode_cube(radiance(cube_face_directions(SKY_SIZE))))
    prefiltered = encode_prefiltered(prefilter_levels(radiance, size, levels, samples), f"{prefix}_prefiltered")
    lut = brdf_lut()
    lut_rgba = np.concatenate([lut, np.zeros(lut.shape[:2] + (1,)), np.ones(lut.shape[:2] + (1,))], axis=-1)
    return IBLMaps(
        sky=CubeTextureData(tuple(sky_pixels), name=f"{prefix}_sky"),
        irradiance=CubeTextureData(tuple(_encode_cube(irradiance_map(radiance))), mipmaps=False,
                                   name=f"{prefix}_irradiance"),
        prefiltered=prefiltered,
        brdf_lut=TextureData.from_array(np.clip(lut_rgba, 0.0, 1.0), srgb=False, wrap="clamp", mipmaps=False,
                                        name=f"{prefix}_brdf_lut"),
        levels=levels,
    )


@functools.cache
def default_ibl() -> IBLMaps:
    """:func:`build_ibl` of the procedural sky, computed once per process (about 1.5 s on 2 cores)."""
    return build_ibl()
