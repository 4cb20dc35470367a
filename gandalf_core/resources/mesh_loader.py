"""Meshes from files: OBJ, glTF/GLB, PLY and STL through trimesh, as validated :class:`MeshData`.

``load_meshes(path)`` returns one mesh per part of the file (the objects of an OBJ, the mesh nodes of a glTF
scene with their node transforms applied); ``load_mesh(path)`` merges all parts into one. Every mesh gets
vertex normals (smooth, area-weighted, computed when the file has none), keeps its UVs (converted to the
engine's convention, v = 0 at the top of the image) and then gets tangents, and keeps vertex colours.
Degenerate triangles (repeated or collinear corners) are dropped, so they never produce NaN normals.

Results are cached by (resolved path, content hash): loading an unchanged file again returns the same immutable
objects; a file rewritten with other bytes loads anew, even when its size and modification time did not change
(the hash reads the file, which costs far less than parsing it). For a ``.gltf`` with separate ``.bin`` or image
files only the ``.gltf`` itself is hashed. trimesh is imported only when a file is read.
"""

from __future__ import annotations

import hashlib
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from gandalf_core.resources.confine import inside_folder
from gandalf_core.resources.errors import MeshFileWarning, ResourceError
from gandalf_core.resources.mesh_data import MeshData

#: File extensions the loader reads (lower case, with the dot).
MESH_EXTENSIONS = (".obj", ".gltf", ".glb", ".ply", ".stl")

_cache: dict[tuple[str, str, bool], dict[str, MeshData]] = {}
_merged_cache: dict[tuple[str, str, bool], MeshData] = {}
#: The MeshFileWarnings each cached file gave when it was read: every load of it gives them again.
_warnings: dict[tuple[str, str, bool], list[str]] = {}


def clear_cache() -> None:
    """Forget every loaded file (the next load reads from disk again)."""
    _cache.clear()
    _merged_cache.clear()
    _warnings.clear()


def _read_once(key: tuple[str, str, bool], label: str, allow_outside: bool) -> None:
    """Read the file of ``key`` into the cache unless it is there; its MeshFileWarnings (given now) are kept to
    be given again by every later load, which the cache would otherwise keep quiet."""
    if key in _cache:
        for message in _warnings.get(key, ()):
            warnings.warn(message, MeshFileWarning, stacklevel=3)
        return
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", MeshFileWarning)
        _cache[key] = _read(Path(key[0]), label, allow_outside)
    _warnings[key] = [str(w.message) for w in caught if issubclass(w.category, MeshFileWarning)]
    for w in caught:
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno, source=w.source)


def load_meshes(path: str | Path, *, allow_outside: bool = False) -> dict[str, MeshData]:
    """One :class:`MeshData` per part of the file at ``path``, by part name, in file order.

    Raises :class:`ResourceError` naming the file when it is missing, has an unsupported extension, cannot be
    parsed, or holds no triangles. Repeated calls for an unchanged file return the cached result. Files the
    file names (an OBJ's material library and its images, a glTF's buffers and images) are read only from the
    file's folder (after following symlinks) unless ``allow_outside``.
    """
    key, label = _key(path, allow_outside)
    _read_once(key, label, allow_outside)
    return dict(_cache[key])


def load_mesh(path: str | Path, *, allow_outside: bool = False) -> MeshData:
    """All parts of the file at ``path`` merged into one :class:`MeshData` (named after the file's stem).

    An attribute (UVs, colours) survives the merge only when every part has it; normals are always present.
    """
    key, label = _key(path, allow_outside)
    _read_once(key, label, allow_outside)
    if key not in _merged_cache:
        _merged_cache[key] = _merge(list(_cache[key].values()), Path(key[0]).stem, label)
    return _merged_cache[key]


def _key(path: str | Path, allow_outside: bool = False) -> tuple[tuple[str, str, bool], str]:
    """The cache key of ``path`` and the label errors use; checks existence and extension first."""
    p = Path(path)
    label = f"mesh file '{p}'"
    if p.suffix.lower() not in MESH_EXTENSIONS:
        allowed = ", ".join(MESH_EXTENSIONS)
        raise ResourceError(label, "path", f"unsupported extension {p.suffix or '(none)'!r}; supported: {allowed}")
    try:
        resolved = p.resolve(strict=True)
    except OSError:
        raise ResourceError(label, "path", "file not found") from None
    if not resolved.is_file():
        raise ResourceError(label, "path", "is not a file")
    try:
        digest = hashlib.blake2b(resolved.read_bytes(), digest_size=16).hexdigest()
    except OSError as exc:
        raise ResourceError(label, "path", f"cannot read the file: {exc}") from None
    return (str(resolved), digest, allow_outside), label


