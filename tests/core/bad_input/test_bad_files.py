"""Files and the data made from them: mesh files (OBJ, PLY, STL, glTF/GLB) that are missing, empty, garbage, out of
range or non-finite, or holding lines and points beside their faces (a MeshFileWarning, on every load: they are not
drawn); image files that are missing, not images or truncated; pixel arrays, cube faces, mesh arrays, procedural
generators and asset tables given the wrong shapes, types or values. Every error is a ResourceError naming the file
(or texture, mesh, material) and the part at fault; a mesh file rewritten with the same size and modification time
loads anew (the cache is keyed by content)."""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
import pytest

from gandalf_core.resources import (
    CubeTextureData,
    MaterialData,
    MeshData,
    MeshFileWarning,
    ResourceError,
    TextureData,
    checkerboard,
    cube,
    load_gltf,
    load_mesh,
    torus,
    uv_sphere,
)
from gandalf_core.resources.assets import Assets

from .catalogue import error, params, quietly, result, run, warning, write_files

TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
FILES = {
    "empty.obj": "",
    "garbage.obj": "garbage here\nxx yy\n",
    "bad_index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
    "nan.obj": "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n",
    "points.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\n",
    "wired.obj": TRIANGLE + "v 2 2 2\nl 1 4\nl 2 4\np 4\n",
    "mesh.xyz": "hello",
    "bad.ply": "ply\ngarbage\n",
    "bad.stl": "solid x\nnonsense\n",
    "bad.glb": "glTF garbage",
    "lost_buffer.gltf": ('{"asset":{"version":"2.0"},"buffers":[{"uri":"missing.bin","byteLength":36}],'
                         '"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,'
                         '"componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],"meshes":'
                         '[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":'
                         '[{"nodes":[0]}],"scene":0}'),
    "fake.png": "not a png",
    "empty.png": "",
}


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = write_files(tmp_path_factory.mktemp("files"), FILES)
    (root / "folder.obj").mkdir()
    (root / "folder.png").mkdir()
    checkerboard(8, 2).save_png(root / "good.png") if hasattr(TextureData, "save_png") else _png(root / "good.png")
    (root / "truncated.png").write_bytes((root / "good.png").read_bytes()[:40])
    return root


def _png(path: Path) -> None:
    from PIL import Image

    Image.fromarray(np.zeros((8, 8, 4), np.uint8)).save(path)


def rewritten_same_size_and_time(folder: Path):
    path = folder / "rewritten.obj"
    path.write_text(TRIANGLE)
    stat = path.stat()
    first = load_mesh(path)
    path.write_text(TRIANGLE.replace("v 1 0 0", "v 2 0 0"))  # same size
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns))  # same modification time
    return first, load_mesh(path)


def mesh(name: str):
    return lambda folder: load_mesh(folder / name)


def image(name: str):
    return lambda folder: TextureData.from_file(folder / name)


def rgba(*shape, dtype=np.uint8, fill=0):
    return np.full(shape, fill, dtype=dtype)


