"""Procedural meshes: triangle, quad, cube, pyramid, plane, UV sphere and torus.

All of them are right-handed with +Y up, their front faces wind **counter-clockwise seen from outside**, and they
carry normals, UVs and tangents (see :mod:`gandalf_core.resources.mesh_data` for the tangent convention).

UV convention: ``v = 0`` is the **top** row of the image. Textures store their rows top-first
(:mod:`gandalf_core.resources.texture_data`), so uv (0, 0) samples the top-left texel, and a texture on a quad,
a cube face or a sphere appears upright when seen from outside. Both backends agree on this, so no shader
flips v.
"""

from __future__ import annotations

import numpy as np

from gandalf_core.resources.errors import ResourceError
from gandalf_core.resources.mesh_data import MeshData


def _positive(name: str, field: str, value: float) -> float:
    v = float(value)
    if not (np.isfinite(v) and v > 0.0):
        raise ResourceError(f"mesh '{name}'", field, f"must be a positive finite number, got {value!r}")
    return v


def _count(name: str, field: str, value: int, minimum: int) -> int:
    if int(value) != value or value < minimum:
        raise ResourceError(f"mesh '{name}'", field, f"must be an integer >= {minimum}, got {value!r}")
    return int(value)


def _grid_indices(rows: int, cols: int) -> np.ndarray:
    """Two CCW triangles per cell of a (rows+1) x (cols+1) vertex grid laid out row-major.

    Vertex (i, j) sits at row i (down the texture, v grows) and column j (right, u grows); seen from the front
    the triangles (a, b, c) and (a, c, d) with a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1) wind
    counter-clockwise because rows go down and columns go right.
    """
    i, j = np.meshgrid(np.arange(rows), np.arange(cols), indexing="ij")
    a = (i * (cols + 1) + j).ravel()
    b = a + cols + 1
    c = b + 1
    d = a + 1
    return np.stack([np.stack([a, b, c], 1), np.stack([a, c, d], 1)], 1).reshape(-1, 3)


def triangle() -> MeshData:
    """The classic first triangle in the XY plane facing +Z, with red, green and blue corner colours."""
    positions = [[-0.5, -0.5, 0.0], [0.5, -0.5, 0.0], [0.0, 0.5, 0.0]]
    colors = [[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0]]
    uvs = [[0.0, 1.0], [1.0, 1.0], [0.5, 0.0]]
    normals = [[0.0, 0.0, 1.0]] * 3
    return MeshData(positions, normals=normals, uvs=uvs, colors=colors, name="triangle").with_tangents()


def quad(size: float = 1.0) -> MeshData:
    """A square of edge ``size`` in the XY plane centred on the origin, facing +Z; 4 vertices, 6 indices."""
    h = _positive("quad", "size", size) / 2.0
    positions = [[-h, -h, 0.0], [h, -h, 0.0], [h, h, 0.0], [-h, h, 0.0]]
    uvs = [[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]]
    normals = [[0.0, 0.0, 1.0]] * 4
    return MeshData(positions, normals=normals, uvs=uvs, indices=[0, 1, 2, 0, 2, 3], name="quad").with_tangents()


# For each cube face: outward normal, then the directions of +u (right) and of image-up (-v) seen from outside.
_CUBE_FACES = (
    ((1, 0, 0), (0, 0, -1), (0, 1, 0)),
    ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    ((0, 1, 0), (1, 0, 0), (0, 0, -1)),
    ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
    ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
)


def cube(size: float = 1.0) -> MeshData:
    """An axis-aligned cube of edge ``size`` centred on the origin: 24 vertices (4 per face), flat normals.

    Each face maps the whole texture (UVs 0..1) upright when seen from outside; the top face's image-up points
    to -Z and the bottom face's to +Z.
    """
    h = _positive("cube", "size", size) / 2.0
    positions, normals, uvs, indices = [], [], [], []
    corners = ((-1, -1, (0.0, 1.0)), (1, -1, (1.0, 1.0)), (1, 1, (1.0, 0.0)), (-1, 1, (0.0, 0.0)))
    for f, (n, right, up) in enumerate(_CUBE_FACES):
        n, right, up = np.array(n, float), np.array(right, float), np.array(up, float)
        for su, sv, uv in corners:
            positions.append((n + su * right + sv * up) * h)
            normals.append(n)
            uvs.append(uv)
        base = 4 * f
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return MeshData(positions, normals=normals, uvs=uvs, indices=indices, name="cube").with_tangents()


def pyramid(base: float = 1.0, height: float = 1.0) -> MeshData:
    """A square pyramid: base of edge ``base`` centred on the origin in the y = 0 plane, apex at (0, height, 0).

    Four triangular sides with flat normals (3 vertices each) and a two-triangle base facing -Y: 16 vertices.
    Standing on y = 0 makes it easy to put on top of something, e.g. as the roof of a house.
    """
    h = _positive("pyramid", "base", base) / 2.0
    top = _positive("pyramid", "height", height)
    apex = np.array([0.0, top, 0.0])
    # Base corners in counter-clockwise order seen from above, starting front-left.
    ring = np.array([[-h, 0.0, h], [h, 0.0, h], [h, 0.0, -h], [-h, 0.0, -h]])
    positions, normals, uvs = [], [], []
    for k in range(4):
        a, b = ring[k], ring[(k + 1) % 4]
        n = np.cross(b - a, apex - a)
        positions += [a, b, apex]
        normals += [n / np.linalg.norm(n)] * 3
        uvs += [(0.0, 1.0), (1.0, 1.0), (0.5, 0.0)]
    # Base seen from below: front-left, back-left, back-right, front-right is counter-clockwise.
    positions += [ring[0], ring[3], ring[2], ring[1]]
    normals += [(0.0, -1.0, 0.0)] * 4
    uvs += [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]
    indices = list(range(12)) + [12, 13, 14, 12, 14, 15]
    return MeshData(positions, normals=normals, uvs=uvs, indices=indices, name="pyramid").with_tangents()


