"""glTF 2.0 models with their metallic-roughness materials: ``load_gltf(path) -> GLTFModel``.

trimesh reads the geometry (through :mod:`gandalf_core.resources.mesh_loader`: node transforms applied, UVs in
the engine's convention, tangents computed); this module reads the file's JSON itself for what trimesh does
not keep: which texture feeds which material field, and the samplers. Each glTF material becomes one
:class:`MaterialData` whose textures are, in this order,

    base colour (sRGB), metallic-roughness (linear: G = roughness, B = metallic), normal (linear),
    occlusion (linear, R), emissive (sRGB)

followed by the caller's ``extra_textures`` (an environment, say); a missing map is replaced by a 1×1 white
(or flat-normal) texture, so one shader fits every material. Its params are ``metallic``, ``roughness``,
``normal_scale``, ``occlusion_strength``, ``emissive`` (vec4) and the caller's ``params``; ``color`` is the
base colour factor.

What cannot be mapped raises :class:`ResourceError` naming the file, the material and the field: a missing
image file, a mirrored-repeat or per-axis wrap mode (the engine has one wrap mode, repeat or clamp), a second
UV set, a textured material on a mesh without UVs, factors out of range, a required extension.
"""

from __future__ import annotations

import io
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from gandalf_core.resources.errors import ResourceError
from gandalf_core.resources.gltf_file import GLTFFile as _File
from gandalf_core.resources.gltf_file import GLTFWarning as GLTFWarning
from gandalf_core.resources.gltf_file import refuse_misread, warn_left_out
from gandalf_core.resources.material_data import MaterialData
from gandalf_core.resources.mesh_data import MeshData
from gandalf_core.resources.texture_data import TextureData

#: The material fields of a glTF material, in the order of MaterialData.textures, with their colour space.
TEXTURE_FIELDS = (
    ("baseColorTexture", True),
    ("metallicRoughnessTexture", False),
    ("normalTexture", False),
    ("occlusionTexture", False),
    ("emissiveTexture", True),
)
_REPEAT, _CLAMP, _MIRRORED = 10497, 33071, 33648
_NEAREST = 9728
_MIPMAP_FILTERS = (9984, 9985, 9986, 9987)
_WRAP_NAMES = {_REPEAT: "REPEAT", _CLAMP: "CLAMP_TO_EDGE", _MIRRORED: "MIRRORED_REPEAT"}
#: Defaults for missing maps: white (factor only) and a flat tangent-space normal.
DEFAULT_TEXTURES = {
    "gltf_white_srgb": TextureData(np.full((1, 1, 4), 255, np.uint8), name="gltf_white_srgb", mipmaps=False),
    "gltf_white_linear": TextureData(np.full((1, 1, 4), 255, np.uint8), srgb=False, name="gltf_white_linear",
                                     mipmaps=False),
    "gltf_flat_normal": TextureData(np.array([[[128, 128, 255, 255]]], np.uint8), srgb=False,
                                    name="gltf_flat_normal", mipmaps=False),
}
_DEFAULT_FOR = {"baseColorTexture": "gltf_white_srgb", "emissiveTexture": "gltf_white_srgb",
                "normalTexture": "gltf_flat_normal"}


@dataclass(frozen=True)
class GLTFModel:
    """What :func:`load_gltf` found: meshes, materials and textures by name (ready for a scene's assets), and
    ``parts``: one (mesh name, material name) pair per drawn primitive."""

    meshes: dict[str, MeshData]
    materials: dict[str, MaterialData]
    textures: dict[str, TextureData]
    parts: tuple[tuple[str, str], ...]