def _check_obj_files(path: Path, label: str, allow_outside: bool) -> None:
    """An OBJ's material library and the images it names, read as trimesh reads them (the rest of the first
    ``mtllib`` line; the rest of each ``map_Kd`` line), must lie in the OBJ's folder unless ``allow_outside``:
    trimesh's own resolver refuses them too, but then drops the materials without a word."""
    text = path.read_text(errors="replace")
    at = text.find("mtllib")
    if at < 0:
        return
    end = text.find("\n", at)
    name = text[at + 6: end if end >= 0 else len(text)].strip()
    library = inside_folder(path, name, label, "mtllib", "the material library", allow_outside)
    if not library.is_file():
        return
    for number, line in enumerate(library.read_text(errors="replace").splitlines(), 1):
        words = line.strip().split()
        if len(words) > 1 and words[0].lower() == "map_kd":
            image = line[line.lower().index("map_kd") + 6:].strip()
            inside_folder(path, image, label, f"mtllib '{name}' line {number} (map_Kd)", "the image", allow_outside)


def _trimesh_load(path: Path, allow_outside: bool) -> Any:
    """trimesh's scene of ``path``; the files it names are read through a resolver confined to its folder (trimesh's
    own rule: paths resolved, symlinks followed) unless ``allow_outside``, and an OBJ's are checked first (a
    :class:`ResourceError` naming the file, the line and the path)."""
    import trimesh
    from trimesh.resolvers import FilePathResolver

    if path.suffix.lower() == ".obj":
        _check_obj_files(path, f"mesh file '{path}'", allow_outside)

    # process=False keeps the file's vertex order and UV seams; OBJ objects stay separate parts.
    return trimesh.load(str(path), process=False, split_objects=True, group_material=False,
                        resolver=FilePathResolver(str(path), allow_anywhere=allow_outside))


def _read(path: Path, label: str, allow_outside: bool = False) -> dict[str, MeshData]:
    if path.stat().st_size == 0:
        raise ResourceError(label, "contents", "the file is empty")
    if path.suffix.lower() in (".gltf", ".glb"):  # what trimesh leaves out of a glTF, named
        from .gltf_file import GLTFFile, refuse_misread, warn_left_out

        try:
            doc = GLTFFile(path, allow_outside).doc
        except ResourceError:
            doc = None  # not glTF: trimesh's own error below says so, as for every format
        if doc is not None:
            warn_left_out(doc, label)
            refuse_misread(doc, label)
    try:
        loaded = _trimesh_load(path, allow_outside)
    except ResourceError:
        raise
    except Exception as exc:  # trimesh raises many types (ValueError, KeyError, struct.error, ...) for bad files
        raise ResourceError(label, "contents", f"cannot be read as {path.suffix[1:].upper()}: {exc}") from None
    _warn_undrawn(path, loaded, label)
    parts: dict[str, MeshData] = {}
    for name, mesh, transform in _parts(loaded, path.stem):
        data = _to_mesh_data(mesh, transform, name, label)
        if data is not None:
            parts[_unique(name, parts)] = data
    if not parts:
        raise ResourceError(label, "contents", "the file holds no triangles")
    return parts


#: OBJ elements trimesh reads nothing of, by their keyword.
_OBJ_UNDRAWN = {"l": "line", "p": "point"}


def _warn_undrawn(path: Path, loaded: Any, label: str) -> None:
    """A :class:`MeshFileWarning` for what the engine leaves out of a mesh file beside its triangles: an OBJ's line
    and point elements (trimesh reads nothing of them) and parts that are lines or point clouds (a PLY's; a glTF's
    primitives are named by :func:`.gltf_file.warn_left_out`)."""
    import trimesh

    if path.suffix.lower() == ".obj":
        counts: dict[str, int] = {}
        for line in path.read_text(errors="replace").splitlines():
            keyword = line.split(maxsplit=1)[0] if line.strip() else ""
            if keyword in _OBJ_UNDRAWN:
                counts[keyword] = counts.get(keyword, 0) + 1
        for keyword, count in counts.items():
            warnings.warn(f"{label}: {count} {_OBJ_UNDRAWN[keyword]} element(s) ('{keyword}' lines) are not drawn: "
                          "only faces ('f') are", MeshFileWarning, stacklevel=5)
    if path.suffix.lower() in (".gltf", ".glb"):
        return
    geometry = loaded.geometry if isinstance(loaded, trimesh.Scene) else {path.stem: loaded}
    for name, part in geometry.items():
        if not isinstance(part, trimesh.Trimesh):
            warnings.warn(f"{label}: part '{name}' is a {type(part).__name__} (no triangles): it is not drawn",
                          MeshFileWarning, stacklevel=5)


