"""load_gltf: glTF metallic-roughness materials mapped to MaterialData/TextureData, and clear errors (naming the
file, the material and the field) for what the engine cannot map. The test files are written by the tests."""

from __future__ import annotations

import base64
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from gandalf_core.resources import GLTFModel, ResourceError, load_gltf
from gandalf_core.resources.gltf import DEFAULT_TEXTURES

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / "step07_advanced" / "pbr_model" / "models" / "power_cell.glb"

POSITIONS = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.float32)
NORMALS = np.tile(np.array([0, 0, 1], np.float32), (4, 1))
UVS = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.float32)  # glTF: v = 0 at the top of the image
INDICES = np.array([0, 1, 2, 0, 2, 3], np.uint16)


def write_gltf(folder: Path, material: dict, *, uvs: bool = True, textures: list | None = None,
               samplers: list | None = None, images: list | None = None, name: str = "quad.gltf") -> Path:
    """A one-quad .gltf with an embedded buffer and the given material/textures/samplers/images."""
    blobs = [POSITIONS.tobytes(), NORMALS.tobytes(), UVS.tobytes(), INDICES.tobytes()]
    offsets = np.cumsum([0] + [len(b) for b in blobs])
    views = [{"buffer": 0, "byteOffset": int(o), "byteLength": len(b)} for o, b in zip(offsets, blobs)]
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
    ]
    attributes = {"POSITION": 0, "NORMAL": 1}
    if uvs:
        attributes["TEXCOORD_0"] = 2
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "quad"}],
        "meshes": [{"name": "quad", "primitives": [{"attributes": attributes, "indices": 3, "material": 0}]}],
        "materials": [material],
        "buffers": [{"byteLength": int(offsets[-1]),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(b"".join(blobs)).decode()}],
        "bufferViews": views, "accessors": accessors,
    }
    for key, value in (("textures", textures), ("samplers", samplers), ("images", images)):
        if value is not None:
            doc[key] = value
    path = folder / name
    path.write_text(json.dumps(doc))
    return path


def write_png(folder: Path, name: str, rgb: tuple[int, int, int] = (200, 100, 50)) -> str:
    pixels = np.zeros((2, 2, 3), np.uint8)
    pixels[0, 0] = rgb  # top-left texel
    Image.fromarray(pixels).save(folder / name)
    return name


def textured(extra: dict | None = None) -> dict:
    return {"name": "Painted", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0.25,
                                                       "roughnessFactor": 0.6, "baseColorFactor": [1, 0.5, 0.5, 1]},
            **(extra or {})}


def test_a_textured_quad_maps_to_material_and_textures(tmp_path):
    write_png(tmp_path, "albedo.png")
    path = write_gltf(tmp_path, textured({"emissiveFactor": [0.5, 0.25, 0.0]}), textures=[{"source": 0, "sampler": 0}],
                      samplers=[{"wrapS": 33071, "wrapT": 33071, "magFilter": 9728, "minFilter": 9728}],
                      images=[{"uri": "albedo.png"}])
    model = load_gltf(path, shader="my_pbr", extra_textures=["env"], params={"env_strength": 0.5})
    assert isinstance(model, GLTFModel)
    assert model.parts == (("quad", "Painted"),)
    material = model.materials["Painted"]
    assert material.shader == "my_pbr"
    assert material.textures[0] == "quad/Painted/baseColorTexture"
    assert material.textures[1:5] == ("gltf_white_linear", "gltf_flat_normal", "gltf_white_linear", "gltf_white_srgb")
    assert material.textures[5] == "env"
    assert material.params["metallic"] == 0.25 and material.params["roughness"] == 0.6
    assert material.params["emissive"] == (0.5, 0.25, 0.0, 1.0) and material.params["env_strength"] == 0.5
    assert np.allclose(material.color, (1, 0.5, 0.5, 1))
    albedo = model.textures["quad/Painted/baseColorTexture"]
    assert (albedo.srgb, albedo.wrap, albedo.filter, albedo.mipmaps) == (True, "clamp", "nearest", False)
    assert tuple(albedo.pixels[0, 0, :3]) == (200, 100, 50)
    for name in material.textures[1:5]:
        assert model.textures[name] is DEFAULT_TEXTURES[name]
    mesh = model.meshes["quad"]
    assert mesh.tangents is not None
    # The engine's UV convention is glTF's: the vertex at the top-left of the quad samples the image's top row.
    top_left = int(np.argmin(np.linalg.norm(mesh.positions - [-1, 1, 0], axis=1)))
    assert np.allclose(mesh.uvs[top_left], [0, 0])


