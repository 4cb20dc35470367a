"""Files stay in their folder: every path a scene file, glTF or OBJ names (a USD texture in ``gandalf:files`` or
``gandalf:levelFiles``, a glTF image or buffer URI, an OBJ's material library) is resolved inside the file's own
folder after following symbolic links, and refused with an error naming the file, the prim or URI and the path
unless the caller passes ``allow_outside=True`` (an OBJ's material library and its ``map_Kd`` images too: trimesh
would drop them without a word). Each refusal has its opt-in twin."""

from __future__ import annotations

import base64
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from gandalf_core.resources import ResourceError, load_gltf
from gandalf_core.resources.mesh_loader import _trimesh_load, load_meshes

from .catalogue import error, params, result, run

pxr = pytest.importorskip("pxr")
from gandalf_core import Scene  # noqa: E402
from gandalf_core.components import InfoComponent, MaterialComponent, MeshComponent, TransformComponent  # noqa: E402
from gandalf_core.resources import MaterialData, checkerboard, cube  # noqa: E402
from step07_advanced.usd import USDSceneError, load_scene, save_scene  # noqa: E402

SECRET = (10, 200, 30)  # the outside image's colour: an opt-in load must show it


def _png(path: Path, rgb=SECRET) -> None:
    Image.fromarray(np.full((2, 2, 3), rgb, np.uint8)).save(path)