FILE_CASES = [
    error("mesh-missing", mesh("gone.obj"), ResourceError, "mesh file", "gone.obj", "file not found"),
    error("mesh-empty", mesh("empty.obj"), ResourceError, "empty.obj", "the file is empty"),
    error("mesh-garbage", mesh("garbage.obj"), ResourceError, "garbage.obj", "no triangles"),
    error("mesh-index-out-of-range", mesh("bad_index.obj"), ResourceError, "bad_index.obj", "out of bounds"),
    error("mesh-nan-vertex", mesh("nan.obj"), ResourceError, "nan.obj", "NaN or infinity"),
    error("mesh-points-only", mesh("points.obj"), ResourceError, "points.obj", "no triangles"),
    warning("mesh-obj-lines-warned", mesh("wired.obj"), MeshFileWarning, "wired.obj", "2 line element(s)",
            "not drawn"),
    warning("mesh-obj-points-warned", mesh("wired.obj"), MeshFileWarning, "1 point element(s) ('p' lines)"),
    result("mesh-obj-faces-beside-lines-still-load", quietly(mesh("wired.obj"), MeshFileWarning),
           lambda m: m.vertex_count == 3),
    error("mesh-unknown-extension", mesh("mesh.xyz"), ResourceError, "mesh.xyz", "unsupported extension '.xyz'",
          ".obj"),
    error("mesh-a-folder", mesh("folder.obj"), ResourceError, "folder.obj", "is not a file"),
    error("mesh-garbage-ply", mesh("bad.ply"), ResourceError, "bad.ply", "PLY"),
    error("mesh-garbage-stl", mesh("bad.stl"), ResourceError, "bad.stl", "no triangles"),
    error("mesh-garbage-glb", mesh("bad.glb"), ResourceError, "bad.glb", "GLB"),
    error("mesh-gltf-buffer-missing", mesh("lost_buffer.gltf"), ResourceError, "lost_buffer.gltf", "missing.bin"),
    error("gltf-missing", lambda folder: load_gltf(folder / "gone.glb"), ResourceError, "glTF file", "gone.glb",
          "file not found"),
    error("gltf-wrong-extension", lambda folder: load_gltf(folder / "garbage.obj"), ResourceError, "garbage.obj",
          "expected a .gltf or .glb file"),
    error("gltf-garbage", lambda folder: load_gltf(folder / "bad.glb"), ResourceError, "bad.glb", "glTF"),
    error("gltf-buffer-missing", lambda folder: load_gltf(folder / "lost_buffer.gltf"), ResourceError,
          "lost_buffer.gltf", "missing.bin"),
    result("mesh-rewritten-same-size-and-time-loads-anew", rewritten_same_size_and_time,
           lambda pair: pair[0].positions.max() == 1.0 and pair[1].positions.max() == 2.0),
    error("image-missing", image("gone.png"), ResourceError, "texture 'gone.png'", "file not found"),
    error("image-not-an-image", image("fake.png"), ResourceError, "texture 'fake.png'", "cannot read image"),
    error("image-empty-file", image("empty.png"), ResourceError, "texture 'empty.png'", "cannot read image"),
    error("image-truncated", image("truncated.png"), ResourceError, "texture 'truncated.png'", "image"),
    error("image-a-folder", image("folder.png"), ResourceError, "texture 'folder.png'", "is a folder"),
    error("image-path-as-pixels", lambda folder: TextureData(str(folder / "gone.png")), ResourceError,
          "texture 'gone.png'", "file not found"),
    result("image-good", image("good.png"), lambda t: t.pixels.shape == (8, 8, 4)),
]

