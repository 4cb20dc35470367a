"""The mesh loader: real files written with trimesh into temporary folders, read back as MeshData."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

from gandalf_core.resources import ResourceError
from gandalf_core.resources.mesh_loader import clear_cache, load_mesh, load_meshes

trimesh = pytest.importorskip("trimesh")


@pytest.fixture(autouse=True)
def _fresh_cache():
    clear_cache()
    yield
    clear_cache()


def _box(extent=(1.0, 1.0, 1.0)):
    return trimesh.creation.box(extents=extent)


def _check_mesh(mesh, triangles=None):
    """Every loaded mesh: finite float32 arrays, unit normals, triangles in range."""
    assert mesh.normals is not None
    assert np.all(np.isfinite(mesh.positions)) and np.all(np.isfinite(mesh.normals))
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-5)
    if triangles is not None:
        assert mesh.triangle_count == triangles


@pytest.mark.parametrize("ext", ["obj", "ply", "stl", "glb"])
def test_each_format_loads_a_box_with_normals(tmp_path, ext):
    path = tmp_path / f"box.{ext}"
    _box((2.0, 1.0, 1.0)).export(path)
    mesh = load_mesh(path)
    _check_mesh(mesh, triangles=12)
    lo, hi = mesh.bounds()
    assert np.allclose(lo, (-1.0, -0.5, -0.5), atol=1e-6) and np.allclose(hi, (1.0, 0.5, 0.5), atol=1e-6)


def test_glb_with_two_meshes_applies_node_transforms(tmp_path):
    scene = trimesh.Scene()
    scene.add_geometry(_box(), node_name="left", geom_name="cube")
    ball = trimesh.creation.icosphere(subdivisions=1, radius=0.5)
    rz90 = trimesh.transformations.rotation_matrix(np.pi / 2, [0, 0, 1])
    move = trimesh.transformations.translation_matrix([3.0, 0.0, 0.0]) @ rz90 @ np.diag([2.0, 1.0, 1.0, 1.0])
    scene.add_geometry(ball, node_name="right", geom_name="ball", transform=move)
    path = tmp_path / "two.glb"
    scene.export(path)
    parts = load_meshes(path)
    assert set(parts) == {"left", "right"}
    _check_mesh(parts["left"], triangles=12)
    _check_mesh(parts["right"], triangles=len(ball.faces))
    lo, hi = parts["right"].bounds()
    # Scaled x2 along x, then turned 90° about z: the long axis ends up along y; then moved to x = 3.
    assert np.allclose((lo + hi) / 2, (3.0, 0.0, 0.0), atol=1e-5)
    assert hi[1] - lo[1] == pytest.approx(2.0, abs=1e-5) and hi[0] - lo[0] == pytest.approx(1.0, abs=1e-5)
    # The normals follow the transform: on the outside, pointing away from the part's centre.
    outward = np.sum((parts["right"].positions - (3.0, 0.0, 0.0)) * parts["right"].normals, axis=1)
    assert outward.min() > 0.0
    merged = load_mesh(path)
    assert merged.triangle_count == 12 + len(ball.faces)
    assert merged.vertex_count == parts["left"].vertex_count + parts["right"].vertex_count


def test_obj_with_several_objects_gives_one_part_each(tmp_path):
    scene = trimesh.Scene()
    scene.add_geometry(_box(), node_name="a", geom_name="a")
    scene.add_geometry(_box((0.5, 0.5, 0.5)), node_name="b", geom_name="b",
                       transform=trimesh.transformations.translation_matrix([0, 2, 0]))
    path = tmp_path / "parts.obj"
    scene.export(path)
    parts = load_meshes(path)
    assert sorted(parts) == ["a", "b"]
    assert np.allclose(parts["b"].bounds()[0], (-0.25, 1.75, -0.25), atol=1e-6)


def test_obj_without_normals_or_uvs_gets_smooth_outward_normals(tmp_path):
    path = tmp_path / "ball.obj"
    path.write_text(trimesh.exchange.obj.export_obj(trimesh.creation.icosphere(2), include_normals=False))
    assert "vn " not in path.read_text() and "vt " not in path.read_text()
    mesh = load_mesh(path)
    _check_mesh(mesh, triangles=320)
    assert mesh.uvs is None and mesh.tangents is None
    # Smooth normals of a sphere are close to the radial direction.
    radial = mesh.positions / np.linalg.norm(mesh.positions, axis=1, keepdims=True)
    assert np.min(np.sum(radial * mesh.normals, axis=1)) > 0.98


def test_uvs_are_kept_flipped_to_top_origin_and_tangents_added(tmp_path):
    box = _box()
    uv = np.random.default_rng(1).random((len(box.vertices), 2))
    box.visual = trimesh.visual.TextureVisuals(uv=uv)
    path = tmp_path / "uv.obj"
    box.export(path)
    mesh = load_mesh(path)
    assert mesh.uvs is not None and mesh.tangents is not None
    # trimesh's v = 0 is the bottom row; the engine's is the top row.
    assert np.allclose(np.sort(mesh.uvs[:, 1]), np.sort(1.0 - uv[:, 1]), atol=1e-6)
    assert np.all(np.isfinite(mesh.tangents))


def test_file_normals_are_used_when_present(tmp_path):
    path = tmp_path / "n.obj"
    box = _box()
    path.write_text(trimesh.exchange.obj.export_obj(box, include_normals=True))
    normals = np.tile([0.0, 0.0, 1.0], (len(box.vertices), 1))
    text = "\n".join("vn 0 0 1" if line.startswith("vn ") else line for line in path.read_text().splitlines())
    path.write_text(text)
    mesh = load_mesh(path)
    assert np.allclose(mesh.normals, normals[: mesh.vertex_count])


def test_vertex_colours_are_kept(tmp_path):
    box = _box()
    box.visual.vertex_colors = np.tile([255, 0, 51, 255], (len(box.vertices), 1))
    path = tmp_path / "c.ply"
    box.export(path)
    mesh = load_mesh(path)
    assert mesh.colors is not None
    assert np.allclose(mesh.colors, (1.0, 0.0, 0.2, 1.0), atol=1e-6)


def test_degenerate_triangles_are_dropped_and_non_manifold_is_fine(tmp_path):
    path = tmp_path / "degenerate.obj"
    path.write_text(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 0 0 1\n"
        "f 1 2 3\n"  # a good triangle
        "f 1 2 4\n"  # collinear corners: zero area
        "f 1 1 3\n"  # a repeated corner
        "f 1 2 5\n"  # a second good one sharing edge 1-2 ...
        "f 2 1 5\n"  # ... and a third on the same edge: non-manifold
    )
    mesh = load_mesh(path)
    _check_mesh(mesh, triangles=3)


def test_loading_the_same_file_twice_returns_the_cached_mesh(tmp_path):
    path = tmp_path / "box.stl"
    _box().export(path)
    first = load_mesh(path)
    assert load_mesh(path) is first
    assert load_mesh(str(tmp_path / "." / "box.stl")) is first  # the resolved path is the key
    assert load_meshes(path)["box"] is load_meshes(path)["box"]
    # A changed file (new size and time) is read again.
    _box((3.0, 1.0, 1.0)).export(path)
    os.utime(path, ns=(path.stat().st_atime_ns, path.stat().st_mtime_ns + 1_000_000))
    second = load_mesh(path)
    assert second is not first
    assert second.bounds()[1][0] == pytest.approx(1.5)


def test_missing_file_names_the_file(tmp_path):
    path = tmp_path / "nowhere.obj"
    with pytest.raises(ResourceError, match=r"nowhere\.obj.*file not found"):
        load_mesh(path)


def test_unsupported_extension_names_the_file_and_the_choices(tmp_path):
    path = tmp_path / "model.fbx"
    path.write_bytes(b"x")
    with pytest.raises(ResourceError, match=r"model\.fbx.*'\.fbx'.*\.obj, \.gltf, \.glb, \.ply, \.stl"):
        load_mesh(path)


@pytest.mark.parametrize("ext", ["glb", "obj", "stl", "ply"])
def test_corrupt_bytes_raise_a_resource_error_naming_the_file(tmp_path, ext):
    path = tmp_path / f"broken.{ext}"
    path.write_bytes(b"\x00\xffnot a mesh at all\x01" * 7)
    with pytest.raises(ResourceError, match=rf"broken\.{ext}"):
        load_mesh(path)


@pytest.mark.parametrize("ext", ["obj", "glb", "stl"])
def test_empty_file_is_an_error(tmp_path, ext):
    path = tmp_path / f"empty.{ext}"
    path.write_bytes(b"")
    with pytest.raises(ResourceError, match=rf"empty\.{ext}.*empty"):
        load_mesh(path)


def test_file_with_only_vertices_holds_no_triangles(tmp_path):
    path = tmp_path / "points.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n")
    with pytest.raises(ResourceError, match=r"points\.obj.*no triangles"):
        load_mesh(path)


def test_importing_the_loader_does_not_import_trimesh():
    code = "import gandalf_core.resources.mesh_loader, sys; print('trimesh' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_a_file_rewritten_with_the_same_size_and_time_is_read_again(tmp_path):
    """The cache is keyed by content: other bytes of the same length, written with the old modification time,
    must not return the old geometry."""
    path = tmp_path / "tri.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    stat = path.stat()
    first = load_mesh(path)
    path.write_text("v 0 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\n")  # the same length, one coordinate changed
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert path.stat().st_size == stat.st_size and path.stat().st_mtime_ns == stat.st_mtime_ns
    second = load_mesh(path)
    assert second is not first and second.bounds()[1][0] == pytest.approx(2.0)
