"""The patch grid and its level of detail, backend-neutral (numpy, float64).

The terrain is a square of ``size`` world units centred on the origin, cut into ``patches`` × ``patches`` quad
patches. A patch's corners, in the order the shaders use: c0 = (u0, v0), c1 = (u1, v0), c2 = (u1, v1),
c3 = (u0, v1), where world x = (u − ½) · size and world z = (v − ½) · size, and y = height_scale · h(u, v).

Its four **outer** levels follow OpenGL's numbering for quads: outer[0] the edge u = u0 (c0–c3), outer[1] the edge
v = v0 (c0–c1), outer[2] the edge u = u1 (c1–c2), outer[3] the edge v = v1 (c3–c2); each is ``tess_level`` of
the edge's two displaced corners, so the two patches sharing an edge compute the same number (no cracks). The
**inner** level is the largest outer level. With ``equal_spacing`` a level x becomes ceil(x) segments.

:func:`patch_vertices` is the numpy twin of the WebGPU compute pass (``tessellate.wgsl``): per patch an
n × n grid (n = ceil(inner)) of 6·n² vertices, the vertices on each edge snapped to that edge's own
ceil(outer) segments, padded with degenerate triangles to a fixed budget of 6·L² (L = max level).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from gandalf_core.resources import MeshData

from .heightfield import height_np, tess_level_np

#: OpenGL guarantees at least this GL_MAX_TESS_GEN_LEVEL; WebGPU's compute path keeps the same limit.
GUARANTEED_MAX_LEVEL = 64


@dataclass(frozen=True)
class TerrainParams:
    """The terrain's shape and level of detail. ``lod_scale``: level = lod_scale · edge length / distance."""

    size: float = 20.0
    patches: int = 16
    height_scale: float = 3.2
    lod_scale: float = 40.0
    min_level: float = 1.0
    max_level: float = 16.0

    def __post_init__(self) -> None:
        # WebGPU dispatches one work-group row per patch: patches² must stay within 65535 work groups.
        if not (isinstance(self.patches, int) and 1 <= self.patches <= 128):
            raise ValueError(f"TerrainParams.patches must be an int in [1, 128], got {self.patches!r}")
        for name in ("size", "height_scale", "lod_scale"):
            value = getattr(self, name)
            if not (np.isfinite(value) and value > 0):
                raise ValueError(f"TerrainParams.{name} must be a positive finite number, got {value!r}")
        for name in ("min_level", "max_level"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and np.isfinite(value) and value >= 1.0):
                raise ValueError(f"TerrainParams.{name} must be a finite level >= 1, got {value!r}")
        if self.min_level > self.max_level:
            raise ValueError(f"TerrainParams.min_level = {self.min_level} is larger than max_level = {self.max_level}")

    @property
    def lod(self) -> tuple[float, float, float]:
        """The exercise's ``lod`` argument: (scale, min_level, max_level)."""
        return (float(self.lod_scale), float(self.min_level), float(self.max_level))

    @property
    def budget(self) -> int:
        """The largest number of segments per patch side: ceil(max_level)."""
        return int(np.ceil(self.max_level))


def check_levels(min_level: float, max_level: float, device_max: int, limit: str = "GL_MAX_TESS_GEN_LEVEL") -> None:
    """Raise ValueError unless 1 <= min_level <= max_level <= device_max (the tessellator's range)."""
    for name, value in (("min_level", min_level), ("max_level", max_level)):
        if not (isinstance(value, (int, float)) and np.isfinite(value) and 1.0 <= value <= device_max):
            raise ValueError(f"tessellation {name} = {value!r} is outside the device's range [1, {device_max}] "
                             f"({limit})")
    if min_level > max_level:
        raise ValueError(f"tessellation min_level = {min_level} is larger than max_level = {max_level}")


def patch_corner_uvs(params: TerrainParams) -> np.ndarray:
    """(P², 4, 2) float64: the uv of each patch's corners c0..c3 (patch k = row · P + column)."""
    p = params.patches
    j, i = np.divmod(np.arange(p * p), p)
    u0, v0, u1, v1 = i / p, j / p, (i + 1) / p, (j + 1) / p
    return np.stack([np.stack([u0, v0], -1), np.stack([u1, v0], -1), np.stack([u1, v1], -1),
                     np.stack([u0, v1], -1)], axis=1)


