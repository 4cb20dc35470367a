"""The exploding bunny rendered in both APIs (OpenGL: geometry shader; WebGPU: vertex pulling), and the
technique's engine-side rules.

Graded per API, at 96×72: at t = 0 the exploding program draws exactly the unexploded bunny (PSNR ≥ 40 dB against
the plain ``explode_lit`` shader; the solution measures inf, identical pictures); at the peak (half a period) the
covered area grows by at least 25 % (the solution: +67 %) and the silhouette's bounding box matches the
float64 numpy exploded triangles projected with the scene's camera within 1.5 pixels (the solution: 0.54 px in both).
Not graded: the two APIs agree on the tour picture at 640×480 (PSNR ≥ 35 dB; measured 68.8 dB), the clock
system, and clear errors for bad parameters and mismatched meshes.
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest
from step07_helpers import check_tour_pictures_agree

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.components import InfoComponent, MaterialComponent, MeshComponent
from gandalf_core.render.render_system import RenderSystem
from gandalf_core.resources import MaterialData, MeshData, ResourceError
from gandalf_tools.grading.shader_box import on_shader_box
from gandalf_tools.testing import compare_images, psnr
from step07_advanced.explode import scene as explode
from step07_advanced.explode.scene import (
    BACKGROUND,
    PERIOD,
    ExplodeComponent,
    ExplodeSystem,
    GeometryShaderRoute,
    PullingRoute,
)

SIZE = (96, 72)
ROTATION = (0.0, 35.0, 0.0)
MIN_GROWTH = 1.25
BOX_TOLERANCE = 1.5


def _route(backend: str, app: Application):
    return GeometryShaderRoute() if backend == "opengl" else PullingRoute(app.renderer)


def _app(backend: str, impl, size=SIZE) -> Application:
    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    importlib.import_module(f"step07_advanced.explode.{backend}").register_shaders(app, impl)
    return app


@on_shader_box  # the student's shaders run in the grader's shader process
def render_bunny(backend: str, impl, t: float | None, size=SIZE) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(picture, world matrix, view-projection) of the bunny exploded to time ``t`` (None: the plain shader)."""
    with _app(backend, impl, size) as app:
        scene = Scene("explode test")
        transform = TransformComponent(rotation=ROTATION)
        if t is None:
            scene.assets.mesh("bunny", explode.bunny())
            scene.assets.material("lit", explode.lit_material())
            scene.create_entity(transform, MeshComponent("bunny"), MaterialComponent("lit"))
        else:
            route = _route(backend, app)
            explode.add_exploding_mesh(scene, route, "bunny", explode.bunny(), time=t, speed=0.0, transform=transform)
            scene.add_system(ExplodeSystem(route))
        explode.add_view(scene)
        app.add_scene(scene)
        app.run(frames=1)
        if backend == "opengl":
            assert app.renderer.ctx.error == "GL_NO_ERROR"
        render = next(s for s in scene.systems if isinstance(s, RenderSystem))
        view, projection, _eye, _ = render.camera()
        return app.capture(), transform.world.copy(), projection @ view


def coverage(image: np.ndarray) -> np.ndarray:
    """Pixels that are not the background colour."""
    background = np.round(np.asarray(BACKGROUND) * 255.0)
    return np.abs(image[..., :3].astype(np.float64) - background).max(axis=2) > 3.0


