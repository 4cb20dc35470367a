"""USD written by other tools: xform op stacks, plain meshes, gprims and UsdPreviewSurface materials.

Everything here turns standard USD data (no ``gandalf:`` attributes) into engine data:

* :func:`decompose` — any local transform (``UsdGeom.Xformable.GetLocalTransformation``: rotateXYZ, rotateY,
  rotateZYX, scale, translate, transform (matrix) ops, pivots with their inverse ops) into translation,
  quaternion and scale; a shear TRS cannot hold is reported (its size), the nearest rotation kept.
* :func:`pin_first_samples` — attributes given only as time samples read as their first sample (listed).
* :func:`mesh_from_usd` — a ``UsdGeom.Mesh``: n-gons triangulated as fans, ``leftHanded`` winding flipped,
  holes left out, normals computed (area-weighted, shared by faces meeting at a point) when absent,
  ``st`` / normals / ``displayColor`` in any interpolation (constant, uniform, vertex, varying, faceVarying,
  indexed or not); any faceVarying or uniform value splits the vertices per face corner.
* :func:`gprim_mesh` — Sphere, Cube, Cylinder, Cone, Capsule and Plane tessellated (the engine's ``uv_sphere``,
  ``cube`` and ``plane`` where they exist; cylinder, cone and capsule here), turned to their ``axis``.
* :func:`preview_surface` — a bound material's ``UsdPreviewSurface`` network read into :class:`PreviewSurface`
  (colour, first ``UsdUVTexture`` on diffuseColor and its ``st`` reader, roughness, metallic, emission,
  opacity); :func:`default_preview_material` turns that into the built-in ``gandalf.blinn_phong``.

Problems that do not stop the load are appended to a list of ``(prim path, why)``; the reader reports them in
one warning.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from pxr import Gf, Usd, UsdGeom, UsdShade

from gandalf_core.math import quat_from_matrix3
from gandalf_core.resources import MaterialData, MeshData, cube, linear_to_srgb, plane, uv_sphere

Notes = list[tuple[str, str]]

#: Tessellation of curved gprims: segments around the axis, rings along a sphere's or capsule cap's latitude.
SEGMENTS = 32
RINGS = 16

SHEAR_TOLERANCE = 1e-6


# --- transforms ---------------------------------------------------------------------------------------
# --8<-- [start:decompose]
def decompose(matrix: Gf.Matrix4d | np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """A USD local matrix (row vectors: ``p' = p·M``) as ``(translation, quaternion (w, x, y, z), scale, shear)``.

    The engine computes ``M = T·R·S`` (column vectors). The scale is the length of each column of the 3×3 part,
    negated on X when the matrix mirrors; ``shear`` is the largest deviation of ``R^T·R`` from the identity
    (0 for any T·R·S matrix); a non-zero shear is not representable and the nearest rotation (polar
    decomposition) is used instead.
    """
    a = np.array(matrix, dtype=np.float64).reshape(4, 4).T  # column-vector convention
    translation = a[:3, 3].copy()
    linear = a[:3, :3]
    scale = np.linalg.norm(linear, axis=0)
    if np.linalg.det(linear) < 0:
        scale[0] = -scale[0]
    singular = np.any(np.abs(scale) < 1e-300)
    if singular:
        u, _, vt = np.linalg.svd(linear)
        rotation = u @ vt
        if np.linalg.det(rotation) < 0:
            rotation = u @ np.diag([1.0, 1.0, -1.0]) @ vt
        shear = 0.0
    else:
        rotation = linear / scale
        shear = float(np.abs(rotation.T @ rotation - np.eye(3)).max())
        if shear > SHEAR_TOLERANCE:
            u, _, vt = np.linalg.svd(rotation)
            rotation = u @ vt
    quaternion = np.asarray(quat_from_matrix3(rotation), dtype=np.float64)
    return translation, quaternion, scale, shear
# --8<-- [end:decompose]


def local_matrix(xformable: UsdGeom.Xformable, notes: Notes) -> tuple[Gf.Matrix4d, bool]:
    """The prim's local transformation and whether it resets the parent's (``!resetXformStack!``).

    Animated ops are read at their first time sample (listed in ``notes``).
    """
    path = str(xformable.GetPath())
    time = Usd.TimeCode.Default()
    ops = xformable.GetOrderedXformOps()
    samples = sorted({t for op in ops for t in op.GetAttr().GetTimeSamples()})
    if samples:
        time = Usd.TimeCode(samples[0])
        notes.append((path, f"animated xform ops: the transform at time {samples[0]:g} is used (no animation)"))
    matrix = xformable.GetLocalTransformation(time)
    return matrix, xformable.GetResetXformStack()


def pin_first_samples(stage: Usd.Stage, notes: Notes) -> None:
    """Read every attribute given only as time samples (an animation the engine does not play: a mesh baked from a
    simulation, an animated radius or intensity) as its first sample, and list them prim by prim: the sample is
    written as the attribute's default in the stage's session layer (the file is untouched), so every read at the
    default time sees it instead of the schema's fallback or nothing. Xform ops are read by :func:`local_matrix`,
    which lists them itself."""
    with Usd.EditContext(stage, stage.GetSessionLayer()):
        for prim in stage.Traverse():
            pinned = []
            for attribute in prim.GetAttributes():
                if attribute.GetName().startswith("xformOp:") or not attribute.GetNumTimeSamples():
                    continue
                if any(spec.HasDefaultValue() for spec in attribute.GetPropertyStack()):
                    continue  # the file's own default is what a still picture shows
                first = attribute.GetTimeSamples()[0]
                value = attribute.Get(first)
                if value is None:  # a blocked first sample: nothing to pin
                    continue
                attribute.Set(value)
                pinned.append((attribute.GetName(), first))
            if pinned:
                names = ", ".join(name for name, _ in pinned)
                times = sorted({t for _, t in pinned})
                notes.append((str(prim.GetPath()), f"animated {names}: the first time sample (time "
                                                   f"{', '.join(f'{t:g}' for t in times)}) is used (no animation)"))


# --- primvars -----------------------------------------------------------------------------------------
_FACE_WISE = (UsdGeom.Tokens.uniform, UsdGeom.Tokens.faceVarying)


@dataclass
class _Value:
    """A primvar's flattened values and interpolation."""

    data: np.ndarray
    interpolation: str


def _primvar(api: UsdGeom.PrimvarsAPI, name: str) -> UsdGeom.Primvar | None:
    primvar = api.GetPrimvar(name)
    return primvar if primvar and primvar.HasAuthoredValue() else None


def _flattened(primvar: UsdGeom.Primvar, width: int) -> _Value | None:
    values = primvar.ComputeFlattened()
    if values is None:
        return None
    return _Value(np.array(values, dtype=np.float64).reshape(-1, width), str(primvar.GetInterpolation()))


def _expected(interpolation: str, points: int, faces: int, corners: int) -> int:
    return {UsdGeom.Tokens.constant: 1, UsdGeom.Tokens.uniform: faces, UsdGeom.Tokens.vertex: points,
            UsdGeom.Tokens.varying: points, UsdGeom.Tokens.faceVarying: corners}.get(interpolation, -1)


# --- meshes -------------------------------------------------------------------------------------------
def mesh_from_usd(mesh: UsdGeom.Mesh, st_name: str, notes: Notes) -> tuple[MeshData | None, np.ndarray | None]:
    """An engine mesh from a plain ``UsdGeom.Mesh`` and its constant ``displayColor`` (RGBA, linear) if any.

    Returns ``(None, None)`` (with a note) for a mesh that cannot be drawn: no points, an invalid topology.
    """
    path = str(mesh.GetPath())
    points_value = mesh.GetPointsAttr().Get()
    counts_value, indices_value = mesh.GetFaceVertexCountsAttr().Get(), mesh.GetFaceVertexIndicesAttr().Get()
    if not points_value or not counts_value or indices_value is None:
        notes.append((path, "a mesh without points or faces: not drawn"))
        return None, None
    ok, why = UsdGeom.Mesh.ValidateTopology(indices_value, counts_value, len(points_value))
    if not ok:
        notes.append((path, f"invalid topology ({why}): not drawn"))
        return None, None
    points = np.array(points_value, dtype=np.float64).reshape(-1, 3)
    counts = np.array(counts_value, dtype=np.int64)
    indices = np.array(indices_value, dtype=np.int64)
    scheme = mesh.GetSubdivisionSchemeAttr().Get()
    if scheme not in (None, UsdGeom.Tokens.none):
        notes.append((path, f"subdivisionScheme '{scheme}': drawn as its control cage (no subdivision)"))
    n_faces, n_corners = len(counts), len(indices)
    face_of_corner = np.repeat(np.arange(n_faces), counts)
    first_corner = np.concatenate([[0], np.cumsum(counts)[:-1]])
    keep = counts >= 3
    holes = mesh.GetHoleIndicesAttr().Get()
    if holes is not None and len(holes):
        keep[np.array(holes, dtype=np.int64)[(np.array(holes) >= 0) & (np.array(holes) < n_faces)]] = False
    if np.any(counts < 3):
        notes.append((path, f"{int(np.sum(counts < 3))} face(s) with fewer than 3 vertices left out"))
    # Fan triangulation, in face-corner numbers: (first, first + k, first + k + 1).
    per_face = np.where(keep, np.maximum(counts - 2, 0), 0)
    if not per_face.sum():
        notes.append((path, "no drawable faces"))
        return None, None
    face_ids = np.repeat(np.arange(n_faces), per_face)
    k = np.arange(int(per_face.sum())) - np.repeat(np.cumsum(per_face) - per_face, per_face)
    f0 = first_corner[face_ids]
    tri_corners = np.stack([f0, f0 + k + 1, f0 + k + 2], axis=1)
    if mesh.GetOrientationAttr().Get() == UsdGeom.Tokens.leftHanded:
        tri_corners = tri_corners[:, [0, 2, 1]]

    api = UsdGeom.PrimvarsAPI(mesh)
    values: dict[str, _Value] = {}
    st = _primvar(api, st_name)
    if st is not None:
        values["uv"] = _flattened(st, 2)
    normals_primvar = _primvar(api, "normals")
    if normals_primvar is not None:
        values["normal"] = _flattened(normals_primvar, 3)
    elif mesh.GetNormalsAttr().HasAuthoredValue():
        values["normal"] = _Value(np.array(mesh.GetNormalsAttr().Get(), dtype=np.float64).reshape(-1, 3),
                                  str(mesh.GetNormalsInterpolation()))
    color_primvar = _primvar(api, "displayColor")
    constant_color = None
    if color_primvar is not None:
        color = _flattened(color_primvar, 3)
        opacity_primvar = _primvar(api, "displayOpacity")
        opacity = _flattened(opacity_primvar, 1) if opacity_primvar is not None else None
        if color is not None and color.interpolation == UsdGeom.Tokens.constant and len(color.data) >= 1:
            alpha = float(opacity.data[0, 0]) if opacity is not None and len(opacity.data) else 1.0
            constant_color = np.array([*color.data[0], alpha])
        elif color is not None:
            if opacity is not None and opacity.interpolation == color.interpolation and len(opacity.data) == len(
                    color.data):
                values["color"] = _Value(np.concatenate([color.data, opacity.data], axis=1), color.interpolation)
            else:
                values["color"] = _Value(np.concatenate([color.data, np.ones((len(color.data), 1))], axis=1),
                                         color.interpolation)
    for key in list(values):
        v = values[key]
        if v is None or len(v.data) != _expected(v.interpolation, len(points), n_faces, n_corners):
            size = "none" if v is None else len(v.data)
            notes.append((path, f"{key} values: {size} for interpolation "
                                f"'{None if v is None else v.interpolation}' do not match the mesh: left out"))
            del values[key]

    split = any(v.interpolation in _FACE_WISE for v in values.values())
    if split:  # one vertex per face corner
        point_of_vertex = indices
        corner_of_vertex = np.arange(n_corners)
        triangles = tri_corners
    else:
        point_of_vertex = np.arange(len(points))
        corner_of_vertex = None
        triangles = indices[tri_corners]

    def per_vertex(v: _Value) -> np.ndarray:
        if v.interpolation == UsdGeom.Tokens.constant:
            return np.repeat(v.data[:1], len(point_of_vertex), axis=0)
        if v.interpolation in (UsdGeom.Tokens.vertex, UsdGeom.Tokens.varying):
            return v.data[point_of_vertex]
        if v.interpolation == UsdGeom.Tokens.faceVarying:
            return v.data[corner_of_vertex]
        return v.data[face_of_corner[corner_of_vertex]]  # uniform

    fields: dict[str, object] = {"positions": points[point_of_vertex]}
    if "normal" in values:
        normals = per_vertex(values["normal"])
    else:
        normals = smooth_normals(points, indices, tri_corners, face_of_corner, keep)[point_of_vertex]
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    fields["normals"] = np.where(length > 1e-20, normals / np.maximum(length, 1e-300), [0.0, 1.0, 0.0])
    if "uv" in values:
        uv = per_vertex(values["uv"]).copy()
        uv[:, 1] = 1.0 - uv[:, 1]  # USD t = 0 at the image bottom, gandalf v = 0 at the top
        fields["uvs"] = uv
    if "color" in values:
        fields["colors"] = per_vertex(values["color"])
    mesh_data = MeshData(**fields, indices=triangles.reshape(-1), name=mesh.GetPrim().GetName())
    return mesh_data, constant_color


def smooth_normals(points: np.ndarray, indices: np.ndarray, tri_corners: np.ndarray, face_of_corner: np.ndarray,
                   kept_faces: np.ndarray) -> np.ndarray:
    """Per-point normals: each face's area vector (the sum of its fan's cross products, independent of the
    triangulation) added once to every point of the face, then normalised."""
    tri_points = indices[tri_corners]
    a, b, c = (points[tri_points[:, i]] for i in range(3))
    face = np.zeros((int(face_of_corner.max()) + 1 if len(face_of_corner) else 0, 3))
    np.add.at(face, face_of_corner[tri_corners[:, 0]], np.cross(b - a, c - a))
    normals = np.zeros_like(points)
    corners = np.flatnonzero(kept_faces[face_of_corner])
    np.add.at(normals, indices[corners], face[face_of_corner[corners]])
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    return np.where(length > 1e-20, normals / np.maximum(length, 1e-300), [0.0, 1.0, 0.0])


# --- gprims -------------------------------------------------------------------------------------------
GPRIMS = ("Sphere", "Cube", "Cylinder", "Cone", "Capsule", "Plane")


def _revolve(profile: list[tuple[float, float, float, float]], segments: int, name: str) -> MeshData:
    """A surface of revolution about +Y from (radius, y, normal_r, normal_y) rows, bottom to top.

    Rows with the same position but different normals make hard edges (e.g. a cylinder's rim).
    """
    angles = np.linspace(0.0, 2.0 * math.pi, segments + 1)
    cos, sin = np.cos(angles), -np.sin(angles)  # counter-clockwise seen from outside with y up
    positions, normals, uvs = [], [], []
    for i, (r, y, nr, ny) in enumerate(profile):
        for j in range(segments + 1):
            positions.append((r * cos[j], y, r * sin[j]))
            normals.append((nr * cos[j], ny, nr * sin[j]))
            uvs.append((j / segments, 1.0 - i / max(len(profile) - 1, 1)))
    indices = []
    row = segments + 1
    for i in range(len(profile) - 1):
        if profile[i][:2] == profile[i + 1][:2]:
            continue  # a hard edge: the two rows are one ring
        for j in range(segments):
            a, b = i * row + j, i * row + j + 1
            c, d = a + row, b + row
            indices += [a, b, d, a, d, c]
    return MeshData(positions, normals=normals, uvs=uvs, indices=indices, name=name)


def cylinder(radius: float = 1.0, height: float = 2.0, segments: int = SEGMENTS) -> MeshData:
    """A capped cylinder about +Y centred on the origin (USD's Cylinder turned to Y)."""
    h = height / 2.0
    return _revolve([(0.0, -h, 0.0, -1.0), (radius, -h, 0.0, -1.0), (radius, -h, 1.0, 0.0), (radius, h, 1.0, 0.0),
                     (radius, h, 0.0, 1.0), (0.0, h, 0.0, 1.0)], segments, "cylinder")


def cone(radius: float = 1.0, height: float = 2.0, segments: int = SEGMENTS) -> MeshData:
    """A capped cone about +Y, apex at +height/2 (USD's Cone turned to Y)."""
    h = height / 2.0
    slope = math.hypot(radius, height)
    nr, ny = height / slope, radius / slope
    return _revolve([(0.0, -h, 0.0, -1.0), (radius, -h, 0.0, -1.0), (radius, -h, nr, ny), (0.0, h, nr, ny)],
                    segments, "cone")


def capsule(radius: float = 0.5, height: float = 1.0, segments: int = SEGMENTS, rings: int = RINGS) -> MeshData:
    """A capsule about +Y: a cylinder of ``height`` with hemispheres of ``radius`` (USD's Capsule turned to Y)."""
    h = height / 2.0
    profile = []
    half = max(rings // 2, 2)
    for k in range(half + 1):  # bottom cap, from the pole up
        phi = -math.pi / 2 + (math.pi / 2) * k / half
        profile.append((radius * math.cos(phi), -h + radius * math.sin(phi), math.cos(phi), math.sin(phi)))
    for k in range(half + 1):  # top cap
        phi = (math.pi / 2) * k / half
        profile.append((radius * math.cos(phi), h + radius * math.sin(phi), math.cos(phi), math.sin(phi)))
    return _revolve(profile, segments, "capsule")


def _to_axis(mesh: MeshData, axis: str) -> MeshData:
    """``mesh`` (built about +Y) turned so that +Y goes to ``axis``."""
    if axis == "Y":
        return mesh
    perm = {"Z": lambda v: np.stack([v[:, 0], -v[:, 2], v[:, 1]], 1),
            "X": lambda v: np.stack([v[:, 1], -v[:, 0], v[:, 2]], 1)}[axis]
    return MeshData(perm(mesh.positions.astype(np.float64)), normals=perm(mesh.normals.astype(np.float64)),
                    uvs=mesh.uvs, indices=mesh.indices, name=mesh.name)


def gprim_mesh(prim: Usd.Prim, notes: Notes) -> MeshData | None:
    """The tessellated mesh of a Sphere, Cube, Cylinder, Cone, Capsule or Plane prim (None: not a gprim)."""
    kind = str(prim.GetTypeName())
    get = lambda name, default: (prim.GetAttribute(name).Get()  # noqa: E731
                                 if prim.GetAttribute(name) and prim.GetAttribute(name).Get() is not None
                                 else default)
    axis = str(get("axis", "Z"))
    if kind == "Sphere":
        return uv_sphere(float(get("radius", 1.0)), SEGMENTS, RINGS)
    if kind == "Cube":
        return cube(float(get("size", 2.0)))
    if kind == "Cylinder":
        return _to_axis(cylinder(float(get("radius", 1.0)), float(get("height", 2.0))), axis)
    if kind == "Cone":
        return _to_axis(cone(float(get("radius", 1.0)), float(get("height", 2.0))), axis)
    if kind == "Capsule":
        return _to_axis(capsule(float(get("radius", 0.5)), float(get("height", 1.0))), axis)
    if kind == "Plane":
        width, length = float(get("width", 2.0)), float(get("length", 2.0))
        base = plane(1.0)
        if axis == "Y":
            positions = base.positions.astype(np.float64) * [width, 1.0, length]
        else:  # built with its normal on +Y: width along x, length along z (which goes to y or -y for Z / X)
            positions = base.positions.astype(np.float64) * [width if axis == "Z" else length, 1.0,
                                                             length if axis == "Z" else width]
        flat = MeshData(positions, normals=base.normals, uvs=base.uvs, indices=base.indices, name="plane")
        return _to_axis(flat, axis)
    return None


# --- materials ----------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PreviewSurface:
    """What the loader read from a ``UsdPreviewSurface`` network (colours in sRGB, like engine colours).

    ``texture`` is the engine texture name of the file on diffuseColor (None: no texture); ``color`` is the
    diffuse colour, or the texture's ``scale`` (a tint) when there is a texture.
    """

    path: str
    color: tuple[float, float, float, float]
    texture: str | None = None
    roughness: float = 0.5
    metallic: float = 0.0
    emissive: tuple[float, float, float] = (0.0, 0.0, 0.0)


def default_preview_material(surface: PreviewSurface) -> MaterialData:
    """The engine's built-in ``gandalf.blinn_phong`` (both APIs, no shader to build), with the surface's colour
    and its texture (the albedo, multiplied by the colour) when it has one.

    Roughness r becomes shininess 2/r⁴ − 2 (clamped to 1..1024) and specular 0.04 + 0.96·metallic (at most 1);
    emission and opacity have no place in it. Pass ``preview_material=`` to :func:`step07_advanced.usd.load_scene`
    to map onto other shaders.
    """
    r = max(surface.roughness, 1e-3)
    params = {"specular": min(1.0, 0.04 + 0.96 * surface.metallic),
              "shininess": float(np.clip(2.0 / r**4 - 2.0, 1.0, 1024.0))}
    textures = [surface.texture] if surface.texture is not None else []
    return MaterialData("gandalf.blinn_phong", textures, color=surface.color, params=params)


def _constant(shader: UsdShade.Shader, name: str, notes: Notes, default: object) -> object:
    inp = shader.GetInput(name)
    if not inp:
        return default
    if inp.HasConnectedSource():
        notes.append((str(shader.GetPath()), f"input '{name}' is connected to a network: its default is used"))
        return default
    value = inp.Get()
    return default if value is None else value


def preview_surface(material: UsdShade.Material, texture_named: Callable[[UsdShade.Shader, str], str | None],
                    notes: Notes) -> tuple[PreviewSurface, str]:
    """The material's UsdPreviewSurface values and the ``st`` primvar name its texture reads.

    ``texture_named(uv_texture_shader, file)`` registers the texture file and returns its engine name (None:
    refused, noted by the caller).
    """
    path = str(material.GetPath())
    shader = material.ComputeSurfaceSource()[0]
    st_name = "st"
    if not shader or shader.GetIdAttr().Get() != "UsdPreviewSurface":
        what = "no surface shader" if not shader else f"surface shader '{shader.GetIdAttr().Get()}'"
        notes.append((path, f"{what} is not a UsdPreviewSurface: drawn in grey"))
        return PreviewSurface(path, (0.5, 0.5, 0.5, 1.0)), st_name
    for inp in shader.GetInputs():
        name = inp.GetBaseName()
        if name not in ("diffuseColor", "roughness", "metallic", "emissiveColor", "opacity") and (
                inp.HasConnectedSource() or inp.GetAttr().HasAuthoredValue()):
            notes.append((str(shader.GetPath()), f"input '{name}' has no engine mapping: left out"))
    texture = None
    diffuse = shader.GetInput("diffuseColor")
    linear = np.array([0.18, 0.18, 0.18])
    if diffuse and diffuse.HasConnectedSource():
        source = UsdShade.Shader(diffuse.GetConnectedSources()[0][0].source.GetPrim())
        if source.GetIdAttr().Get() == "UsdUVTexture":
            file = source.GetInput("file").Get() if source.GetInput("file") else None
            texture = texture_named(source, file.path if file is not None else "") if file is not None else None
            scale = _constant(source, "scale", notes, Gf.Vec4f(1, 1, 1, 1))
            linear = np.array(list(scale)[:3], dtype=np.float64)
            bias = _constant(source, "bias", notes, Gf.Vec4f(0, 0, 0, 0))
            if any(abs(b) > 0 for b in bias):
                notes.append((str(source.GetPath()), "a texture bias has no engine mapping: left out"))
            st_input = source.GetInput("st")
            if st_input and st_input.HasConnectedSource():
                reader = UsdShade.Shader(st_input.GetConnectedSources()[0][0].source.GetPrim())
                if reader.GetIdAttr().Get() == "UsdPrimvarReader_float2" and reader.GetInput("varname"):
                    st_name = str(reader.GetInput("varname").Get() or "st")
                elif reader.GetIdAttr().Get() != "UsdPrimvarReader_float2":
                    notes.append((str(reader.GetPath()), f"'{reader.GetIdAttr().Get()}' on st: 'st' is used"))
        else:
            notes.append((str(source.GetPath()), f"'{source.GetIdAttr().Get()}' on diffuseColor: not mapped, "
                                                 "grey is used"))
    elif diffuse:
        linear = np.array(list(diffuse.Get() or (0.18, 0.18, 0.18)), dtype=np.float64)
    opacity = float(_constant(shader, "opacity", notes, 1.0))
    srgb = linear_to_srgb(np.clip(linear, 0.0, 1.0))
    emissive = tuple(float(x) for x in _constant(shader, "emissiveColor", notes, (0.0, 0.0, 0.0)))
    return PreviewSurface(path, (*map(float, srgb), opacity), texture,
                          float(_constant(shader, "roughness", notes, 0.5)),
                          float(_constant(shader, "metallic", notes, 0.0)), emissive), st_name


def inside(folder: Path, target: Path) -> bool:
    """True when ``target`` lies in ``folder`` (both resolved)."""
    try:
        target.resolve().relative_to(folder.resolve())
    except ValueError:
        return False
    return True