def world(uv: np.ndarray, heights: np.ndarray, params: TerrainParams) -> np.ndarray:
    """World positions (..., 3) of terrain points at ``uv`` (displaced by the heightmap)."""
    uv = np.asarray(uv, dtype=np.float64)
    y = params.height_scale * height_np(heights, uv)
    return np.stack([(uv[..., 0] - 0.5) * params.size, y, (uv[..., 1] - 0.5) * params.size], axis=-1)


def patch_mesh(params: TerrainParams) -> MeshData:
    """The flat control points as a patch mesh: (P+1)² corners (y = 0), four indices per patch (c0..c3)."""
    p = params.patches
    g = np.arange(p + 1) / p
    u, v = np.meshgrid(g, g)
    positions = np.stack([(u - 0.5) * params.size, np.zeros_like(u), (v - 0.5) * params.size], -1).reshape(-1, 3)
    j, i = np.divmod(np.arange(p * p), p)
    c0 = j * (p + 1) + i
    indices = np.stack([c0, c0 + 1, c0 + p + 2, c0 + p + 1], axis=1).reshape(-1)
    uvs = np.stack([u, v], -1).reshape(-1, 2)
    return MeshData(positions, uvs=uvs, indices=indices, patch_size=4, name="terrain patches")


#: Corner pairs of the four outer edges, in OpenGL's order (see the module docstring).
EDGES = ((0, 3), (0, 1), (1, 2), (3, 2))


def patch_levels(heights: np.ndarray, params: TerrainParams, eye: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(outer (P², 4), inner (P²,)) continuous levels of every patch for a camera at ``eye``."""
    corners = world(patch_corner_uvs(params), heights, params)
    lod = np.asarray(params.lod)
    outer = np.stack([tess_level_np(corners[:, a], corners[:, b], eye, lod) for a, b in EDGES], axis=1)
    return outer, outer.max(axis=1)


def _snap(i: np.ndarray, n: np.ndarray, m: np.ndarray) -> np.ndarray:
    """Grid index i of n snapped to the nearest of m segments, in integers: floor(i·m/n + ½) / m."""
    return ((2 * i * m + n) // (2 * n)) / m


def patch_vertices(outer: np.ndarray, inner: np.ndarray, budget: int) -> tuple[np.ndarray, np.ndarray]:
    """The compute pass's vertex placement: (P², 6·budget², 2) patch-local (s, t) in [0, 1] and a (P², 6·budget²)
    mask of the slots in use (the rest are degenerate). Triangles per cell: (00, 10, 11), (00, 11, 01)."""
    segments = np.ceil(inner).astype(np.int64)
    edge = np.ceil(outer).astype(np.int64)
    cj, ci = np.divmod(np.arange(budget * budget), budget)
    corner_i = np.array([0, 1, 1, 0, 1, 0])
    corner_j = np.array([0, 0, 1, 0, 1, 1])
    gi = ci[:, None] + corner_i[None, :]  # (cells, 6)
    gj = cj[:, None] + corner_j[None, :]
    n = segments[:, None, None]
    gi, gj = np.broadcast_to(gi, (len(segments),) + gi.shape), np.broadcast_to(gj, (len(segments),) + gj.shape)
    s, t = gi / n, gj / n
    m0, m1, m2, m3 = (edge[:, k, None, None] for k in range(4))
    s = np.where(gj == 0, _snap(gi, n, m1), np.where(gj == n, _snap(gi, n, m3), s))
    t = np.where(gi == 0, _snap(gj, n, m0), np.where(gi == n, _snap(gj, n, m2), t))
    used = (ci[None, :] < segments[:, None]) & (cj[None, :] < segments[:, None])
    st = np.stack([s, t], -1).reshape(len(segments), -1, 2)
    return st, np.repeat(used, 6, axis=1)


def gl_triangle_count(outer: np.ndarray, inner: np.ndarray) -> int:
    """Triangles OpenGL's quad tessellator makes for these levels (equal spacing, both inner levels equal):
    2 for a 1×1 patch, else 2·(n−2)² inside plus Σ (m_k + n − 2) in the outer ring."""
    n = np.ceil(inner).astype(np.int64)
    m = np.ceil(outer).astype(np.int64)
    ring = (m + (n - 2)[:, None]).sum(axis=1) + 2 * (n - 2) ** 2
    return int(np.where(n == 1, 2, ring).sum())
