"""Grades exercise 2: ``ngon_mesh`` (an indexed, counter-clockwise triangle fan) and the ``NGonSystem``.

The area check renders the polygon in white with back-face culling on (a clockwise fan would vanish) on a
128x128 target, where clip space's 2x2 square covers the whole image, and compares the covered fraction with
the analytic area ``n/2 r^2 sin(2 pi / n)`` / 4. Tolerance: 2 % relative (the rasteriser samples pixel
centres; along the edges that alone costs up to ~1.2 % at this size).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from gandalf_core import Scene
from gandalf_core.app.cli import load_impl
from gandalf_core.components import MeshComponent
from gandalf_core.resources import MeshData
from step02_triangle.components import NGonComponent
from step02_triangle.opengl import create_app as create_opengl
from step02_triangle.preview import render_mesh
from step02_triangle.scene import CENTRES, CLEAR_COLOR, SIZE
from step02_triangle.webgpu import create_app as create_webgpu

AREA_TOLERANCE = 0.02
RADIUS = 0.8


def _white(mesh: MeshData) -> MeshData:
    """The same geometry in white, so that coverage is easy to count whatever the student's colours."""
    return MeshData(mesh.positions, colors=np.ones((mesh.vertex_count, 4)), indices=mesh.indices)


@pytest.mark.exercise("ngon_mesh")
@pytest.mark.parametrize("sides", [3, 4, 5, 8, 32])
def test_rendered_area_matches_the_polygon(impl, backend, sides):
    image = render_mesh(backend, _white(impl.ngon_mesh(sides, RADIUS)), 128, 128, cull="back")
    covered = float((image[..., :3].min(axis=2) > 127).mean())
    expected = sides / 2 * RADIUS**2 * math.sin(2 * math.pi / sides) / 4.0
    assert covered == pytest.approx(expected, rel=AREA_TOLERANCE), (
        f"{sides}-gon covers {covered:.4f} of the image, expected {expected:.4f}"
        + (" (nothing drawn: is it wound clockwise, so back-face culling drops it?)" if covered == 0 else "")
    )


@pytest.mark.exercise("ngon_mesh")
@pytest.mark.parametrize("sides", [3, 6, 17])
def test_fan_structure_and_winding(impl, sides):
    mesh = impl.ngon_mesh(sides, 0.5)
    assert isinstance(mesh, MeshData)
    assert mesh.indices is not None, "the fan must use an index buffer"
    assert mesh.vertex_count == sides + 1 and mesh.triangle_count == sides
    assert mesh.colors is not None and np.allclose(mesh.colors[:, 3], 1.0)
    p = mesh.positions.astype(np.float64)
    assert np.allclose(p[:, 2], 0.0)
    radii = np.sort(np.linalg.norm(p[:, :2], axis=1))
    assert radii[0] == pytest.approx(0.0, abs=1e-6) and np.allclose(radii[1:], 0.5, atol=1e-6)
    tri = mesh.triangles().astype(int)
    a, b, c = p[tri[:, 0], :2], p[tri[:, 1], :2], p[tri[:, 2], :2]
    signed = (b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0]
    assert (signed > 0).all(), "every triangle must wind counter-clockwise seen from +Z"
    assert 0.5 * signed.sum() == pytest.approx(sides / 2 * 0.25 * math.sin(2 * math.pi / sides), rel=1e-5)


@pytest.mark.exercise("ngon_mesh")
@pytest.mark.parametrize("sides", [2, 0, -3, 4.5, "6"])
def test_too_few_or_invalid_sides_raise(impl, sides):
    with pytest.raises(ValueError, match="sides"):
        impl.ngon_mesh(sides, 1.0)


@pytest.mark.exercise("ngon_mesh")
@pytest.mark.parametrize("radius", [0.0, -1.0, math.nan, math.inf])
def test_invalid_radius_raises(impl, radius):
    with pytest.raises(ValueError, match="radius"):
        impl.ngon_mesh(5, radius)


@pytest.mark.exercise("NGonSystem")
def test_system_registers_meshes_under_the_mesh_components_name(impl):
    scene = Scene("ngons")
    scene.create_entity(NGonComponent(sides=5, radius=0.7), MeshComponent("pentagon"))
    scene.add_system(impl.NGonSystem())  # entities that existed before the system
    scene.create_entity(NGonComponent(sides=9, radius=0.3), MeshComponent("nonagon"))  # and after
    registered = sorted(scene.assets.meshes)
    for name in ("pentagon", "nonagon"):
        assert name in scene.assets.meshes, (
            f"for NGonComponents with MeshComponent('pentagon') and MeshComponent('nonagon'): got the meshes "
            f"{registered}, expected {name!r} among them (register each mesh under its MeshComponent's name)")
    pentagon, nonagon = scene.assets.meshes["pentagon"], scene.assets.meshes["nonagon"]
    assert (pentagon.vertex_count, pentagon.triangle_count) == (6, 5)
    assert (nonagon.vertex_count, nonagon.triangle_count) == (10, 9)
    assert np.linalg.norm(nonagon.positions[:, :2], axis=1).max() == pytest.approx(0.3, abs=1e-6)


@pytest.mark.exercise("NGonSystem")
@pytest.mark.parametrize("create_app", [create_opengl, create_webgpu], ids=["opengl", "webgpu"])
def test_the_step_scene_shows_the_hexagon(impl, create_app, monkeypatch):
    # Graded on the system alone: its mesh comes from the reference ngon_mesh, whatever the student's does.
    monkeypatch.setattr(f"{impl.__name__}.ngon.ngon_mesh", load_impl("step02_triangle").ngon.ngon_mesh)
    with create_app(headless=True, student=impl.__name__.endswith("exercises"), width=160, height=120) as app:
        app.run(frames=1)
        image = app.capture().astype(int)
        assert app.renderer.stats["draw_calls"] == 3
    x, y, _ = CENTRES["ngon"]
    row, col = int((1 - y) / 2 * 120), int((x + 1) / 2 * 160)
    background = np.round(np.array(CLEAR_COLOR) * 255)
    assert np.abs(image[row, col, :3] - background).max() > 40, "no n-gon in the middle of the picture"
    # Just outside the hexagon's left and right corners (radius 0.5 scaled by SIZE) is background.
    half_width = int(0.5 * SIZE * 0.75 / 2 * 160)
    for c in (col - half_width - 3, col + half_width + 3):
        assert np.abs(image[row, c, :3] - background).max() <= 1