def _texture(file: _File, material: str, field: str, info: Mapping[str, Any], srgb: bool,
             name: str) -> TextureData:
    """The TextureData of one material field (its image decoded, its sampler mapped)."""
    where = f"material '{material}' {field}"
    for extension in info.get("extensions", {}):
        what = "its UV offset, scale and rotation are" if extension == "KHR_texture_transform" else "it is"
        warnings.warn(f"{file.label}: {where}: extension {extension} is not supported: {what} ignored",
                      GLTFWarning, stacklevel=4)
    if info.get("texCoord", 0) != 0:
        raise ResourceError(file.label, where, f"uses UV set {info['texCoord']}; only TEXCOORD_0 is supported")
    textures = file.items("textures")
    index = info.get("index")
    if not isinstance(index, int) or not 0 <= index < len(textures):
        raise ResourceError(file.label, where, f"texture index {index!r} does not exist ({len(textures)} textures)")
    texture = textures[index]
    if "source" not in texture:
        raise ResourceError(file.label, where, f"texture {index} has no image source (extensions are not supported)")
    settings: dict[str, Any] = {"wrap": "repeat", "filter": "linear", "mipmaps": True}
    if "sampler" in texture:
        sampler = file.items("samplers")[texture["sampler"]]
        wrap_s, wrap_t = sampler.get("wrapS", _REPEAT), sampler.get("wrapT", _REPEAT)
        for axis, mode in (("wrapS", wrap_s), ("wrapT", wrap_t)):
            if mode not in (_REPEAT, _CLAMP):
                raise ResourceError(file.label, f"{where} sampler {texture['sampler']} {axis}",
                                    f"{_WRAP_NAMES.get(mode, mode)} is not supported (use REPEAT or CLAMP_TO_EDGE)")
        if wrap_s != wrap_t:
            raise ResourceError(file.label, f"{where} sampler {texture['sampler']}",
                                f"wrapS {_WRAP_NAMES[wrap_s]} differs from wrapT {_WRAP_NAMES[wrap_t]}; the engine "
                                "has one wrap mode for both axes")
        settings["wrap"] = "repeat" if wrap_s == _REPEAT else "clamp"
        if sampler.get("magFilter") == _NEAREST:
            settings["filter"] = "nearest"
        if "minFilter" in sampler and sampler["minFilter"] not in _MIPMAP_FILTERS:
            settings["mipmaps"] = False
    from PIL import Image

    raw = file.image_bytes(texture["source"], f"{where} image {texture['source']}")
    try:
        with Image.open(io.BytesIO(raw)) as img:
            pixels = np.array(img.convert("RGBA"), dtype=np.uint8)
    except (OSError, ValueError) as exc:
        raise ResourceError(file.label, f"{where} image {texture['source']}", f"cannot decode: {exc}") from None
    return TextureData(pixels, srgb=srgb, name=name, **settings)


def _factor(file: _File, material: str, field: str, value: Any, default: Any, size: int) -> np.ndarray:
    v = np.asarray(default if value is None else value, dtype=np.float64).reshape(-1)
    if v.size != size or not np.all(np.isfinite(v)):
        detail = f"expected {size} finite numbers, got {value!r}"
        raise ResourceError(file.label, f"material '{material}' {field}", detail)
    if field != "emissiveFactor" and (v.min() < 0.0 or v.max() > 1.0):
        raise ResourceError(file.label, f"material '{material}' {field}", f"{value!r} is outside [0, 1]")
    if v.min() < 0.0:
        raise ResourceError(file.label, f"material '{material}' {field}", f"{value!r} is negative")
    return v


