"""glTF files the engine cannot map whole: an accessor that does not exist or an index past the vertex count is an
error naming the file, the mesh, the primitive, the accessor and the index; an optional extension it leaves out
(``KHR_texture_transform`` on a texture, a material extension) is a :class:`GLTFWarning` naming the material and
the extension, never dropped silently."""

from __future__ import annotations

import base64
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from gandalf_core.resources import GLTFWarning, ResourceError, load_gltf

from .catalogue import error, params, result, run, warning

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
    return root


def loads(name: str):
    return lambda folder: load_gltf(folder / name)


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
]


@pytest.mark.parametrize("case", params(CASES))
def test_gltf(case, folder):
    run(case, folder)
