"""glTF files the engine cannot map whole: an accessor that does not exist or an index past the vertex count is an
error naming the file, the mesh, the primitive, the accessor and the index; an optional extension it leaves out
(``KHR_texture_transform`` on a texture, a material extension) is a :class:`GLTFWarning` naming the material and
the extension, never dropped silently; so is what trimesh would drop without a word: a primitive of lines or points
(beside triangles), morph targets, animations, skins, cameras, and the extensions of the file or a node (punctual
lights, GPU instancing), vertex colours beside a material; what it would read into wrong numbers is an error naming
the accessor (a sparse accessor, texture coordinates stored as integers); through :func:`load_gltf` and
:func:`load_meshes` alike."""

from __future__ import annotations

import base64
import contextlib
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from gandalf_core.resources import GLTFWarning, ResourceError, load_gltf, load_meshes

from .catalogue import error, params, quietly, result, run, warning

POSITIONS = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], np.float32)
UVS = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], np.float32)


def write(folder: Path, name: str, indices=(0, 1, 2, 2, 1, 3), edit=None) -> Path:
    """A two-triangle .gltf (inline buffer, base colour from paint.png); ``edit(doc)`` changes its JSON."""
    idx = np.asarray(indices, np.uint16).tobytes()
    blob = POSITIONS.tobytes() + UVS.tobytes() + idx
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                                                    "material": 0}]}],
        "materials": [{"name": "paint", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48,
                                                                           "byteLength": 32},
                        {"buffer": 0, "byteOffset": 80, "byteLength": len(idx)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0],
                       "max": [1, 1, 0]}, {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                      {"bufferView": 2, "componentType": 5123, "count": len(indices), "type": "SCALAR"}],
        "textures": [{"source": 0}], "images": [{"uri": "paint.png"}],
    }
    if edit is not None:
        edit(doc)
    path = folder / name
    path.write_text(json.dumps(doc))
    return path


def _transform(doc):
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
        "KHR_texture_transform": {"offset": [0.5, 0], "scale": [2, 2]}}
    doc["extensionsUsed"] = ["KHR_texture_transform"]


def _clearcoat(doc):
    doc["materials"][0]["extensions"] = {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0}}


def _lines(doc):  # a second primitive of the quad drawn as lines
    doc["meshes"][0]["primitives"].append({"attributes": {"POSITION": 0}, "indices": 2, "mode": 1})


def _points(doc):  # a second mesh, a point cloud on a node of its own
    doc["meshes"].append({"name": "dots", "primitives": [{"attributes": {"POSITION": 0}, "mode": 0}]})
    doc["nodes"].append({"mesh": 1})
    doc["scenes"][0]["nodes"].append(1)


def _fan(doc):
    doc["meshes"][0]["primitives"][0]["mode"] = 6


def _animated(doc):
    doc["nodes"][0]["name"] = "body"
    doc["animations"] = [{"name": "spin", "channels": [], "samplers": []}]
    doc["skins"] = [{"joints": [0]}]
    doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.1}}]
    doc["meshes"][0]["primitives"][0]["targets"] = [{"POSITION": 0}]


def _lights(doc):
    doc["extensionsUsed"] = ["KHR_lights_punctual", "EXT_mesh_gpu_instancing"]
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point"}]}}
    doc["nodes"].append({"name": "lamp", "extensions": {"KHR_lights_punctual": {"light": 0}}})
    doc["nodes"][0]["name"] = "crowd"
    doc["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": 0}}}
    doc["scenes"][0]["nodes"].append(1)


def _accessor(doc, values: np.ndarray, component_type: int, kind: str, normalized: bool = False) -> int:
    """Append ``values`` to the inline buffer as a new accessor; returns its index."""
    blob = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    offset, raw = len(blob), values.tobytes()
    blob += raw + b"\0" * (-len(raw) % 4)
    doc["buffers"][0] = {"byteLength": len(blob),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}
    doc["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": len(raw)})
    doc["accessors"].append({"bufferView": len(doc["bufferViews"]) - 1, "componentType": component_type,
                             "count": len(values), "type": kind, "normalized": normalized})
    return len(doc["accessors"]) - 1


def _short_uvs(doc):  # valid glTF 2.0: UVs as normalized unsigned shorts (trimesh reads 0..65535)
    doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = _accessor(
        doc, (UVS * 65535).astype(np.uint16), 5123, "VEC2", normalized=True)


def _sparse(doc):  # POSITION with one vertex substituted by a sparse block (trimesh leaves it out)
    moved = _accessor(doc, np.array([[5, 5, 0]], np.float32), 5126, "VEC3")
    which = _accessor(doc, np.array([3, 0], np.uint16), 5123, "SCALAR")
    doc["accessors"][0]["sparse"] = {"count": 1, "indices": {"bufferView": doc["accessors"][which]["bufferView"],
                                                             "componentType": 5123},
                                     "values": {"bufferView": doc["accessors"][moved]["bufferView"]}}