def plane(size: float = 1.0, subdivisions: int = 1) -> MeshData:
    """A square of edge ``size`` in the XZ plane facing +Y, split into ``subdivisions``² cells.

    UVs span 0..1 over the whole plane; seen from above with -Z up, the texture is upright.
    """
    s = _positive("plane", "size", size)
    n = _count("plane", "subdivisions", subdivisions, 1)
    t = np.linspace(0.0, 1.0, n + 1)
    v, u = np.meshgrid(t, t, indexing="ij")  # rows run from z = -size/2 (image top) to +size/2
    positions = np.stack([(u - 0.5) * s, np.zeros_like(u), (v - 0.5) * s], -1).reshape(-1, 3)
    normals = np.tile([0.0, 1.0, 0.0], (len(positions), 1))
    uvs = np.stack([u, v], -1).reshape(-1, 2)
    return MeshData(positions, normals=normals, uvs=uvs, indices=_grid_indices(n, n), name="plane").with_tangents()


def uv_sphere(radius: float = 1.0, segments: int = 32, rings: int = 16) -> MeshData:
    """A sphere of ``radius`` around the origin with ``segments`` columns and ``rings`` rows of quads.

    u runs once around (starting at +Z, moving towards +X, i.e. left to right seen from outside), v from the
    north pole (v = 0) to the south pole, so an equirectangular image appears upright. The seam column is
    duplicated for the UV wrap; each pole has one vertex per column (u at the column's middle), so the pole
    rows are single triangles without degenerate ones.
    """
    r = _positive("uv_sphere", "radius", radius)
    cols = _count("uv_sphere", "segments", segments, 3)
    rows = _count("uv_sphere", "rings", rings, 2)
    v, u = np.meshgrid(np.linspace(0.0, 1.0, rows + 1), np.linspace(0.0, 1.0, cols + 1), indexing="ij")
    # Each pole vertex serves one column only (north: column j, south: column j - 1): sample that column's middle.
    u[0] += 0.5 / cols
    u[-1] -= 0.5 / cols
    theta, phi = v * np.pi, u * 2.0 * np.pi
    normals = np.stack([np.sin(theta) * np.sin(phi), np.cos(theta), np.sin(theta) * np.cos(phi)], -1)
    normals[0], normals[-1] = (0.0, 1.0, 0.0), (0.0, -1.0, 0.0)  # exact poles, whatever phi says
    tris = _grid_indices(rows, cols).reshape(rows, cols, 2, 3)
    # Row 0's second triangle (a, c, d) has a and d on the north pole; the last row's first (a, b, c) has b and c
    # on the south pole: both are degenerate.
    keep = np.ones((rows, cols, 2), dtype=bool)
    keep[0, :, 1] = False
    keep[-1, :, 0] = False
    indices = tris[keep]
    # One pole vertex per pole belongs to no kept triangle (north: the last column, south: the first): drop them.
    used = np.ones(normals.shape[:2], dtype=bool)
    used[0, -1] = used[-1, 0] = False
    remap = np.cumsum(used.ravel()) - 1
    normals = normals[used]
    uvs = np.stack([u, v], -1)[used]
    return MeshData(normals * r, normals=normals, uvs=uvs, indices=remap[indices], name="uv_sphere").with_tangents()


def torus(
    major_radius: float = 1.0, minor_radius: float = 0.25, major_segments: int = 32, minor_segments: int = 16
) -> MeshData:
    """A torus around the Y axis: its tube of ``minor_radius`` circles the origin at ``major_radius`` in XZ.

    u runs once around the Y axis (from +Z towards +X), v once around the tube, starting at the outer equator,
    going down and under, and coming back over the top (on the outer side v grows downwards, so images there
    stay upright).
    """
    big = _positive("torus", "major_radius", major_radius)
    small = _positive("torus", "minor_radius", minor_radius)
    if small >= big:
        raise ResourceError(
            "mesh 'torus'", "minor_radius", f"{small} must be smaller than major_radius {big} (else it self-intersects)"
        )
    cols = _count("torus", "major_segments", major_segments, 3)
    rows = _count("torus", "minor_segments", minor_segments, 3)
    # Row i sits at tube angle 2*pi*(1 - i/rows): rows 0 and `rows` meet at the outer equator, and walking down the
    # rows first moves downwards on the outer side, so image-down is world-down there, as on the sphere.
    v, u = np.meshgrid(np.linspace(0.0, 1.0, rows + 1), np.linspace(0.0, 1.0, cols + 1), indexing="ij")
    phi, theta = u * 2.0 * np.pi, (1.0 - v) * 2.0 * np.pi
    radial = np.stack([np.sin(phi), np.zeros_like(phi), np.cos(phi)], -1)
    up = np.array([0.0, 1.0, 0.0])
    normals = np.cos(theta)[..., None] * radial + np.sin(theta)[..., None] * up
    positions = big * radial + small * normals
    uvs = np.stack([u, v], -1).reshape(-1, 2)
    return MeshData(
        positions.reshape(-1, 3),
        normals=normals.reshape(-1, 3),
        uvs=uvs,
        indices=_grid_indices(rows, cols),
        name="torus",
    ).with_tangents()
