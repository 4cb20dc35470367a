"""A bounding volume hierarchy over triangles, built on the CPU with numpy (float64) and flattened for the GPU.

Build: a binned surface-area heuristic (SAH) split along the longest axis of the triangle centroids' box, with
:data:`BINS` bins; a node with at most :data:`LEAF_SIZE` triangles, or one that no split makes cheaper, is a
leaf. Flattened depth-first: an inner node's left child is the next node, so a node stores only its right child.

GPU layout (two ``vec4`` per node, float32, integers stored as exact floats below 2^24):

    (bmin.x, bmin.y, bmin.z, first triangle | right child)   (bmax.x, bmax.y, bmax.z, triangle count; 0 = inner)

The boxes are rounded outwards to float32, so a float32 triangle never pokes out of its float32 box. The shader
walks the tree with a short stack of :data:`MAX_DEPTH` entries (``trace.glsl`` / ``trace.wgsl``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from gandalf_core.resources import ResourceError

LEAF_SIZE = 4
BINS = 12
#: The shaders' traversal stack holds 32 entries; a depth-first walk needs at most depth + 1 of them.
MAX_DEPTH = 30
#: Triangles whose doubled area is below this fraction of the squared size of the mesh are dropped as degenerate.
DEGENERATE = 1e-14
#: Cost of visiting a node relative to testing one triangle (SAH).
TRAVERSAL_COST = 1.0


@dataclass(frozen=True)
class BVH:
    """``nodes`` (N, 8) float64 as laid out above, ``order`` the triangle indices in leaf order, ``depth``."""

    nodes: np.ndarray
    order: np.ndarray
    depth: int

    def packed(self) -> np.ndarray:
        """The nodes as float32 (N·2, 4) for upload, boxes rounded outwards."""
        out = np.empty((len(self.nodes), 8), np.float32)
        lo = self.nodes[:, 0:3].astype(np.float32)
        hi = self.nodes[:, 4:7].astype(np.float32)
        lo = np.where(lo.astype(np.float64) > self.nodes[:, 0:3], np.nextafter(lo, np.float32(-np.inf)), lo)
        hi = np.where(hi.astype(np.float64) < self.nodes[:, 4:7], np.nextafter(hi, np.float32(np.inf)), hi)
        out[:, 0:3], out[:, 4:7] = lo, hi
        out[:, 3], out[:, 7] = self.nodes[:, 3], self.nodes[:, 7]
        return out.reshape(-1, 4)


def triangle_areas(triangles: np.ndarray) -> np.ndarray:
    """Areas of (T, 3, 3) float64 triangles."""
    t = np.asarray(triangles, np.float64)
    return 0.5 * np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1)


def usable_triangles(triangles: np.ndarray, label: str = "mesh") -> np.ndarray:
    """Indices of the triangles that are finite and not degenerate (zero area); a ResourceError naming ``label``
    when there are none (an empty mesh, or only zero-area triangles)."""
    t = np.asarray(triangles, np.float64)
    if t.ndim != 3 or t.shape[1:] != (3, 3):
        raise ResourceError(label, "triangles", f"expected an array of shape (T, 3, 3), got {t.shape}")
    if len(t) == 0:
        raise ResourceError(label, "triangles", "a BVH needs at least one triangle; the mesh has none")
    finite = np.all(np.isfinite(t), axis=(1, 2))
    if not np.all(finite):
        raise ResourceError(label, "positions", f"{int(np.sum(~finite))} triangle(s) have non-finite corners")
    extent = float(np.ptp(t.reshape(-1, 3), axis=0).max())
    doubled = 2.0 * triangle_areas(t)
    keep = np.flatnonzero(doubled > DEGENERATE * max(extent, 1e-300) ** 2)
    if len(keep) == 0:
        raise ResourceError(label, "triangles", f"all {len(t)} triangle(s) have zero area (degenerate): "
                                                "a BVH over them would hit nothing")
    return keep


def _area(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    e = np.maximum(hi - lo, 0.0)
    return 2.0 * (e[..., 0] * e[..., 1] + e[..., 1] * e[..., 2] + e[..., 2] * e[..., 0])


def build_bvh(triangles: np.ndarray, label: str = "mesh") -> BVH:
    """The BVH over ``triangles`` (T, 3, 3) float64 world-space corners (degenerate ones must be removed first:
    see :func:`usable_triangles`). Raises a ResourceError naming ``label`` for an empty input or a tree deeper
    than :data:`MAX_DEPTH`."""
    t = np.asarray(triangles, np.float64)
    if t.ndim != 3 or t.shape[1:] != (3, 3) or len(t) == 0:
        raise ResourceError(label, "triangles", f"a BVH needs (T, 3, 3) corners with T >= 1, got shape {t.shape}")
    tri_lo, tri_hi = t.min(axis=1), t.max(axis=1)
    centroids = t.mean(axis=1)
    nodes: list[list[float]] = []
    order: list[np.ndarray] = []
    placed = 0
    depth_seen = 0
    # An explicit stack of (triangle indices, depth, parent whose right child this is, or -1) instead of recursion.
    work: list[tuple[np.ndarray, int, int]] = [(np.arange(len(t)), 0, -1)]
    while work:
        idx, depth, parent = work.pop()
        if depth > MAX_DEPTH:
            raise ResourceError(label, "triangles", f"the BVH is deeper than {MAX_DEPTH} levels (the shaders' "
                                                    "traversal stack): too many coincident triangles")
        depth_seen = max(depth_seen, depth)
        node = len(nodes)
        if parent >= 0:
            nodes[parent][3] = float(node)  # the right child (the left one is parent + 1)
        lo, hi = tri_lo[idx].min(axis=0), tri_hi[idx].max(axis=0)
        split = _split(idx, centroids, tri_lo, tri_hi, lo, hi) if len(idx) > LEAF_SIZE else None
        if split is None:
            nodes.append([*lo, float(placed), *hi, float(len(idx))])
            order.append(idx)
            placed += len(idx)
            continue
        left, right = split
        nodes.append([*lo, 0.0, *hi, 0.0])
        # Depth-first, left first: push the right child below the left one.
        work.append((right, depth + 1, node))
        work.append((left, depth + 1, -1))
    return BVH(np.array(nodes, np.float64), np.concatenate(order), depth_seen)


def _split(idx: np.ndarray, centroids: np.ndarray, tri_lo: np.ndarray, tri_hi: np.ndarray, lo: np.ndarray,
           hi: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """The binned-SAH split of ``idx`` (or a median split when all centroids coincide on every axis); None
    when a leaf is cheaper."""
    c = centroids[idx]
    c_lo, c_hi = c.min(axis=0), c.max(axis=0)
    axis = int(np.argmax(c_hi - c_lo))
    extent = c_hi[axis] - c_lo[axis]
    if extent <= 0.0:
        half = len(idx) // 2
        return (idx[:half], idx[half:]) if len(idx) > 2 * LEAF_SIZE else None
    bins = np.minimum(((c[:, axis] - c_lo[axis]) / extent * BINS).astype(int), BINS - 1)
    b_lo = np.full((BINS, 3), np.inf)
    b_hi = np.full((BINS, 3), -np.inf)
    np.minimum.at(b_lo, bins, tri_lo[idx])
    np.maximum.at(b_hi, bins, tri_hi[idx])
    counts = np.bincount(bins, minlength=BINS)
    # Left side = bins [0, k], right side = bins (k, BINS): prefix and suffix boxes and counts.
    left_lo, left_hi = np.minimum.accumulate(b_lo), np.maximum.accumulate(b_hi)
    right_lo = np.minimum.accumulate(b_lo[::-1])[::-1]
    right_hi = np.maximum.accumulate(b_hi[::-1])[::-1]
    n_left = np.cumsum(counts)[:-1]
    n_right = len(idx) - n_left
    cost = (_area(left_lo[:-1], left_hi[:-1]) * n_left + _area(right_lo[1:], right_hi[1:]) * n_right)
    cost = np.where((n_left > 0) & (n_right > 0), cost, np.inf)
    k = int(np.argmin(cost))
    parent_area = _area(lo, hi)
    if not np.isfinite(cost[k]):
        return None
    split_cost = TRAVERSAL_COST + cost[k] / max(parent_area, 1e-300)
    if split_cost >= len(idx) and len(idx) <= 4 * LEAF_SIZE:
        return None
    mask = bins <= k
    return idx[mask], idx[~mask]


def closest_hit_np(bvh: BVH, triangles: np.ndarray, origin: np.ndarray, direction: np.ndarray,
                   t_min: float = 1e-4) -> tuple[float, int]:
    """(t, triangle index) of the closest hit of one ray through the BVH (float64, for tests); (inf, -1) for none.
    ``triangles`` are the ones the BVH was built over (original order)."""
    o = np.asarray(origin, np.float64)
    d = np.asarray(direction, np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / np.where(np.abs(d) < 1e-300, 1e-300, d)
    best, best_i = np.inf, -1
    stack = [0]
    while stack:
        i = stack.pop()
        n = bvh.nodes[i]
        t0, t1 = (n[0:3] - o) * inv, (n[4:7] - o) * inv
        enter = max(np.minimum(t0, t1).max(), t_min)
        leave = min(np.maximum(t0, t1).min(), best)
        if enter > leave:
            continue
        if n[7] == 0:
            stack += [int(n[3]), i + 1]
            continue
        for k in bvh.order[int(n[3]):int(n[3]) + int(n[7])]:
            t = _triangle_np(o, d, triangles[k], t_min, best)
            if t < best:
                best, best_i = t, int(k)
    return best, best_i


def _triangle_np(o: np.ndarray, d: np.ndarray, tri: np.ndarray, t_min: float, t_max: float) -> float:
    e1, e2 = tri[1] - tri[0], tri[2] - tri[0]
    p = np.cross(d, e2)
    det = float(e1 @ p)
    if abs(det) < 1e-300:
        return np.inf
    tv = o - tri[0]
    u = float(tv @ p) / det
    q = np.cross(tv, e1)
    v = float(d @ q) / det
    t = float(e2 @ q) / det
    return t if (u >= 0 and v >= 0 and u + v <= 1 and t_min < t < t_max) else np.inf