DATA_CASES = [
    # pixels
    error("pixels-grey-2d", lambda: TextureData(rgba(4, 4)), ResourceError, "texture", "pixels",
          "uint8 array of shape (H, W, 4)", "from_array"),
    error("pixels-five-channels", lambda: TextureData(rgba(4, 4, 5)), ResourceError, "pixels", "(4, 4, 5)"),
    error("pixels-empty", lambda: TextureData(rgba(0, 4, 4)), ResourceError, "pixels", "empty"),
    error("pixels-float", lambda: TextureData(rgba(4, 4, 4, dtype=np.float32)), ResourceError, "pixels", "float32"),
    error("pixels-int64", lambda: TextureData(rgba(4, 4, 4, dtype=np.int64)), ResourceError, "pixels", "int64"),
    error("pixels-wrap-unknown", lambda: TextureData(rgba(4, 4, 4), wrap="tile", name="bricks"), ResourceError,
          "texture 'bricks'", "wrap", "'tile'", "'repeat'"),
    error("pixels-filter-unknown", lambda: TextureData(rgba(4, 4, 4), filter="cubic", name="bricks"), ResourceError,
          "texture 'bricks'", "filter", "'cubic'"),
    error("pixels-srgb-text", lambda: TextureData(rgba(4, 4, 4), srgb="no", name="bricks"), ResourceError,
          "texture 'bricks'", "srgb", "True or False", "'no'"),
    error("pixels-mipmaps-int", lambda: TextureData(rgba(4, 4, 4), mipmaps=0, name="bricks"), ResourceError,
          "texture 'bricks'", "mipmaps", "True or False"),
    error("pixels-anisotropy-zero", lambda: TextureData(rgba(4, 4, 4), anisotropy=0, name="bricks"), ResourceError,
          "texture 'bricks'", "anisotropy", "got 0"),
    error("pixels-anisotropy-needs-linear", lambda: TextureData(rgba(4, 4, 4), anisotropy=4, filter="nearest"),
          ResourceError, "anisotropy", "filter='linear'"),
    error("from-array-nan", lambda: TextureData.from_array(np.full((4, 4, 3), math.nan)), ResourceError, "pixels",
          "nan"),
    error("from-array-above-one", lambda: TextureData.from_array(np.full((4, 4, 3), 2.0)), ResourceError, "pixels",
          "[0, 1]"),
    error("from-array-int-300", lambda: TextureData.from_array(np.full((4, 4, 3), 300)), ResourceError, "pixels",
          "[0, 255]"),
    error("from-array-4d", lambda: TextureData.from_array(np.zeros((2, 2, 2, 2))), ResourceError, "pixels",
          "(2, 2, 2, 2)"),
    error("cube-five-faces", lambda: CubeTextureData([rgba(4, 4, 4)] * 5), ResourceError, "cube texture", "faces",
          "expected 6 faces", "got 5"),
    error("cube-faces-differ", lambda: CubeTextureData([rgba(4, 4, 4)] * 5 + [rgba(8, 8, 4)]), ResourceError,
          "faces[-Z]", "8x8 differs from face +X"),
    error("cube-face-not-square", lambda: CubeTextureData([rgba(4, 8, 4)] * 6), ResourceError, "faces[+X]",
          "square"),
    error("cube-srgb-text", lambda: CubeTextureData([rgba(4, 4, 4)] * 6, srgb="yes"), ResourceError, "srgb"),
    # mesh arrays
    error("mesh-positions-2d", lambda: MeshData(np.zeros((3, 2))), ResourceError, "mesh", "positions",
          "(N, 3)", "(3, 2)"),
    error("mesh-positions-nan", lambda: MeshData(np.array([[0, 0, 0], [math.nan, 0, 0], [0, 1, 0]])),
          ResourceError, "positions[1, 0] = nan"),
    error("mesh-positions-text", lambda: MeshData("cube"), ResourceError, "positions", "'cube'"),
    error("mesh-no-vertices", lambda: MeshData(np.zeros((0, 3))), ResourceError, "positions", "no vertices"),
    error("mesh-not-whole-triangles", lambda: MeshData(np.zeros((4, 3))), ResourceError, "4 vertices",
          "whole triangles"),
    error("mesh-index-out-of-range", lambda: MeshData(np.zeros((3, 3)), indices=np.array([0, 1, 5])),
          ResourceError, "indices[2] = 5", "out of range for 3 vertices"),
    error("mesh-index-negative", lambda: MeshData(np.zeros((3, 3)), indices=np.array([0, 1, -1])), ResourceError,
          "indices[2] = -1"),
    error("mesh-index-count", lambda: MeshData(np.zeros((3, 3)), indices=np.array([0, 1])), ResourceError,
          "indices", "multiple of 3"),
    error("mesh-index-float", lambda: MeshData(np.zeros((3, 3)), indices=np.array([0.0, 1.0, 2.0])),
          ResourceError, "indices", "float64", "not an integer type"),
    error("mesh-normals-count", lambda: MeshData(np.zeros((3, 3)), normals=np.zeros((2, 3))), ResourceError,
          "normals", "2 rows", "N = 3"),
    error("mesh-uvs-shape", lambda: MeshData(np.zeros((3, 3)), uvs=np.zeros((3, 3))), ResourceError, "uvs",
          "(N, 2)"),
    # generators
    error("sphere-segments-zero", lambda: uv_sphere(segments=0), ResourceError, "mesh 'uv_sphere'", "segments",
          ">= 3"),
    error("cube-size-negative", lambda: cube(-1), ResourceError, "mesh 'cube'", "size", "-1"),
    error("cube-size-nan", lambda: cube(math.nan), ResourceError, "mesh 'cube'", "size", "nan"),
    error("torus-radius-zero", lambda: torus(0, 0), ResourceError, "mesh 'torus'", "major_radius"),
    error("checkerboard-size-zero", lambda: checkerboard(0, 2), ResourceError, "texture 'checkerboard'", "size"),
    # asset tables
    error("assets-mesh-not-data", lambda: Assets().mesh("m", "cube"), ResourceError, "mesh 'm'", "expected MeshData",
          "got str"),
    error("assets-texture-array", lambda: Assets().texture("t", np.zeros((4, 4, 4))), ResourceError, "texture 't'",
          "TextureData or CubeTextureData", "got ndarray"),
    error("assets-empty-name", lambda: Assets().mesh("", cube()), ResourceError, "mesh ''", "non-empty string"),
    error("assets-number-name", lambda: Assets().material(3, MaterialData("flat")), ResourceError, "material 3",
          "name"),
    error("assets-remove-missing", lambda: Assets().remove_texture("bricks"), ResourceError, "texture 'bricks'",
          "no such texture"),
]


@pytest.mark.parametrize("case", params(FILE_CASES))
def test_files(case, folder):
    run(case, folder)


@pytest.mark.parametrize("case", params(DATA_CASES))
def test_data(case):
    run(case)