def _material(file: _File, index: int, shader: str, extra_textures: Sequence[str],
              params: Mapping[str, Any], textures: dict[str, TextureData]) -> tuple[str, MaterialData]:
    m = file.items("materials")[index]
    name = str(m.get("name") or f"material_{index}")
    for extension in m.get("extensions", {}):
        warnings.warn(f"{file.label}: material '{name}': extension {extension} is not supported: it is ignored",
                      GLTFWarning, stacklevel=3)
    pbr = m.get("pbrMetallicRoughness", {})
    color = _factor(file, name, "baseColorFactor", pbr.get("baseColorFactor"), [1.0, 1.0, 1.0, 1.0], 4)
    metallic = _factor(file, name, "metallicFactor", pbr.get("metallicFactor"), 1.0, 1)
    roughness = _factor(file, name, "roughnessFactor", pbr.get("roughnessFactor"), 1.0, 1)
    emissive = _factor(file, name, "emissiveFactor", m.get("emissiveFactor"), [0.0, 0.0, 0.0], 3)
    names = []
    for field, srgb in TEXTURE_FIELDS:
        info = (pbr if field in ("baseColorTexture", "metallicRoughnessTexture") else m).get(field)
        if info is None:
            default = _DEFAULT_FOR.get(field, "gltf_white_linear")
            textures.setdefault(default, DEFAULT_TEXTURES[default])
            names.append(default)
            continue
        tex_name = f"{file.path.stem}/{name}/{field}"
        textures[tex_name] = _texture(file, name, field, info, srgb, tex_name)
        names.append(tex_name)
    normal_scale = float(m.get("normalTexture", {}).get("scale", 1.0))
    occlusion = float(m.get("occlusionTexture", {}).get("strength", 1.0))
    if not 0.0 <= occlusion <= 1.0:
        raise ResourceError(file.label, f"material '{name}' occlusionTexture.strength",
                            f"{occlusion} is outside [0, 1]")
    values = {"metallic": float(metallic[0]), "roughness": float(roughness[0]), "normal_scale": normal_scale,
              "occlusion_strength": occlusion, "emissive": (*emissive, 1.0), **params}
    if m.get("alphaMode", "OPAQUE") != "OPAQUE":
        raise ResourceError(file.label, f"material '{name}' alphaMode",
                            f"{m['alphaMode']!r} is not supported (only OPAQUE)")
    cull = "none" if m.get("doubleSided", False) else "back"
    return name, MaterialData(shader, [*names, *extra_textures], color=tuple(color), params=values, cull=cull)


def load_gltf(path: str | Path, shader: str = "pbr_model", extra_textures: Sequence[str] = (),
              params: Mapping[str, Any] | None = None, *, allow_outside: bool = False) -> GLTFModel:
    """Read a .gltf/.glb file: meshes (with tangents), metallic-roughness materials for ``shader`` and their
    textures. ``extra_textures`` are appended to every material's textures, ``params`` to its params.

    Buffer and image URIs must lie in the file's folder (after following symlinks) unless ``allow_outside``."""
    from gandalf_core.resources.mesh_loader import _parts, _to_mesh_data, _trimesh_load

    file = _File(Path(path), allow_outside)
    for i, buffer in enumerate(file.items("buffers")):  # refused here before trimesh reads them
        if "uri" in buffer:
            file.buffer(i, f"buffer {i}")
    required = file.doc.get("extensionsRequired", [])
    if required:
        raise ResourceError(file.label, "extensionsRequired", f"{', '.join(map(str, required))} not supported")
    warn_left_out(file.doc, file.label)
    refuse_misread(file.doc, file.label)
    textures: dict[str, TextureData] = {}
    materials: dict[str, MaterialData] = {}
    by_index: dict[int, str] = {}
    for i in range(len(file.items("materials"))):
        name, data = _material(file, i, shader, tuple(extra_textures), dict(params or {}), textures)
        if name in materials:
            name = f"{name}.{i}"
        materials[name], by_index[i] = data, name
    _check_accessors(file)
    # Primitives that use a textured material must have UVs.
    for mesh_index, mesh in enumerate(file.items("meshes")):
        for k, primitive in enumerate(mesh.get("primitives", [])):
            material_index = primitive.get("material")
            if material_index is None:
                continue
            if material_index not in by_index:
                raise ResourceError(file.label, f"mesh '{mesh.get('name', mesh_index)}' primitive {k}",
                                    f"material {material_index} does not exist")
            data = materials[by_index[material_index]]
            textured = [f for (f, _), t in zip(TEXTURE_FIELDS, data.textures) if t not in DEFAULT_TEXTURES]
            if textured and "TEXCOORD_0" not in primitive.get("attributes", {}):
                raise ResourceError(file.label, f"mesh '{mesh.get('name', mesh_index)}' primitive {k}",
                                    f"material '{by_index[material_index]}' has {textured[0]} but the mesh has no "
                                    "UVs (TEXCOORD_0)")
    try:
        loaded = _trimesh_load(file.path, allow_outside)
    except Exception as exc:  # trimesh raises many types for bad files
        raise ResourceError(file.label, "contents", f"trimesh cannot read it: {exc}") from None
    meshes: dict[str, MeshData] = {}
    parts = []
    material_names = {data_name: data_name for data_name in materials}
    for name, mesh, transform in _parts(loaded, file.path.stem):
        data = _to_mesh_data(mesh, transform, name, file.label)
        if data is None:
            continue
        material = getattr(getattr(mesh.visual, "material", None), "name", None)
        if material not in material_names:
            material = "gltf_default"
            materials.setdefault(material, _material_default(shader, extra_textures, params or {}, textures))
        mesh_name = name if name not in meshes else f"{name}.{len(meshes)}"
        meshes[mesh_name] = data
        parts.append((mesh_name, material))
    if not parts:
        raise ResourceError(file.label, "contents", "the file holds no triangles")
    return GLTFModel(meshes, materials, textures, tuple(parts))