def test_data_textures_are_linear_and_colour_textures_srgb(tmp_path):
    for name in ("a.png", "b.png", "c.png", "d.png", "e.png"):
        write_png(tmp_path, name)
    material = {"name": "Full", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                         "metallicRoughnessTexture": {"index": 1}},
                "normalTexture": {"index": 2, "scale": 0.5}, "occlusionTexture": {"index": 3, "strength": 0.8},
                "emissiveTexture": {"index": 4}}
    path = write_gltf(tmp_path, material, textures=[{"source": i} for i in range(5)],
                      images=[{"uri": n} for n in ("a.png", "b.png", "c.png", "d.png", "e.png")])
    model = load_gltf(path)
    data = model.materials["Full"]
    assert [model.textures[t].srgb for t in data.textures] == [True, False, False, False, True]
    assert all(model.textures[t].wrap == "repeat" and model.textures[t].mipmaps for t in data.textures)
    assert data.params["normal_scale"] == 0.5 and data.params["occlusion_strength"] == pytest.approx(0.8)
    assert data.params["metallic"] == 1.0 and data.params["roughness"] == 1.0  # glTF defaults


def _error(path: Path) -> str:
    with pytest.raises(ResourceError) as info:
        load_gltf(path)
    return str(info.value)


def test_a_missing_texture_file_names_file_material_and_field(tmp_path):
    path = write_gltf(tmp_path, textured(), textures=[{"source": 0}], images=[{"uri": "missing.png"}])
    message = _error(path)
    for part in ("quad.gltf", "material 'Painted'", "baseColorTexture", "missing.png", "not found"):
        assert part in message, message


@pytest.mark.parametrize("wraps, parts", [
    ({"wrapS": 33648, "wrapT": 33648}, ("quad.gltf", "material 'Painted'", "baseColorTexture", "wrapS",
                                        "MIRRORED_REPEAT")),
    ({"wrapS": 10497, "wrapT": 33071}, ("material 'Painted'", "baseColorTexture",
                                        "wrapS REPEAT differs from wrapT CLAMP_TO_EDGE")),
], ids=["mirrored-repeat", "different-wraps-per-axis"])
def test_an_unsupported_wrap_is_refused(tmp_path, wraps, parts):
    write_png(tmp_path, "albedo.png")
    path = write_gltf(tmp_path, textured(), textures=[{"source": 0, "sampler": 0}], samplers=[wraps],
                      images=[{"uri": "albedo.png"}])
    message = _error(path)
    for part in parts:
        assert part in message, message


def test_a_textured_material_on_a_mesh_without_uvs_is_refused(tmp_path):
    write_png(tmp_path, "albedo.png")
    path = write_gltf(tmp_path, textured(), uvs=False, textures=[{"source": 0}], images=[{"uri": "albedo.png"}])
    message = _error(path)
    for part in ("quad.gltf", "mesh 'quad'", "material 'Painted'", "baseColorTexture", "TEXCOORD_0"):
        assert part in message, message


def test_an_untextured_material_needs_no_uvs(tmp_path):
    path = write_gltf(tmp_path, {"name": "Plain", "pbrMetallicRoughness": {"roughnessFactor": 0.3}}, uvs=False)
    model = load_gltf(path)
    assert model.materials["Plain"].params["roughness"] == pytest.approx(0.3)
    assert model.meshes["quad"].uvs is None


