"""The exercise's three parallax functions in float64 numpy, vectorised over rows (the graders' and the study's
reference), plus a bilinear, repeating sampler of a height map so the study can march the real brick wall.

Every function takes ``height`` — a callable mapping uv rows (n, 2) to heights (n,) in [0, 1] — and the same
conventions as ``exercises/parallax.glsl``: ``view`` rows are unit vectors towards the eye in texture space (x along
+u, y along +v, z out of the surface), ``scale`` the depth of height 0 in uv units, the division by
``max(view.z, MIN_Z)``.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

#: The floor of view_ts.z in every division (PARALLAX_MIN_Z of the shaders).
MIN_Z = 0.1
#: Layer counts are clamped to [1, MAX_LAYERS] (PARALLAX_MAX_LAYERS of the shaders).
MAX_LAYERS = 256

Height = Callable[[np.ndarray], np.ndarray]


def _rows(uv, view, scale, layers=None):
    uv = np.atleast_2d(np.asarray(uv, np.float64))
    view = np.atleast_2d(np.asarray(view, np.float64))
    n = max(len(uv), len(view))
    uv = np.broadcast_to(uv, (n, 2))
    view = np.broadcast_to(view[:, :3], (n, 3))
    scale = np.broadcast_to(np.asarray(scale, np.float64), (n,))
    if layers is None:
        return uv, view, scale, None
    count = np.clip(np.broadcast_to(np.asarray(layers, np.int64), (n,)), 1, MAX_LAYERS)
    return uv, view, scale, count


def layer_step(view: np.ndarray, scale: np.ndarray, count: np.ndarray) -> np.ndarray:
    """The uv shift from one layer to the next, rows (n, 2)."""
    return view[:, :2] / np.maximum(view[:, 2:3], MIN_Z) * (scale / count)[:, None]


def parallax_offset_np(height: Height, uv, view, scale) -> np.ndarray:
    """Simple parallax mapping: uv − view.xy / max(view.z, 0.1) · scale · (1 − h(uv))."""
    uv, view, scale, _ = _rows(uv, view, scale)
    depth = 1.0 - height(uv)
    return uv - view[:, :2] / np.maximum(view[:, 2:3], MIN_Z) * (scale * depth)[:, None]


def march_np(height: Height, uv, view, scale, layers) -> dict[str, np.ndarray]:
    """The layer march of steep and occlusion parallax mapping, per row.

    Returns ``steep`` and ``occlusion`` (the two functions' uv, (n, 2)), ``index`` (the first layer at or below
    the surface), ``margin`` (the smallest |surface depth − layer depth| over the layers visited, for telling
    near-ties apart from real differences; layer n, where the march ends anyway, does not count) and
    ``samples`` (height look-ups the march makes, per row).
    """
    uv, view, scale, count = _rows(uv, view, scale, layers)
    step = layer_step(view, scale, count)
    n = len(uv)
    gap = 1.0 - height(uv)  # (surface depth) - (layer depth) at layer 0
    done = gap <= 0.0
    index = np.zeros(n, np.int64)
    above = gap.copy()
    below = np.where(done, gap, 0.0)
    margin = np.abs(gap)
    for i in range(1, int(count.max()) + 1):
        active = ~done & (i <= count)
        if not active.any():
            break
        g = 1.0 - height(uv - i * step) - i / count
        # A tie at layer n changes nothing: the march ends there either way.
        margin = np.where(active & (i < count), np.minimum(margin, np.abs(g)), margin)
        hit = active & (g <= 0.0)
        index = np.where(hit, i, index)
        below = np.where(hit, g, below)
        above = np.where(active & ~hit, g, above)
        done |= hit
    # Heights outside [0, 1] only: the march ends at layer n.
    index = np.where(done, index, count)
    steep = uv - index[:, None] * step
    weight = np.where(index > 0, above / np.where(index > 0, above - below, 1.0), 0.0)
    weight = np.where(done, weight, 1.0)
    occlusion = uv - (np.maximum(index - 1, 0) + weight)[:, None] * step
    occlusion = np.where((index == 0)[:, None], uv, occlusion)
    return {"steep": steep, "occlusion": occlusion, "index": index, "margin": margin, "samples": index + 1}


def parallax_steep_np(height: Height, uv, view, scale, layers) -> np.ndarray:
    """Steep parallax mapping: uv of the first layer at or below the surface."""
    return march_np(height, uv, view, scale, layers)["steep"]


def parallax_occlusion_np(height: Height, uv, view, scale, layers) -> np.ndarray:
    """Parallax occlusion mapping: the march, then the linear interpolation between its last two layers."""
    return march_np(height, uv, view, scale, layers)["occlusion"]


def bilinear_sampler(image: np.ndarray) -> Height:
    """h(uv) of a (H, W) height map with bilinear filtering and repeat wrapping, as a GPU samples it (texel
    centres at (i + 0.5) / size, row 0 at v = 0)."""
    img = np.asarray(image, np.float64)
    rows, cols = img.shape

    def height(uv: np.ndarray) -> np.ndarray:
        x = np.asarray(uv[:, 0], np.float64) * cols - 0.5
        y = np.asarray(uv[:, 1], np.float64) * rows - 0.5
        x0, y0 = np.floor(x), np.floor(y)
        fx, fy = x - x0, y - y0
        i0, j0 = x0.astype(np.int64) % cols, y0.astype(np.int64) % rows
        i1, j1 = (i0 + 1) % cols, (j0 + 1) % rows
        top = img[j0, i0] * (1 - fx) + img[j0, i1] * fx
        bottom = img[j1, i0] * (1 - fx) + img[j1, i1] * fx
        return top * (1 - fy) + bottom * fy

    return height
