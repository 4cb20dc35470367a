"""Backend-neutral triangle meshes and the engine-wide vertex attribute locations.

A :class:`MeshData` is a validated triangle list: per-vertex arrays (positions, optional normals, UVs, tangents,
colours) and optional indices. Its :meth:`MeshData.interleaved` method packs exactly the attributes a shader
asks for into one float32 vertex buffer plus a :class:`VertexLayout` that both backends turn into their own
vertex-buffer description.

Attribute locations are fixed for the whole engine (:data:`ATTRIBUTE_LOCATIONS`), so any shader can be used with
any mesh: ``layout(location = 2) in vec2 uv`` in GLSL and ``@location(2) uv: vec2f`` in WGSL always mean the
UV set. Per-instance data (the three affine rows of the model matrix) is no vertex attribute: vertex shaders read
it from the frame's instance buffer by instance index (``instance_model()`` in ``instance.glsl``/``instance.wgsl``).

Tangent convention (the glTF one): ``tangent.xyz`` points along +u; the bitangent
``B = cross(N, tangent.xyz) * tangent.w`` points along -v, i.e. *up* the image (v = 0 is the top row). Normal maps
with green = up (OpenGL/glTF style) therefore work without flipping; DirectX-style maps (green = down) negate B.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from gandalf_core.resources.errors import ResourceError

#: The largest patch a patch mesh may have (OpenGL guarantees GL_MAX_PATCH_VERTICES >= 32).
MAX_PATCH_SIZE = 32
ATTRIBUTE_LOCATIONS: dict[str, int] = {"position": 0, "normal": 1, "uv": 2, "tangent": 3, "color": 4}

# attribute name -> (MeshData field, components)
_ATTRIBUTES: dict[str, tuple[str, int]] = {
    "position": ("positions", 3),
    "normal": ("normals", 3),
    "uv": ("uvs", 2),
    "tangent": ("tangents", 4),
    "color": ("colors", 4),
}
_FALLBACK_NORMAL = np.array([0.0, 1.0, 0.0])


@dataclass(frozen=True)
class VertexAttribute:
    """One attribute inside an interleaved vertex: its shader location, float count and byte offset."""

    name: str
    location: int
    components: int
    offset_bytes: int

    @property
    def wgpu_format(self) -> str:
        """The WebGPU vertex format name, e.g. ``"float32x3"``."""
        return "float32" if self.components == 1 else f"float32x{self.components}"

    @property
    def gl_format(self) -> str:
        """The moderngl buffer format, e.g. ``"3f"``."""
        return f"{self.components}f"


@dataclass(frozen=True)
class VertexLayout:
    """The attributes of one interleaved float32 vertex buffer and its stride in bytes."""

    attributes: tuple[VertexAttribute, ...]
    stride: int

    @property
    def floats_per_vertex(self) -> int:
        """Number of float32 values per vertex (``stride // 4``)."""
        return self.stride // 4

    @property
    def names(self) -> tuple[str, ...]:
        """The attribute names, in buffer order."""
        return tuple(a.name for a in self.attributes)


def _float_attribute(label: str, field: str, value: Any, components: int, count: int | None) -> np.ndarray:
    """Validate an (N, components) float attribute; ``count`` is the vertex count it must match."""
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise ResourceError(label, field, f"cannot convert to a float array: {exc}") from exc
    if a.ndim != 2 or a.shape[1] != components:
        raise ResourceError(label, field, f"expected shape (N, {components}), got {a.shape}")
    if count is not None and a.shape[0] != count:
        raise ResourceError(label, field, f"has {a.shape[0]} rows but the mesh has N = {count} vertices")
    with np.errstate(over="ignore"):  # values too large for float32 become inf and are reported just below
        a32 = a.astype(np.float32)
    bad = ~np.isfinite(a32)
    if bad.any():
        row, col = (int(i) for i in np.argwhere(bad)[0])
        raise ResourceError(label, field, f"{field}[{row}, {col}] = {a[row, col]} is not a finite float32")
    a32 = np.ascontiguousarray(a32)
    a32.flags.writeable = False
    return a32


def _index_array(label: str, value: Any, count: int, group: int = 3) -> np.ndarray:
    a = np.asarray(value)
    if a.dtype.kind not in "iu":
        raise ResourceError(label, "indices", f"dtype {a.dtype} is not an integer type")
    if not (a.ndim == 1 or (a.ndim == 2 and a.shape[1] == group)):
        raise ResourceError(label, "indices", f"expected shape (M,) or (M/{group}, {group}), got {a.shape}")
    flat = a.reshape(-1).astype(np.int64)
    if flat.size == 0 or flat.size % group:
        raise ResourceError(label, "indices", f"index count {flat.size} is not a positive multiple of {group}")
    bad = (flat < 0) | (flat >= count)
    if bad.any():
        i = int(np.argmax(bad))
        raise ResourceError(label, "indices", f"indices[{i}] = {int(flat[i])} is out of range for {count} vertices")
    out = np.ascontiguousarray(flat.astype(np.uint32))
    out.flags.writeable = False
    return out


def _normalize_rows(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unit rows of ``v`` and a mask of rows that had a usable length (others are left as zero)."""
    length = np.linalg.norm(v, axis=1)
    ok = length > 1e-30
    out = np.zeros_like(v)
    out[ok] = v[ok] / length[ok, None]
    return out, ok


def _any_perpendicular(n: np.ndarray) -> np.ndarray:
    """A unit vector perpendicular to each unit row of ``n``: +X made orthogonal, or +Z where n is near ±X."""
    axis = np.where(np.abs(n[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]])
    t = axis - n * np.sum(n * axis, axis=1, keepdims=True)
    return t / np.linalg.norm(t, axis=1, keepdims=True)


@dataclass(frozen=True, eq=False)
class MeshData:
    """A triangle-list mesh; every ``(N, k)`` attribute has one row per vertex.

    Arrays are converted on construction (float32 attributes, ``uint32`` flattened indices), made read-only and
    validated: shapes, matching lengths, finite values, indices in range and a multiple of 3. Without indices the
    vertices themselves form the triangles (three per triangle). Methods return new meshes.

    With ``patch_size`` set (1 to :data:`MAX_PATCH_SIZE`) the mesh is a **patch mesh** for tessellation: the indices
    (or the vertices) form patches of that many control points instead of triangles. Only a program with a
    tessellation control stage whose ``layout(vertices = N) out`` has the same N can draw it (OpenGL).

    With ``indirect`` set (the name of a buffer of the renderer's buffer library, 16 bytes or more) the mesh is
    drawn **indirectly**: the GPU reads the vertex count from the buffer's first ``uint32``, which the app's own
    compute pass writes, so a compute pass decides how much is drawn without a read-back (the renderer writes the
    other three: the instance count, first vertex 0, first instance 0; batches that share the buffer in a frame
    need the same instance count). Its vertices are then placeholders for shaders that pull their data
    themselves; it has no indices and no patches.
    """

    positions: np.ndarray
    normals: np.ndarray | None = None
    uvs: np.ndarray | None = None
    tangents: np.ndarray | None = None
    colors: np.ndarray | None = None
    indices: np.ndarray | None = None
    name: str = "mesh"
    patch_size: int | None = None
    indirect: str | None = None

    def __post_init__(self) -> None:
        label = self._label
        if self.indirect is not None:
            if not isinstance(self.indirect, str) or not self.indirect:
                raise ResourceError(label, "indirect", f"expected the name of a buffer, got {self.indirect!r}")
            if self.indices is not None or self.patch_size is not None:
                raise ResourceError(label, "indirect", "an indirectly drawn mesh has no indices and no patches: the "
                                    "compute pass that writes its vertex count writes the vertices in order")
        positions = _float_attribute(label, "positions", self.positions, 3, None)
        n = positions.shape[0]
        if n == 0:
            raise ResourceError(label, "positions", "the mesh has no vertices")
        object.__setattr__(self, "positions", positions)
        for attr, (field, components) in _ATTRIBUTES.items():
            value = getattr(self, field)
            if attr != "position" and value is not None:
                object.__setattr__(self, field, _float_attribute(label, field, value, components, n))
        group = 3
        if self.patch_size is not None:
            size = self.patch_size
            if isinstance(size, bool) or not isinstance(size, (int, np.integer)) or not 1 <= size <= MAX_PATCH_SIZE:
                detail = f"expected an integer from 1 to {MAX_PATCH_SIZE}, got {size!r}"
                raise ResourceError(label, "patch_size", detail)
            group = int(size)
            object.__setattr__(self, "patch_size", group)
        if self.indices is not None:
            object.__setattr__(self, "indices", _index_array(label, self.indices, n, group))
        elif n % group:
            whole = "whole triangles" if group == 3 and self.patch_size is None else f"whole patches of {group}"
            raise ResourceError(label, "positions", f"{n} vertices without indices do not form {whole}")

    @property
    def _label(self) -> str:
        return f"mesh '{self.name}'"

    @property
    def vertex_count(self) -> int:
        """Number of vertices N."""
        return int(self.positions.shape[0])

    @property
    def index_count(self) -> int:
        """Number of indices, 0 for a non-indexed mesh (draw ``vertex_count`` vertices then)."""
        return 0 if self.indices is None else int(self.indices.shape[0])

    @property
    def triangle_count(self) -> int:
        """Number of triangles (of a patch mesh: 0, its patches become triangles only on the GPU)."""
        return 0 if self.patch_size is not None else (self.index_count or self.vertex_count) // 3

    @property
    def patch_count(self) -> int:
        """Number of patches of a patch mesh (0 for a triangle mesh)."""
        return 0 if self.patch_size is None else (self.index_count or self.vertex_count) // self.patch_size

    def triangles(self) -> np.ndarray:
        """Vertex indices of every triangle, shape (T, 3) ``uint32`` (consecutive vertices when non-indexed)."""
        if self.patch_size is not None:
            raise ResourceError(self._label, "patch_size",
                                f"a patch mesh (patches of {self.patch_size}) has no triangles until it is tessellated")
        if self.indices is None:
            return np.arange(self.vertex_count, dtype=np.uint32).reshape(-1, 3)
        return self.indices.reshape(-1, 3)

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Axis-aligned bounding box ``(min, max)`` of the positions, float64 arrays of shape (3,)."""
        p = self.positions.astype(np.float64)
        return p.min(axis=0), p.max(axis=0)

    def _replace(self, **fields: Any) -> MeshData:
        current = {f: getattr(self, f) for f in ("positions", "normals", "uvs", "tangents", "colors", "indices")}
        return MeshData(**{**current, **fields}, name=self.name, patch_size=self.patch_size, indirect=self.indirect)

    def with_normals(self, recompute: bool = False) -> MeshData:
        """This mesh with smooth, area-weighted vertex normals (kept as they are unless absent or ``recompute``).

        Each triangle adds its unnormalised face normal ``(b - a) x (c - a)`` (length = twice its area) to its
        three vertices, so degenerate triangles add nothing. A vertex with no usable triangle gets (0, 1, 0).
        Vertices shared by triangles are smoothed; split vertices (a cube's 24) keep hard edges.
        """
        if self.normals is not None and not recompute:
            return self
        p = self.positions.astype(np.float64)
        tri = self.triangles().astype(np.int64)
        face = np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]])
        acc = np.zeros_like(p)
        for k in range(3):
            np.add.at(acc, tri[:, k], face)
        normals, ok = _normalize_rows(acc)
        normals[~ok] = _FALLBACK_NORMAL
        return self._replace(normals=normals)

    def with_tangents(self, recompute: bool = False) -> MeshData:
        """This mesh with per-vertex tangents (xyz + handedness w) derived from the UVs (Lengyel's method).

        Per triangle the directions of +u and -v are solved from the edge and UV deltas, normalised and
        weighted by the triangle's area; per vertex the sum is made orthogonal to the normal (Gram-Schmidt) and
        ``w = ±1`` records whether ``cross(N, T)`` points along -v (see the module docstring). Triangles with
        degenerate UVs add nothing; a vertex left without a tangent gets a stable one perpendicular to its normal
        (``w = 1``). Normals are computed first when absent. Requires ``uvs``.
        """
        if self.tangents is not None and not recompute:
            return self
        if self.uvs is None:
            raise ResourceError(self._label, "uvs", "tangents need texture coordinates, but the mesh has no uvs")
        mesh = self.with_normals()
        p = mesh.positions.astype(np.float64)
        uv = mesh.uvs.astype(np.float64)
        n = mesh.normals.astype(np.float64)
        tri = mesh.triangles().astype(np.int64)
        e1 = p[tri[:, 1]] - p[tri[:, 0]]
        e2 = p[tri[:, 2]] - p[tri[:, 0]]
        d1 = uv[tri[:, 1]] - uv[tri[:, 0]]
        d2 = uv[tri[:, 2]] - uv[tri[:, 0]]
        det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
        scale = np.abs(d1[:, 0] * d2[:, 1]) + np.abs(d2[:, 0] * d1[:, 1])
        valid = np.abs(det) > 1e-9 * np.maximum(scale, 1e-300)
        sign = np.where(valid, np.sign(det), 0.0)[:, None]
        # The directions only, without dividing by a possibly tiny det; the weight is the geometric area.
        t_dir, _ = _normalize_rows((e1 * d2[:, 1:2] - e2 * d1[:, 1:2]) * sign)
        b_dir, _ = _normalize_rows(-(e2 * d1[:, 0:1] - e1 * d2[:, 0:1]) * sign)  # along -v
        area = 0.5 * np.linalg.norm(np.cross(e1, e2), axis=1)[:, None]
        t_acc = np.zeros_like(p)
        b_acc = np.zeros_like(p)
        for k in range(3):
            np.add.at(t_acc, tri[:, k], t_dir * area)
            np.add.at(b_acc, tri[:, k], b_dir * area)
        t_acc -= n * np.sum(n * t_acc, axis=1, keepdims=True)
        tangent, ok = _normalize_rows(t_acc)
        tangent[~ok] = _any_perpendicular(n[~ok])
        w = np.where(np.sum(np.cross(n, tangent) * b_acc, axis=1) < 0.0, -1.0, 1.0)
        return mesh._replace(tangents=np.concatenate([tangent, w[:, None]], axis=1))

    def interleaved(self, attributes: Sequence[str] = ("position", "normal", "uv")) -> tuple[np.ndarray, VertexLayout]:
        """Pack the requested attributes into one float32 array of shape (N, floats_per_vertex).

        ``attributes`` are names from :data:`ATTRIBUTE_LOCATIONS`, in the order they should appear in the
        buffer; ask for what the shader reads. A requested attribute the mesh lacks raises
        :class:`ResourceError` naming it (call :meth:`with_normals`/:meth:`with_tangents` first).
        """
        if isinstance(attributes, str):
            attributes = (attributes,)
        columns = []
        layout = []
        offset = 0
        for attr in attributes:
            if attr not in _ATTRIBUTES:
                allowed = ", ".join(repr(a) for a in _ATTRIBUTES)
                raise ResourceError(self._label, "attributes", f"unknown attribute {attr!r}; allowed: {allowed}")
            if attr in (a.name for a in layout):
                raise ResourceError(self._label, "attributes", f"attribute {attr!r} is requested twice")
            field, components = _ATTRIBUTES[attr]
            value = getattr(self, field)
            if value is None:
                raise ResourceError(self._label, field, f"the shader needs attribute {attr!r} but the mesh has none")
            columns.append(value)
            layout.append(VertexAttribute(attr, ATTRIBUTE_LOCATIONS[attr], components, offset))
            offset += 4 * components
        if not columns:
            raise ResourceError(self._label, "attributes", "no attributes requested")
        data = np.ascontiguousarray(np.concatenate(columns, axis=1), dtype=np.float32)
        return data, VertexLayout(tuple(layout), offset)
