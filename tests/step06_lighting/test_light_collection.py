"""Exercise 2: ``LightCollectionSystem.pack``, graded against the core packer for random lights and by
rendering many lights with it (the picture must equal the one made with the core LightSystem)."""

from __future__ import annotations

import numpy as np
import pytest
from step06_helpers import render, sphere_scene

from gandalf_core import Scene, TransformComponent, TransformSystem
from gandalf_core.app.cli import load_impl
from gandalf_core.components import LightComponent
from gandalf_core.render.frame import LIGHTS_BYTES, MAX_LIGHTS
from gandalf_core.resources import MaterialData
from gandalf_core.systems.light_system import LightSystem, pack_lights


def _random_lights(rng: np.random.Generator, count: int) -> list[tuple[LightComponent, TransformComponent]]:
    kinds = ["point", "directional", "ambient"]
    out = []
    for _ in range(count):
        light = LightComponent(kinds[rng.integers(3)], rng.random(3), float(rng.uniform(0, 4)),
                               float(rng.choice([0.0, rng.uniform(0.5, 10)])))
        transform = TransformComponent(rng.uniform(-5, 5, 3), rng.uniform(-180, 180, 3), rng.uniform(0.2, 3, 3))
        out.append((light, transform))
    return out


def _packed(system: LightSystem, lights) -> tuple[bytes, bytes]:
    """(the system's bytes, the core's bytes) after one update of a scene holding ``lights``."""
    _update(system, lights)
    return system.data, pack_lights(system.components)


def _update(system: LightSystem, lights) -> None:
    """One update of a scene holding ``lights`` with ``system`` (only the student's code runs)."""
    scene = Scene("lights")
    for light, transform in lights:
        scene.create_entity(transform, light)
    scene.add_system(TransformSystem())
    scene.add_system(system)
    scene.update(0.0)


def _assert_same_block(actual: bytes, expected: bytes) -> None:
    assert isinstance(actual, bytes) and len(actual) == LIGHTS_BYTES
    a, e = np.frombuffer(actual, np.float32), np.frombuffer(expected, np.float32)
    assert np.frombuffer(actual, np.int32)[:4].tolist() == np.frombuffer(expected, np.int32)[:4].tolist()
    assert np.allclose(a[4:], e[4:], rtol=1e-6, atol=1e-7)


@pytest.mark.exercise("LightCollectionSystem")
@pytest.mark.parametrize("seed,count", [(0, 1), (1, 5), (2, 20), (3, 60)])
def test_pack_matches_the_core_packer(impl, seed, count):
    actual, expected = _packed(impl.LightCollectionSystem(), _random_lights(np.random.default_rng(seed), count))
    _assert_same_block(actual, expected)


@pytest.mark.exercise("LightCollectionSystem")
def test_no_lights_is_an_empty_block(impl):
    actual, expected = _packed(impl.LightCollectionSystem(), [])
    _assert_same_block(actual, expected)
    assert not np.any(np.frombuffer(actual, np.float32))


@pytest.mark.exercise("LightCollectionSystem")
def test_more_than_max_lights_warns_and_keeps_the_first(impl):
    lights = [(LightComponent("point", (1, 1, 1), 1.0), TransformComponent((i, 0, 0))) for i in range(MAX_LIGHTS + 6)]
    system = impl.LightCollectionSystem()
    with pytest.warns(UserWarning, match=str(MAX_LIGHTS)):  # only the student's code runs inside this block
        _update(system, lights)
    actual = system.data
    with pytest.warns(UserWarning):
        expected = pack_lights([(light, t) for light, t in lights])
    _assert_same_block(actual, expected)
    assert np.frombuffer(actual, np.int32)[0] == MAX_LIGHTS


@pytest.mark.exercise("LightCollectionSystem")
def test_rendering_with_the_system_equals_the_core_lights(impl, backend):
    lights = _random_lights(np.random.default_rng(7), 24)
    material = MaterialData("phong", color=(0.7, 0.7, 0.7), params={"specular": 0.4, "shininess": 32.0})
    # Both pictures use the reference's shading (blinn_phong is another exercise; in a student's release, which has no
    # reference, the student's own): only the light block differs between them, and the student's shaders are not
    # compiled in the grading process (the shader process runs them, for blinn_phong's own tests).
    shading = load_impl("step06_lighting")
    mine = render(backend, shading, sphere_scene(material, lights, light_system=impl.LightCollectionSystem()))
    core = render(backend, shading, sphere_scene(material, lights, light_system=LightSystem()))
    assert np.abs(mine.astype(int) - core.astype(int)).max() <= 1
    assert mine[..., :3].max() > 40  # something is lit


@pytest.mark.exercise("LightCollectionSystem")
def test_a_parented_light_is_placed_by_its_world_position(impl):
    """"(world position, 1)": a point light under a moved and turned parent is where the parent puts it, and a
    directional light under a turned parent shines along its world -Z, not its local one."""
    from gandalf_core.components import LinkComponent

    scene = Scene("parented lights")
    parent = scene.create_entity(TransformComponent((3.0, 1.0, -2.0), (0.0, 90.0, 0.0), 2.0))
    scene.create_entity(TransformComponent((1.0, 0.5, 0.0)), LightComponent("point", (1, 1, 1), 2.0),
                        LinkComponent(parent))
    scene.create_entity(TransformComponent(rotation=(-40.0, 0.0, 0.0)), LightComponent("directional"),
                        LinkComponent(parent))
    scene.add_system(TransformSystem())
    system = scene.add_system(impl.LightCollectionSystem())
    scene.update(0.0)
    expected = pack_lights(system.components)
    block = np.frombuffer(system.data, np.float32)
    positions = block[8:8 + 8].reshape(2, 4)
    want = np.frombuffer(expected, np.float32)[8:8 + 8].reshape(2, 4)
    assert np.allclose(positions, want, atol=1e-5), (
        f"light positions/directions {positions.tolist()} expected {want.tolist()}: use the world matrix "
        "(transform.world), not the local translation and rotation")


@pytest.mark.exercise("LightCollectionSystem")
def test_a_directional_light_without_an_axis_points_up(impl):
    """"a zero axis gives (0, 1, 0)": a directional light whose transform squashes its Z axis to nothing (scale 0
    along z) has no direction to normalise; the block holds (0, 1, 0, 0) there, not NaN."""
    lights = [(LightComponent("directional", (1, 1, 1), 1.0), TransformComponent(scale=(1.0, 1.0, 0.0))),
              (LightComponent("point", (1, 0.5, 0.2), 2.0), TransformComponent((0.0, 2.0, 0.0)))]
    actual, expected = _packed(impl.LightCollectionSystem(), lights)
    positions = np.frombuffer(actual, np.float32)[8:8 + 4 * MAX_LIGHTS].reshape(MAX_LIGHTS, 4)
    assert np.all(np.isfinite(positions)), f"the directional light's slot holds {positions[0].tolist()}"
    assert positions[0].tolist() == [0.0, 1.0, 0.0, 0.0], f"expected (0, 1, 0, 0), got {positions[0].tolist()}"
    _assert_same_block(actual, expected)