@pytest.mark.parametrize(("field", "material"), [
    ("roughnessFactor", {"name": "Bad", "pbrMetallicRoughness": {"roughnessFactor": 1.5}}),
    ("metallicFactor", {"name": "Bad", "pbrMetallicRoughness": {"metallicFactor": -0.1}}),
    ("baseColorFactor", {"name": "Bad", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1]}}),
    ("emissiveFactor", {"name": "Bad", "emissiveFactor": [-1, 0, 0]}),
    ("alphaMode", {"name": "Bad", "alphaMode": "BLEND"}),
])
def test_factors_out_of_range_name_the_material_and_field(tmp_path, field, material):
    message = _error(write_gltf(tmp_path, material))
    assert "material 'Bad'" in message and field in message, message


def test_a_second_uv_set_is_refused(tmp_path):
    write_png(tmp_path, "albedo.png")
    material = textured()
    material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0, "texCoord": 1}
    message = _error(write_gltf(tmp_path, material, textures=[{"source": 0}], images=[{"uri": "albedo.png"}]))
    assert "baseColorTexture" in message and "TEXCOORD_0" in message, message


def test_bad_paths_name_the_file(tmp_path):
    assert "file not found" in _error(tmp_path / "nothing.glb")
    (tmp_path / "model.obj").write_text("")
    assert ".gltf or .glb" in _error(tmp_path / "model.obj")
    (tmp_path / "broken.glb").write_bytes(b"nope")
    assert "broken.glb" in _error(tmp_path / "broken.glb")


def test_the_step07_model_loads_with_all_five_maps():
    model = load_gltf(MODEL, extra_textures=("a", "b", "c"))
    assert len(model.parts) == 1
    mesh_name, material_name = model.parts[0]
    material = model.materials[material_name]
    assert len(material.textures) == 8
    assert [model.textures[t].srgb for t in material.textures[:5]] == [True, False, False, False, True]
    assert not any(t in DEFAULT_TEXTURES for t in material.textures[:5])
    mesh = model.meshes[mesh_name]
    assert mesh.tangents is not None and mesh.uvs is not None
    assert MODEL.stat().st_size < 300_000


def test_required_extensions_are_refused(tmp_path):
    path = write_gltf(tmp_path, {"name": "Plain"})
    doc = json.loads(path.read_text())
    doc["extensionsRequired"] = ["KHR_texture_transform"]
    path.write_text(json.dumps(doc))
    assert "KHR_texture_transform" in _error(path)


def test_a_glb_with_an_embedded_image(tmp_path):
    """A binary glTF: JSON chunk + BIN chunk holding the geometry and the PNG (image by bufferView)."""
    import io
    import struct

    gltf = write_gltf(tmp_path, textured(), textures=[{"source": 0, "sampler": 0}],
                      samplers=[{"wrapS": 10497, "wrapT": 10497, "minFilter": 9729}], images=[{"uri": "x.png"}])
    doc = json.loads(gltf.read_text())
    geometry = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    png = io.BytesIO()
    pixels = np.zeros((2, 2, 3), np.uint8)
    pixels[0, 0] = (10, 20, 30)
    Image.fromarray(pixels).save(png, format="PNG")
    image = png.getvalue()
    pad = (-len(geometry)) % 4
    binary = geometry + b"\0" * pad + image + b"\0" * ((-len(image)) % 4)
    doc["buffers"] = [{"byteLength": len(binary)}]
    doc["bufferViews"].append({"buffer": 0, "byteOffset": len(geometry) + pad, "byteLength": len(image)})
    doc["images"] = [{"bufferView": len(doc["bufferViews"]) - 1, "mimeType": "image/png"}]
    text = json.dumps(doc).encode()
    text += b" " * ((-len(text)) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
    path = tmp_path / "quad.glb"
    path.write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)
    model = load_gltf(path)
    albedo = model.textures["quad/Painted/baseColorTexture"]
    assert tuple(albedo.pixels[0, 0, :3]) == (10, 20, 30)
    assert (albedo.wrap, albedo.filter, albedo.mipmaps) == ("repeat", "linear", False)
    assert model.meshes["quad"].vertex_count == 4