_INDEX_TYPES = {5121: "<u1", 5123: "<u2", 5125: "<u4"}


def _check_accessors(file: _File) -> None:
    """Every primitive's attribute and index accessors exist, and its indices stay below its vertex count: an error
    naming the mesh, the primitive, the accessor and the index (before trimesh reads them)."""
    accessors = file.items("accessors")
    for mesh_index, mesh in enumerate(file.items("meshes")):
        for k, primitive in enumerate(mesh.get("primitives", [])):
            where = f"mesh '{mesh.get('name', mesh_index)}' primitive {k}"
            used = {f"attribute {n}": a for n, a in primitive.get("attributes", {}).items()}
            if "indices" in primitive:
                used["indices"] = primitive["indices"]
            for what, accessor in used.items():
                if not isinstance(accessor, int) or not 0 <= accessor < len(accessors):
                    raise ResourceError(file.label, f"{where} {what}",
                                        f"accessor {accessor!r} does not exist ({len(accessors)} accessors)")
            position = primitive.get("attributes", {}).get("POSITION")
            if "indices" not in primitive or position is None:
                continue
            acc = accessors[primitive["indices"]]
            dtype = _INDEX_TYPES.get(acc.get("componentType"))
            views = file.items("bufferViews")
            if dtype is None or not 0 <= acc.get("bufferView", -1) < len(views):
                continue  # trimesh names what else is wrong
            view = views[acc["bufferView"]]
            data = file.buffer(view.get("buffer", 0), f"{where} indices")
            start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
            count = int(acc.get("count", 0))
            if start + count * np.dtype(dtype).itemsize > len(data):
                continue  # the accessor overruns its buffer: trimesh's error says so
            values = np.frombuffer(data, dtype, count, start) if count else np.zeros(0, int)
            vertices = int(accessors[position].get("count", 0))
            if values.size and int(values.max()) >= vertices:
                bad = int(np.argmax(values >= vertices))
                raise ResourceError(file.label, f"{where} indices (accessor {primitive['indices']})",
                                    f"index {bad} is {int(values[bad])}, out of range for the {vertices} vertices of "
                                    f"POSITION (accessor {position})")


def _material_default(shader: str, extra_textures: Sequence[str], params: Mapping[str, Any],
                      textures: dict[str, TextureData]) -> MaterialData:
    """glTF's default material (white, metallic 1, roughness 1) for primitives without one."""
    names = []
    for field, _ in TEXTURE_FIELDS:
        default = _DEFAULT_FOR.get(field, "gltf_white_linear")
        textures.setdefault(default, DEFAULT_TEXTURES[default])
        names.append(default)
    values = {"metallic": 1.0, "roughness": 1.0, "normal_scale": 1.0, "occlusion_strength": 1.0,
              "emissive": (0.0, 0.0, 0.0, 1.0), **params}
    return MaterialData(shader, [*names, *extra_textures], color=(1.0, 1.0, 1.0, 1.0), params=values)
