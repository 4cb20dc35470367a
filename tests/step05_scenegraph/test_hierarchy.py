"""Step 05's hierarchy (not graded: it has no exercise): parent links, re-parenting, spinning about an own axis,
and the solar system in both APIs.

Pictures (160 × 120, 60 frames): the two APIs agree to PSNR ≥ 40 dB (measured on llvmpipe/lavapipe: 87.3 dB, largest
channel difference 1) and OpenGL matches ``references/scene_solar.png`` to ≥ 35 dB.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from step05_helpers import check_both_apis_agree, picture, run_scene

from gandalf_core import InfoComponent, Scene, TransformComponent
from gandalf_core.math import quat_from_axis_angle, quat_from_euler, quat_to_matrix3
from gandalf_core.systems import SpinComponent, SpinSystem
from gandalf_core.systems.transform_system import set_parent_keep_world, world_matrix
from gandalf_tools.testing import compare_to_reference
from step05_scenegraph.hierarchy import opengl, webgpu
from step05_scenegraph.hierarchy.scene import build_solar_scene

REFERENCES = Path(__file__).parent / "references"
VARIANTS = {"opengl": opengl, "webgpu": webgpu}


def named(scene: Scene, name: str):
    return next(e for e, (info,) in scene.view(InfoComponent) if info.name == name)


def test_moon_follows_the_earth_at_a_fixed_distance():
    scene = build_solar_scene()
    carrier, moon = named(scene, "earth carrier"), named(scene, "moon")
    distances, carrier_positions = [], []
    for _ in range(5):
        run_scene(scene, 17)
        c = scene.get_component(carrier, TransformComponent).world[:3, 3]
        m = scene.get_component(moon, TransformComponent).world[:3, 3]
        distances.append(np.linalg.norm(m - c))
        carrier_positions.append(c.copy())
    assert np.allclose(distances, 0.85, atol=1e-9)  # the moon orbit is in the carrier's unscaled frame
    assert np.allclose(np.linalg.norm(carrier_positions, axis=1), 3.4, atol=1e-9)  # the earth orbits the sun
    assert np.linalg.norm(carrier_positions[0] - carrier_positions[-1]) > 0.5  # ... and it moved


def test_reparent_keeps_the_world_pose():
    scene = build_solar_scene()
    run_scene(scene, 40)
    moon, root, sun = named(scene, "moon"), named(scene, "solar system"), named(scene, "sun")
    for new_parent in (root, sun, None, named(scene, "mars")):
        before = world_matrix(scene, moon)
        set_parent_keep_world(scene, moon, new_parent)
        assert scene.parent_of(moon) == new_parent
        assert np.allclose(world_matrix(scene, moon), before, atol=1e-9, rtol=0)
        run_scene(scene, 1, dt=0.0)  # the transform system agrees
        assert np.allclose(scene.get_component(moon, TransformComponent).world, before, atol=1e-9, rtol=0)


def test_reparent_key_in_the_app(backend):
    with VARIANTS[backend].create_app(headless=True, width=32, height=24) as app:
        scene = app.scene
        moon, root, orbit = named(scene, "moon"), named(scene, "solar system"), named(scene, "moon orbit")
        app.run(frames=10)
        before = world_matrix(scene, moon)
        app.input.key("M")
        app.step(0.0)
        assert scene.parent_of(moon) == root
        assert np.allclose(world_matrix(scene, moon), before, atol=1e-9, rtol=0)
        app.input.key("M", "release")
        app.step(0.0)
        app.input.key("M")
        app.step(0.0)
        assert scene.parent_of(moon) == orbit
        assert np.allclose(world_matrix(scene, moon), before, atol=1e-9, rtol=0)


def test_a_local_spin_turns_about_the_own_axis():
    scene = Scene("spin")
    e = scene.create_entity(TransformComponent(rotation=(0, 0, 90)), SpinComponent((0, 1, 0), 90.0, local=True))
    scene.add_system(SpinSystem())
    run_scene(scene, 60)
    world = scene.get_component(e, TransformComponent).world[:3, :3]
    # About its OWN (tilted) y-axis: R = R_tilt @ R_y(90°), not R_y(90°) @ R_tilt (step 03's world spin).
    tilt = quat_to_matrix3(quat_from_euler((0, 0, 90)))
    turn = quat_to_matrix3(quat_from_axis_angle((0, 1, 0), np.pi / 2))
    assert np.allclose(world, tilt @ turn, atol=1e-9)


def test_the_earth_keeps_its_tilt_while_it_spins():
    scene = build_solar_scene()
    earth = named(scene, "earth")
    axes = []
    for _ in range(4):
        run_scene(scene, 25)
        local = scene.get_component(earth, TransformComponent)
        axes.append(quat_to_matrix3(local.quaternion)[:, 1])  # its own y axis, in the carrier's frame
    assert np.allclose(axes, axes[0], atol=1e-9), "a local spin must not move the spin axis"
    assert np.degrees(np.arccos(axes[0][1])) == pytest.approx(23.0, abs=1e-6)


def test_both_apis_draw_the_same_solar_system():
    check_both_apis_agree(VARIANTS, "solar")


def test_the_solar_system_matches_its_reference():
    compare_to_reference(picture(VARIANTS, "opengl"), REFERENCES / "scene_solar.png", min_psnr=35.0)