def projected_box(corners: np.ndarray, view_projection: np.ndarray, size=SIZE) -> np.ndarray:
    """(x0, y0, x1, y1) in pixels (y down) of world-space points projected by ``view_projection``."""
    clip = np.c_[corners.reshape(-1, 3), np.ones(corners.size // 3)] @ view_projection.T
    ndc = clip[:, :2] / clip[:, 3:4]
    x = (ndc[:, 0] * 0.5 + 0.5) * size[0]
    y = (0.5 - ndc[:, 1] * 0.5) * size[1]
    return np.array([x.min(), y.min(), x.max(), y.max()])


def covered_box(mask: np.ndarray) -> np.ndarray:
    """(x0, y0, x1, y1) pixel edges of the covered pixels."""
    ys, xs = np.nonzero(mask)
    return np.array([xs.min(), ys.min(), xs.max() + 1.0, ys.max() + 1.0])


@pytest.mark.exercise("explode_offset")
def test_rendered_explosion_rests_at_zero_and_grows_at_the_peak(impl, backend):
    plain, _, _ = render_bunny(backend, impl, None)
    rest, world, view_projection = render_bunny(backend, impl, 0.0)
    compare_images(rest, plain, f"explode-{backend}-rest", min_psnr=40.0)
    peak, _, _ = render_bunny(backend, impl, PERIOD / 2)
    grown = coverage(peak).sum() / max(coverage(rest).sum(), 1)
    assert grown >= MIN_GROWTH, (
        f"{backend}: at the peak (t = {PERIOD / 2} s) the bunny covers {grown:.2f}× its area at rest; expected ≥ "
        f"{MIN_GROWTH} (about 1.67). Hint: explode_offset must move each face by amount · n at half a period")
    corners = explode.exploded_triangles_np(explode.bunny(), world, PERIOD / 2)
    expected = projected_box(corners, view_projection)
    got = covered_box(coverage(peak))
    assert np.abs(got - expected).max() <= BOX_TOLERANCE, (
        f"{backend}: silhouette box at the peak (x0, y0, x1, y1) = {got.tolist()} px, the numpy exploded bunny gives "
        f"{np.round(expected, 1).tolist()} (tolerance {BOX_TOLERANCE} px). Hint: the offset is amount · unit normal")


def test_both_apis_agree_on_the_tour_picture(impl):
    """The tour's picture (TOUR_FRAMES at 60 fps, 640×480) from both variant files."""
    check_tour_pictures_agree("explode", impl, explode.TOUR_FRAMES)


def test_the_clock_advances_the_material_time(impl):
    """The clock system's time reaches the material (whatever the offset function under test does with it)."""
    with Application("opengl", 32, 24, headless=True, fixed_dt=0.25) as app:
        from step07_advanced.explode.opengl import register_shaders

        register_shaders(app, impl)
        scene = explode.build_scene(impl, GeometryShaderRoute(), time=1.0, speed=2.0)
        app.add_scene(scene)
        app.run(frames=3)
        material = app.renderer.materials.get("bunny")
        assert float(material.values["explode_time"]) == pytest.approx(1.0 + 3 * 2.0 * 0.25)


@pytest.mark.parametrize(("key", "value"), [("amount", -0.1), ("period", 0.0), ("period", -2.0),
                                            ("amount", float("nan")), ("period", "soon")])
def test_bad_amount_or_period_is_refused_naming_it(key, value):
    kwargs = {"amount": 0.3, "period": 2.0, key: value}
    with pytest.raises(ResourceError, match=key):
        explode.explode_material("explode", **kwargs)


def test_pulled_material_with_a_mesh_of_the_wrong_vertex_count_names_both():
    with Application("webgpu", 16, 16, headless=True) as app:
        route = PullingRoute(app.renderer)
        scene = Scene("bad")
        explode.add_exploding_mesh(scene, route, "bunny", explode.bunny())
        scene.assets.mesh("small", MeshData(np.zeros((9, 3)), name="small"))
        scene.add_system(ExplodeSystem(route))
        with pytest.raises(ResourceError, match=r"mesh 'small'.*material 'bunny'.*3 x 3280"):
            scene.create_entity(InfoComponent("wrong"), TransformComponent(), ExplodeComponent(),
                                MeshComponent("small"), MaterialComponent("bunny"))


def test_pulled_material_needs_buffers_of_the_route():
    route = PullingRoute(renderer=None)
    with pytest.raises(ResourceError, match="material 'loose'.*buffers"):
        route.check("m", MeshData(np.zeros((3, 3))), "loose", MaterialData("explode_pulled"))


def test_geometry_route_needs_vertex_normals():
    mesh = MeshData(np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]]), name="flat")
    with pytest.raises(ResourceError, match="mesh 'flat'.*normals"):
        GeometryShaderRoute().check("flat", mesh, "bunny", explode.explode_material("explode"))


def test_numpy_reference_rests_and_peaks():
    mesh = explode.bunny()
    model = np.eye(4)
    rest = explode.exploded_triangles_np(mesh, model, 0.0)
    assert np.allclose(rest, mesh.positions[mesh.triangles().astype(np.int64)], atol=1e-12)
    peak = explode.exploded_triangles_np(mesh, model, PERIOD / 2)
    moved = np.linalg.norm(peak - rest, axis=2)
    assert np.allclose(moved[moved > 0], explode.AMOUNT)
    assert psnr(np.zeros((2, 2, 4), np.uint8), np.zeros((2, 2, 4), np.uint8)) == float("inf")
