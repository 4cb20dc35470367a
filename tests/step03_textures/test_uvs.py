"""Grades exercise 2, ``cube_cross_uvs``: numerically against the cube primitive's own face UVs, and by
rendering each face of a box head-on in both APIs and comparing with its square of a test atlas."""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core import Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, MeshData, TextureData, cube
from step03_textures.atlas import CROSS_CELLS, CROSS_GRID, FACE_FRAMES
from step03_textures.scene import SHADER, with_uvs

FACES = list(FACE_FRAMES)
# Cube vertices come in groups of 4 per face, in primitives' face order +X, -X, +Y, -Y, +Z, -Z.
CUBE_FACE_ORDER = ["+X", "-X", "+Y", "-Y", "+Z", "-Z"]


def _expected(mesh: MeshData) -> np.ndarray:
    """Per face, the cube's own 0..1 UVs squeezed into that face's cell of the 4 x 3 cross."""
    cells = np.repeat([CROSS_CELLS[f] for f in CUBE_FACE_ORDER], 4, axis=0)
    return (cells + mesh.uvs.astype(np.float64)) / np.array(CROSS_GRID)


@pytest.mark.exercise("cube_cross_uvs")
def test_unit_cube_faces_land_in_their_cells(impl):
    mesh = cube(1.0)
    uv = np.asarray(impl.cube_cross_uvs(mesh.positions, mesh.normals), dtype=np.float64)
    assert uv.shape == (24, 2)
    assert np.allclose(uv, _expected(mesh), atol=1e-6)


@pytest.mark.exercise("cube_cross_uvs")
@pytest.mark.parametrize("scale,offset", [((2.0, 1.0, 0.5), (0.0, 0.0, 0.0)), ((3.0, 3.0, 3.0), (10.0, -4.0, 2.5))])
def test_any_axis_aligned_box(impl, scale, offset):
    mesh = cube(1.0)
    positions = mesh.positions.astype(np.float64) * scale + offset
    uv = np.asarray(impl.cube_cross_uvs(positions, mesh.normals), dtype=np.float64)
    assert np.allclose(uv, _expected(mesh), atol=1e-6)


@pytest.mark.exercise("cube_cross_uvs")
def test_the_dominant_normal_axis_picks_the_face(impl):
    # Slightly bent (smoothed) normals still pick the face of their largest component.
    mesh = cube(1.0)
    normals = mesh.normals.astype(np.float64) + 0.3 * np.sign(mesh.positions)
    uv = np.asarray(impl.cube_cross_uvs(mesh.positions, normals), dtype=np.float64)
    assert np.allclose(uv, _expected(mesh), atol=1e-6)


@pytest.mark.exercise("cube_cross_uvs")
@pytest.mark.parametrize("positions,normals", [
    (np.zeros((4, 2)), np.zeros((4, 3))),
    (np.ones((4, 3)) * np.arange(4)[:, None], np.ones((3, 3))),
    (np.array([[0, 0, 0], [1, 1, np.nan], [1, 0, 1]]), np.eye(3)),
    (np.array([[0, 0, 0], [1, 1, 0], [1, 0, 0]]), np.eye(3)),  # flat: no volume
    (np.array([[0, 0, 0], [1, 1, 1], [1, 0, 1]]), np.array([[0, 0, 0], [0, 1, 0], [1, 0, 0]])),  # zero normal
    (np.zeros((0, 3)), np.zeros((0, 3))),  # N > 0
    (np.array([[0, 0, 0], [1, 1, np.inf], [1, 0, 1]]), np.eye(3)),  # "NaN/Inf": infinities too
    (np.array([[0, 0, 0], [1, 1, 1], [1, 0, 1]]), np.array([[1, 0, 0], [0, -np.inf, 0], [0, 0, 1]])),
])
def test_bad_input_raises_value_error(impl, positions, normals):
    with pytest.raises(ValueError):
        impl.cube_cross_uvs(positions, normals)


CELL = 16  # texels per face square in the test atlas
BLOCKS = 4  # each square is a 4 x 4 grid of blocks with unique colours
SIZE = 48  # rendered image, pixels; one block = 12 x 12 pixels


def _test_atlas() -> np.ndarray:
    """A 64 x 48 atlas: 12 cells x 16 blocks, every block a different colour (no symmetry to hide errors)."""
    cols, rows = CROSS_GRID
    idx = np.arange(cols * rows * BLOCKS * BLOCKS)
    palette = np.stack([(idx * 37) % 251, (idx * 91 + 60) % 241, (idx * 53 + 120) % 239], axis=1).astype(np.uint8)
    blocks = palette.reshape(rows * BLOCKS, cols * BLOCKS, 3)
    return np.repeat(np.repeat(blocks, CELL // BLOCKS, axis=0), CELL // BLOCKS, axis=1)


@pytest.mark.exercise("cube_cross_uvs")
@pytest.mark.parametrize("face", FACES)
def test_each_face_shows_its_square_upright(impl, backend, render_scene, face):
    atlas = _test_atlas()
    mesh = cube(2.0)
    scene = Scene("atlas box")
    scene.assets.texture("atlas", TextureData.from_array(atlas, filter="nearest", mipmaps=False, name="atlas"))
    scene.assets.mesh("box", with_uvs(mesh, np.asarray(impl.cube_cross_uvs(mesh.positions, mesh.normals)), "box"))
    scene.assets.material("M", MaterialData(SHADER, ["atlas"], color=(1.0, 1.0, 1.0)))
    scene.create_entity(TransformComponent(), MeshComponent("box"), MaterialComponent("M"))
    # An orthographic camera in front of the face, its up along the face's image-up: the face fills the view.
    normal, _right, up = (np.array(v, dtype=np.float64) for v in FACE_FRAMES[face])
    eye = 4.0 * normal
    scene.create_entity(
        TransformComponent(eye, quaternion=look_at_rotation(eye, (0.0, 0.0, 0.0), up)),
        CameraComponent(near=0.5, far=10.0, projection="orthographic", height=2.0),
    )
    image, _ = render_scene(backend, scene, SIZE, SIZE)
    col, row = CROSS_CELLS[face]
    square = atlas[row * CELL:(row + 1) * CELL, col * CELL:(col + 1) * CELL]
    expected = np.repeat(np.repeat(square, SIZE // CELL, axis=0), SIZE // CELL, axis=1).astype(int)
    wrong = np.any(np.abs(image[..., :3].astype(int) - expected) > 1, axis=-1)
    # Pixel centres never fall on a block edge, so every pixel must match (one 8-bit step for sRGB rounding).
    assert wrong.mean() <= 0.01, f"face {face}: {wrong.mean():.0%} of the pixels show the wrong part of the atlas"
