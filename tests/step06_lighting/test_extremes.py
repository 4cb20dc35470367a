"""Bad and extreme inputs with the reference solutions, in both APIs: meshes without normals or UVs,
degenerate triangles, no lights, too many lights, a light inside the surface, extreme shininess, and scenes
that must not share lights. Besides the pixels, the numpy twin of the shading is checked for NaN/Inf."""

from __future__ import annotations

import numpy as np
import pytest
from step06_helpers import (
    add_lights,
    ambient,
    blinn_phong_np,
    directional,
    inner,
    make_app,
    point,
    reference_sphere,
    render,
    shade_np,
    sphere_scene,
)

from gandalf_core import Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, MeshData
from gandalf_core.resources.mesh_loader import load_mesh
from step06_lighting import solutions

PHONG = MaterialData("phong", color=(0.8, 0.5, 0.3), params={"specular": 0.5, "shininess": 24.0})


def _quad_scene(mesh: MeshData, lights) -> Scene:
    """``mesh`` seen from +Z (camera at z = 3), lit by ``lights``."""
    scene = Scene("quad")
    scene.assets.mesh("m", mesh)
    scene.assets.material("M", PHONG)
    scene.create_entity(TransformComponent(), MeshComponent("m"), MaterialComponent("M"))
    add_lights(scene, lights)
    scene.create_entity(TransformComponent((0, 0, 3.0)), CameraComponent(45.0, 0.1, 10.0))
    return scene


def _square(extra_triangles=()) -> MeshData:
    positions = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], [0.5, 0.5, 0], [0.2, 0.2, 0]], float)
    indices = [[0, 1, 2], [0, 2, 3], *extra_triangles]
    return MeshData(positions, indices=np.array(indices, dtype=np.uint32)).with_normals()


def test_mesh_file_without_normals_or_uvs_renders(backend, tmp_path):
    path = tmp_path / "ball.obj"
    import trimesh

    path.write_text(trimesh.exchange.obj.export_obj(trimesh.creation.icosphere(3), include_normals=False))
    mesh = load_mesh(path)
    assert mesh.uvs is None
    scene = sphere_scene(PHONG, [directional((0, 0, 1))])
    scene.assets.mesh("sphere", mesh)  # replace the UV sphere by the loaded one
    image = render(backend, solutions, scene)
    expected, hit = reference_sphere(PHONG, [directional((0, 0, 1))])
    # An icosphere of 1280 faces is coarser than the UV sphere: a looser tolerance (mean <= 2.5 steps).
    assert np.abs(image[..., :3] - expected)[inner(hit, 3)].mean() <= 2.5


def test_degenerate_triangles_change_nothing(backend):
    lights = [directional((0.3, 0.4, 1.0))]
    clean = render(backend, solutions, _quad_scene(_square(), lights))
    # A zero-area sliver (collinear corners) and a triangle with a repeated corner.
    dirty = render(backend, solutions, _quad_scene(_square([[0, 4, 5], [1, 1, 2]]), lights))
    assert np.array_equal(clean, dirty)
    assert clean[36, 48, :3].min() > 20


@pytest.mark.parametrize("ambient_rgb", [(0.0, 0.0, 0.0), (0.3, 0.25, 0.2)])
def test_no_lights_leaves_ambient_only(backend, ambient_rgb):
    lights = [ambient(ambient_rgb)]
    image = render(backend, solutions, sphere_scene(PHONG, lights))
    expected, hit = reference_sphere(PHONG, lights)
    region = inner(hit)
    assert np.abs(image[..., :3].astype(int) - expected)[region].max() <= 1
    # Ambient alone is flat: every sphere pixel has the same colour.
    assert len(np.unique(image[region][:, :3], axis=0)) == 1


def test_more_lights_than_the_block_holds_are_dropped_with_a_warning(backend):
    lights = [point((np.cos(a) * 3, np.sin(a) * 3, 2.0), (1, 1, 1), 0.05) for a in np.linspace(0, 6, 80)]
    with pytest.warns(UserWarning, match="64"):
        image = render(backend, solutions, sphere_scene(PHONG, lights))
    expected, hit = reference_sphere(PHONG, lights[:64])
    assert np.abs(image[..., :3] - expected)[inner(hit)].mean() <= 1.0


@pytest.mark.parametrize("light_range", [0.0, 2.0])
def test_point_light_exactly_on_the_surface(backend, light_range):
    # The light sits at the quad's centre; an odd image size puts a pixel centre right on it (distance ~0).
    key = directional((0.3, 0.4, 1.0), (0.5, 0.5, 0.5))
    on_surface = point((0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 0.5, light_range)
    base = render(backend, solutions, _quad_scene(_square(), [key]), size=(97, 73)).astype(int)
    image = render(backend, solutions, _quad_scene(_square(), [key, on_surface]), size=(97, 73)).astype(int)
    # A NaN would store 0 (or garbage): every pixel keeps at least the key light's share, none turns black.
    assert np.all(image[..., :3] >= base[..., :3] - 1)
    assert image[36, 48, :3].min() >= base[36, 48, :3].min()
    # The twin at the exact point: finite, and the light counts as head-on (l = n).
    p = np.zeros((1, 3))
    n = np.array([[0.0, 0.0, 1.0]])
    out = shade_np(p, n, n, (0.8, 0.5, 0.3), 0.5, 24.0, [on_surface])
    assert np.all(np.isfinite(out)) and out.min() > 0.0


@pytest.mark.parametrize("shininess", [0.0, 1e-6, 1.0, 1e4, 1e8])
def test_numpy_twin_is_finite_for_extreme_shininess_and_vectors(shininess):
    rng = np.random.default_rng(3)
    n = rng.normal(size=(500, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    to_light = n.copy()
    to_light[::2] = -n[::2]  # light straight behind
    v = -to_light  # l + v = 0: no half vector
    out = blinn_phong_np(n, to_light, v, np.ones(3), np.full(3, 0.5), 1.0, shininess)
    assert np.all(np.isfinite(out)) and out.min() >= 0.0


@pytest.mark.parametrize("shininess", [0.0, 1e4])
def test_extreme_shininess_has_no_speckles(backend, shininess):
    material = MaterialData("phong", color=(0.5, 0.5, 0.5), params={"specular": 1.0, "shininess": shininess})
    lights = [directional((0.5, 0.5, 1.0))]
    image = render(backend, solutions, sphere_scene(material, lights))
    expected, hit = reference_sphere(material, lights)
    diff = np.abs(image[..., :3] - expected)[inner(hit)]
    assert diff.max() <= 2, "speckles: isolated pixels far from the reference"


def test_lights_of_one_scene_never_change_another(backend):
    def scene(name: str, light_colour) -> Scene:
        s = sphere_scene(PHONG, [directional((0.2, 0.6, 1.0), light_colour)])
        s.name = name
        return s

    with make_app(backend, solutions) as app:
        a = app.add_scene(scene("a", (1.0, 1.0, 1.0)))
        b = app.add_scene(scene("b", (0.2, 0.4, 1.0)))
        app.run(frames=1)
        first = app.capture()
        app.switch_scene(b)
        app.run(frames=1)
        b.create_entity(TransformComponent((0, 0, 2.0)), LightComponent("point", (1.0, 0.0, 0.0), 4.0))
        b.create_entity(TransformComponent(), LightComponent("ambient", (0.5, 0.5, 0.5)))
        app.run(frames=1)
        lit_b = app.capture()
        app.switch_scene(a)
        app.run(frames=1)
        again = app.capture()
    assert app.scenes.active is a
    assert np.array_equal(first, again)
    assert not np.array_equal(first, lit_b)