def _gltf(path: Path, image_uri: str | None = None, buffer_uri: str | None = None) -> Path:
    """A one-triangle .gltf whose base colour is the image at ``image_uri``; its buffer is inline unless
    ``buffer_uri`` names a file (written beside the uri's target by the caller)."""
    blob = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32).tobytes() + np.array(
        [[0, 0], [1, 0], [0, 1]], np.float32).tobytes()
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
        "materials": [{"name": "paint", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "buffers": [{"byteLength": len(blob),
                     "uri": buffer_uri or "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36,
                                                                           "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0],
                       "max": [1, 1, 0]}, {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
        "textures": [{"source": 0}], "images": [{"uri": image_uri or "paint.png"}],
    }
    path.write_text(json.dumps(doc))
    return path


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """``scene/`` holds the files under test; ``elsewhere/`` the files they must not reach without the opt-in."""
    root = tmp_path_factory.mktemp("paths")
    scene_dir, elsewhere = root / "scene", root / "elsewhere"
    scene_dir.mkdir()
    elsewhere.mkdir()
    _png(elsewhere / "secret.png")
    _png(scene_dir / "paint.png", (255, 255, 255))
    (scene_dir / "link.png").symlink_to(elsewhere / "secret.png")
    s = Scene("paths")
    s.assets.mesh("box", cube())
    s.assets.texture("checker", checkerboard(8, 2))
    s.assets.material("red", MaterialData("gandalf.unlit", ["checker"], color=(1, 0, 0)))
    s.create_entity(InfoComponent("crate"), TransformComponent(), MeshComponent("box"), MaterialComponent("red"))
    save_scene(s, scene_dir / "good.usda")
    text = (scene_dir / "good.usda").read_text()
    files = "gandalf:files = [@./good_usda_textures/checker.png@]"
    assert files in text
    for name, target in (("absolute", str(elsewhere / "secret.png")), ("dotdot", "../elsewhere/secret.png"),
                         ("symlink", "link.png")):
        (scene_dir / f"{name}.usda").write_text(text.replace(files, f"gandalf:files = [@{target}@]"))
    _gltf(scene_dir / "dotdot.gltf", "../elsewhere/secret.png")
    _gltf(scene_dir / "absolute.gltf", str(elsewhere / "secret.png"))
    _gltf(scene_dir / "symlink.gltf", "link.png")
    blob = (elsewhere / "tri.bin")
    blob.write_bytes(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32).tobytes()
                     + np.array([[0, 0], [1, 0], [0, 1]], np.float32).tobytes())
    _gltf(scene_dir / "buffer.gltf", "paint.png", "../elsewhere/tri.bin")
    (elsewhere / "paint.mtl").write_text("newmtl paint\nKd 0.1 0.8 0.1\n")
    triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl paint\nf 1/1 2/2 3/3\n"
    (scene_dir / "crate.obj").write_text("mtllib ../elsewhere/paint.mtl\n" + triangle)
    (scene_dir / "absolute.obj").write_text(f"mtllib {elsewhere / 'paint.mtl'}\n" + triangle)
    (scene_dir / "linked.mtl").symlink_to(elsewhere / "paint.mtl")
    (scene_dir / "linked.obj").write_text("mtllib linked.mtl\n" + triangle)
    (scene_dir / "image.mtl").write_text("newmtl paint\nKd 1 1 1\nmap_Kd ../elsewhere/secret.png\n")
    (scene_dir / "image.obj").write_text("mtllib image.mtl\n" + triangle)
    (scene_dir / "inside.mtl").write_text("newmtl paint\nKd 0.1 0.8 0.1\nmap_Kd paint.png\n")
    (scene_dir / "inside.obj").write_text("mtllib inside.mtl\n" + triangle)
    return scene_dir


def usd(name: str, **kwargs):
    return lambda folder: load_scene(folder / f"{name}.usda", **kwargs)


def gltf(name: str, **kwargs):
    return lambda folder: load_gltf(folder / f"{name}.gltf", **kwargs)


def texel(scene_or_model) -> tuple[int, ...]:
    """The first texel of the (only) loaded image texture."""
    textures = scene_or_model.assets.textures if hasattr(scene_or_model, "assets") else scene_or_model.textures
    texture = next(t for name, t in textures.items() if not name.startswith("gltf_"))
    return tuple(int(v) for v in texture.pixels[0, 0, :3])


def obj(name: str, **kwargs):
    return lambda folder: load_meshes(folder / f"{name}.obj", **kwargs)


def obj_colour(allow_outside: bool, name: str = "crate"):
    """The diffuse colour trimesh read from the OBJ's material library."""
    def action(folder: Path):
        loaded = _trimesh_load(folder / f"{name}.obj", allow_outside)
        mesh = next(iter(loaded.geometry.values())) if hasattr(loaded, "geometry") else loaded
        material = getattr(mesh.visual, "material", None)
        return None if material is None else tuple(int(v) for v in np.asarray(material.main_color)[:3])
    return action


CASES = [
    error("usd-texture-absolute-path", usd("absolute"), USDSceneError, "absolute.usda", "</Assets/Textures/checker>",
          "'gandalf:files'", "secret.png", "outside the scene's folder", "allow_outside"),
    error("usd-texture-dotdot", usd("dotdot"), USDSceneError, "dotdot.usda", "</Assets/Textures/checker>",
          "@../elsewhere/secret.png@", "outside the scene's folder"),
    error("usd-texture-symlink-to-outside", usd("symlink"), USDSceneError, "symlink.usda", "@link.png@",
          "elsewhere", "outside the scene's folder"),
    result("usd-texture-outside-allowed", usd("dotdot", allow_outside=True), lambda s: texel(s) == SECRET),
    result("usd-texture-symlink-allowed", usd("symlink", allow_outside=True), lambda s: texel(s) == SECRET),
    result("usd-texture-inside-still-loads", usd("good"), lambda s: "checker" in s.assets.textures),
    error("gltf-image-dotdot", gltf("dotdot"), ResourceError, "dotdot.gltf", "baseColorTexture",
          "'../elsewhere/secret.png'", "outside the file's folder", "allow_outside"),
    error("gltf-image-absolute", gltf("absolute"), ResourceError, "absolute.gltf", "secret.png",
          "outside the file's folder"),
    error("gltf-image-symlink-to-outside", gltf("symlink"), ResourceError, "symlink.gltf", "'link.png'",
          "elsewhere", "outside the file's folder"),
    error("gltf-buffer-outside", gltf("buffer"), ResourceError, "buffer.gltf", "buffer 0", "'../elsewhere/tri.bin'",
          "outside the file's folder"),
    result("gltf-image-outside-allowed", gltf("dotdot", allow_outside=True), lambda m: texel(m) == SECRET),
    result("gltf-symlink-allowed", gltf("symlink", allow_outside=True), lambda m: texel(m) == SECRET),
    result("gltf-buffer-outside-allowed", gltf("buffer", allow_outside=True), lambda m: len(m.meshes) == 1),
    error("mesh-loader-gltf-buffer-outside", lambda folder: load_meshes(folder / "buffer.gltf"), ResourceError,
          "buffer.gltf", "tri.bin"),
    result("mesh-loader-gltf-buffer-allowed", lambda folder: load_meshes(folder / "buffer.gltf", allow_outside=True),
           lambda parts: len(parts) == 1),
    error("obj-material-library-dotdot", obj("crate"), ResourceError, "crate.obj", "mtllib",
          "'../elsewhere/paint.mtl'", "outside the file's folder", "allow_outside"),
    error("obj-material-library-absolute", obj("absolute"), ResourceError, "absolute.obj", "mtllib", "paint.mtl",
          "outside the file's folder"),
    error("obj-material-library-symlink-to-outside", obj("linked"), ResourceError, "linked.obj", "'linked.mtl'",
          "elsewhere", "outside the file's folder"),
    error("obj-image-outside", obj("image"), ResourceError, "image.obj", "mtllib 'image.mtl' line 3 (map_Kd)",
          "'../elsewhere/secret.png'", "outside the file's folder"),
    error("obj-refused-through-trimesh-load-too", obj_colour(False), ResourceError, "crate.obj", "mtllib"),
    result("obj-material-library-outside-allowed", obj_colour(True), lambda rgb: rgb == (26, 204, 26)),
    result("obj-image-outside-allowed", obj("image", allow_outside=True), lambda parts: len(parts) == 1),
    result("obj-inside-still-loads", obj_colour(True, "inside"), lambda rgb: rgb is not None),
    result("obj-inside-loads-without-opt-in", obj("inside"), lambda parts: len(parts) == 1),
]


@pytest.mark.parametrize("case", params(CASES))
def test_paths(case, folder):
    run(case, folder)