def _coloured(doc):  # vertex colours beside the textured material
    doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = _accessor(
        doc, np.array([[255, 0, 0, 255]] * 4, np.uint8), 5121, "VEC4", normalized=True)


def _position_accessor(doc):
    doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("gltf")
    Image.fromarray(np.full((2, 2, 3), 200, np.uint8)).save(root / "paint.png")
    write(root, "good.gltf")
    write(root, "transform.gltf", edit=_transform)
    write(root, "clearcoat.gltf", edit=_clearcoat)
    write(root, "position.gltf", edit=_position_accessor)
    write(root, "index.gltf", indices=(0, 1, 2, 2, 1, 7))
    for name, edit in (("lines", _lines), ("points", _points), ("fan", _fan), ("animated", _animated),
                       ("lights", _lights), ("short_uvs", _short_uvs), ("sparse", _sparse), ("coloured", _coloured)):
        write(root, f"{name}.gltf", edit=edit)
    return root


def loads(name: str):
    return lambda folder: load_gltf(folder / name)


def erring(action):
    """``action`` with its ResourceError swallowed: a warning case about a file that then ends in an error."""
    def swallowed(folder):
        with contextlib.suppress(ResourceError):
            return action(folder)
    return swallowed


CASES = [
    result("a-good-quad", loads("good.gltf"), lambda m: [material for _, material in m.parts] == ["paint"]),
    warning("texture-transform-warned", loads("transform.gltf"), GLTFWarning, "transform.gltf", "material 'paint'",
            "baseColorTexture", "KHR_texture_transform", "ignored"),
    warning("material-extension-warned", loads("clearcoat.gltf"), GLTFWarning, "material 'paint'",
            "KHR_materials_clearcoat"),
    error("attribute-accessor-missing", loads("position.gltf"), ResourceError, "position.gltf",
          "mesh 'quad' primitive 0 attribute POSITION", "accessor 9 does not exist", "3 accessors"),
    error("index-out-of-range", loads("index.gltf"), ResourceError, "index.gltf", "mesh 'quad' primitive 0",
          "accessor 2", "index 5 is 7", "4 vertices"),
    warning("lines-primitive-warned", loads("lines.gltf"), GLTFWarning, "lines.gltf", "mesh 'quad' primitive 1",
            "mode LINES (1) is not drawn"),
    result("lines-beside-triangles-still-draw-the-triangles", quietly(loads("lines.gltf"), GLTFWarning),
           lambda m: len(m.parts) == 1),
    warning("points-mesh-warned", loads("points.gltf"), GLTFWarning, "mesh 'dots' primitive 0", "mode POINTS (0)"),
    warning("points-warned-by-load-meshes-too", lambda folder: load_meshes(folder / "points.gltf"), GLTFWarning,
            "points.gltf", "mesh 'dots' primitive 0", "POINTS"),
    warning("triangle-fan-warned", erring(loads("fan.gltf")), GLTFWarning, "mesh 'quad' primitive 0",
            "mode TRIANGLE_FAN (6) is not drawn"),
    error("triangle-fan-alone-is-no-triangles", quietly(loads("fan.gltf"), GLTFWarning), ResourceError, "fan.gltf",
          "holds no triangles"),
    warning("animations-warned", loads("animated.gltf"), GLTFWarning, "animated.gltf", "1 animation(s)",
            "drawn at rest"),
    warning("skins-warned", loads("animated.gltf"), GLTFWarning, "1 skin(s)", "drawn unskinned"),
    warning("cameras-warned", loads("animated.gltf"), GLTFWarning, "1 camera(s)", "ignored"),
    warning("morph-targets-warned", loads("animated.gltf"), GLTFWarning, "mesh 'quad' primitive 0",
            "1 morph target(s)", "the base shape is drawn"),
    warning("punctual-lights-warned", loads("lights.gltf"), GLTFWarning, "node 'lamp'", "KHR_lights_punctual"),
    warning("gpu-instancing-warned", loads("lights.gltf"), GLTFWarning, "node 'crowd'", "EXT_mesh_gpu_instancing"),
    error("integer-uvs-refused", loads("short_uvs.gltf"), ResourceError, "short_uvs.gltf",
          "mesh 'quad' primitive 0 TEXCOORD_0 (accessor 3)", "normalized UNSIGNED_SHORT", "store them as FLOAT"),
    error("integer-uvs-refused-by-load-meshes-too", lambda folder: load_meshes(folder / "short_uvs.gltf"),
          ResourceError, "short_uvs.gltf", "TEXCOORD_0"),
    error("sparse-accessor-refused", loads("sparse.gltf"), ResourceError, "sparse.gltf",
          "mesh 'quad' primitive 0 POSITION (accessor 0)", "sparse accessor"),
    warning("vertex-colours-beside-a-material-warned", loads("coloured.gltf"), GLTFWarning, "mesh 'quad' primitive 0",
            "COLOR_0", "not read"),
]


@pytest.mark.parametrize("case", params(CASES))
def test_gltf(case, folder):
    run(case, folder)
