"""Where two implementations may legally sample a receding textured plane from different mip levels.

OpenGL 4.6 §8.14.1 (and Vulkan's "scale factor") let an implementation replace the ideal texel scale factor
ρ = max(|∂(u, v)/∂x|, |∂(u, v)/∂y|) by any f with max(m_u, m_v) ≤ f ≤ m_u + m_v, where m_u = max(|∂u/∂x|, |∂u/∂y|)
and m_v likewise; the derivatives themselves are differences across the pixel's 2 × 2 quad, taken forwards or
backwards, on the pixel's own row/column or its quad neighbour's ("coarse"); and the level of detail
λ = log2(f) carries a few bits of precision (Vulkan asks for 4: 1/16). With a nearest mip filter the level is
round(λ) (level d for d - 1/2 < λ ≤ d + 1/2): a pixel whose legal range of λ holds a level's boundary d + 1/2
may show either level. :func:`mip_flip_pixels` finds those pixels for a textured plane y = const, from the
camera that drew it; a picture compared across implementations leaves them out and checks the rest.
"""

from __future__ import annotations

import numpy as np

#: Vulkan's minimum mipLodPrecisionBits (4): λ may be off by 1/16.
LOD_PRECISION = 1.0 / 16.0


def plane_texels(view: np.ndarray, projection: np.ndarray, size: tuple[int, int], height: float,
                 extent: float, texels: int) -> np.ndarray:
    """(H + 2, W + 2, 2) texel coordinates where each pixel centre's ray (one pixel of margin around the picture)
    meets the plane y = ``height`` of edge ``extent`` centred on the origin (UV 0..1 across, as
    ``primitives.plane``), times ``texels``; NaN where the ray misses it."""
    w, h = size
    x = (np.arange(-1, w + 1) + 0.5) / w * 2.0 - 1.0
    y = 1.0 - (np.arange(-1, h + 1) + 0.5) / h * 2.0
    ndc_x, ndc_y = np.meshgrid(x, y)
    inverse = np.linalg.inv(projection @ view)

    def unproject(z: float) -> np.ndarray:
        p = np.stack([ndc_x, ndc_y, np.full_like(ndc_x, z), np.ones_like(ndc_x)], -1) @ inverse.T
        return p[..., :3] / p[..., 3:]

    a, b = unproject(0.0), unproject(0.5)  # two points on each ray, inside either API's depth range
    t = (height - a[..., 1]) / (b[..., 1] - a[..., 1])
    hit = a + t[..., None] * (b - a)
    uv = np.stack([hit[..., 0], hit[..., 2]], -1) / extent + 0.5
    in_front = (np.concatenate([hit, np.ones_like(t)[..., None]], -1) @ (projection @ view).T)[..., 3] > 0.0
    on_plane = in_front[..., None] & np.all((uv >= 0.0) & (uv <= 1.0), axis=-1, keepdims=True)
    return np.where(on_plane, uv * texels, np.nan)


def mip_flip_pixels(texel: np.ndarray) -> np.ndarray:
    """(H, W) pixels whose legal λ range (module docstring) holds a nearest-mip boundary d + 1/2, d ≥ 0, from the
    (H + 2, W + 2, 2) texel coordinates of :func:`plane_texels`; also the plane's pixels whose quad leaves the
    plane (their derivatives are undefined)."""
    dx_all = np.abs(np.diff(texel, axis=1))  # (H + 2, W + 1, 2): differences between horizontal neighbours
    dy_all = np.abs(np.diff(texel, axis=0))  # (H + 1, W + 2, 2)
    h, w = texel.shape[0] - 2, texel.shape[1] - 2
    # Every difference a pixel's quad may use: left or right of it, on its row or the rows above and below.
    dx = np.stack([dx_all[r:r + h, c:c + w] for r in (0, 1, 2) for c in (0, 1)])
    dy = np.stack([dy_all[r:r + h, c:c + w] for r in (0, 1) for c in (0, 1, 2)])
    with np.errstate(invalid="ignore", divide="ignore"):
        lowest = np.maximum(dx.min(axis=0).max(axis=-1), dy.min(axis=0).max(axis=-1))
        m_u = np.maximum(dx[..., 0].max(axis=0), dy[..., 0].max(axis=0))
        m_v = np.maximum(dx[..., 1].max(axis=0), dy[..., 1].max(axis=0))
        lo = np.log2(lowest) - LOD_PRECISION
        hi = np.log2(m_u + m_v) + LOD_PRECISION
    boundary = np.ceil(lo - 0.5) + 0.5  # the first d + 1/2 at or above lo
    flips = (boundary <= hi) & (hi >= 0.5)
    on_plane = ~np.isnan(texel[1:-1, 1:-1, 0])
    return on_plane & (flips | np.isnan(lo) | np.isnan(hi))