def _parts(loaded: Any, stem: str) -> list[tuple[str, Any, np.ndarray]]:
    """(name, trimesh.Trimesh, world transform) for every triangle mesh in a load result."""
    import trimesh

    if isinstance(loaded, trimesh.Trimesh):
        return [(stem, loaded, np.eye(4))]
    if not isinstance(loaded, trimesh.Scene):
        return []  # a point cloud or a path: no triangles
    out = []
    for node in loaded.graph.nodes_geometry:
        transform, geometry = loaded.graph[node]
        mesh = loaded.geometry.get(geometry)
        if isinstance(mesh, trimesh.Trimesh):
            out.append((str(node), mesh, np.asarray(transform, dtype=np.float64)))
    return out


def _unique(name: str, taken: dict[str, Any]) -> str:
    candidate, i = name, 1
    while candidate in taken:
        i += 1
        candidate = f"{name}.{i}"
    return candidate


def _to_mesh_data(mesh: Any, transform: np.ndarray, name: str, label: str) -> MeshData | None:
    """A validated MeshData for one trimesh part, or None when it has no usable triangle."""
    positions = np.asarray(mesh.vertices, dtype=np.float64)
    faces = np.asarray(mesh.faces, dtype=np.int64).reshape(-1, 3)
    if positions.ndim != 2 or positions.shape[1] != 3 or len(faces) == 0:
        return None
    if not np.all(np.isfinite(positions)):
        raise ResourceError(label, f"part '{name}'", "vertex positions contain NaN or infinity")
    if faces.min() < 0 or faces.max() >= len(positions):
        raise ResourceError(label, f"part '{name}'", "a face refers to a vertex that does not exist")
    positions = positions @ transform[:3, :3].T + transform[:3, 3]
    faces = faces[_usable_triangles(positions, faces)]
    if len(faces) == 0:
        return None
    # trimesh keeps normals read from the file in its cache; asking for mesh.vertex_normals would compute them.
    normals = mesh._cache.cache.get("vertex_normals")
    if normals is not None:
        normals = np.asarray(normals, dtype=np.float64)
        if normals.shape != positions.shape or not np.all(np.isfinite(normals)):
            normals = None
        else:
            # Normals transform with the cofactor (inverse transpose) of the linear part, then renormalise.
            normals = normals @ np.linalg.inv(transform[:3, :3])
            length = np.linalg.norm(normals, axis=1, keepdims=True)
            normals = np.where(length > 1e-12, normals / np.maximum(length, 1e-12), [0.0, 1.0, 0.0])
    uvs = _uvs(mesh, len(positions))
    colors = _colors(mesh, len(positions))
    data = MeshData(positions, normals=normals, uvs=uvs, colors=colors, indices=faces, name=name).with_normals()
    return data.with_tangents() if uvs is not None else data


def _usable_triangles(positions: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Mask of triangles with three distinct corners and a non-zero area (relative to their size)."""
    a, b, c = (positions[faces[:, k]] for k in range(3))
    distinct = (faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])
    area2 = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    edge2 = np.maximum.reduce([np.sum((b - a) ** 2, 1), np.sum((c - b) ** 2, 1), np.sum((a - c) ** 2, 1)])
    return distinct & (area2 > 1e-12 * np.maximum(edge2, 1e-300))


def _uvs(mesh: Any, count: int) -> np.ndarray | None:
    uv = getattr(mesh.visual, "uv", None) if getattr(mesh.visual, "kind", None) == "texture" else None
    if uv is None:
        return None
    uv = np.asarray(uv, dtype=np.float64)
    if uv.shape != (count, 2) or not np.all(np.isfinite(uv)):
        return None
    # trimesh uses the OBJ convention (v = 0 at the bottom); the engine's v = 0 is the top row.
    return np.column_stack([uv[:, 0], 1.0 - uv[:, 1]])


def _colors(mesh: Any, count: int) -> np.ndarray | None:
    if getattr(mesh.visual, "kind", None) != "vertex":
        return None
    colors = np.asarray(mesh.visual.vertex_colors)
    if colors.shape != (count, 4):
        return None
    return colors.astype(np.float64) / 255.0 if colors.dtype.kind in "iu" else colors.astype(np.float64)


def _merge(parts: list[MeshData], name: str, label: str) -> MeshData:
    if len(parts) == 1:
        return parts[0] if parts[0].name == name else MeshData(**_fields(parts[0]), name=name)
    fields: dict[str, Any] = {"positions": np.concatenate([p.positions for p in parts])}
    for attr in ("normals", "uvs", "tangents", "colors"):
        values = [getattr(p, attr) for p in parts]
        fields[attr] = np.concatenate(values) if all(v is not None for v in values) else None
    offsets = np.cumsum([0] + [p.vertex_count for p in parts[:-1]])
    fields["indices"] = np.concatenate([p.triangles().reshape(-1).astype(np.int64) + o for p, o in zip(parts, offsets)])
    return MeshData(**fields, name=name)


def _fields(mesh: MeshData) -> dict[str, Any]:
    return {f: getattr(mesh, f) for f in ("positions", "normals", "uvs", "tangents", "colors", "indices")}
