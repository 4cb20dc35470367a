"""Step 05's non-graded parts: hierarchy and re-parenting, the custom systems, FixedStep, scene switching
(no GPU resource leak), and the three scenes in both APIs against each other and their references."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import step05_scenegraph.solutions as solutions
from gandalf_core import InfoComponent, LinkComponent, Scene, TransformComponent, TransformSystem
from gandalf_core.math import quat_from_axis_angle, quat_from_euler, quat_to_matrix3
from gandalf_core.systems.transform_system import set_parent_keep_world, world_matrix
from gandalf_core.testing import compare_images, compare_to_reference
from step05_scenegraph import opengl, webgpu
from step05_scenegraph.components import GravityComponent, SpinComponent, SpringComponent
from step05_scenegraph.fixed_step import FixedStep
from step05_scenegraph.integrators import damped_spring_exact
from step05_scenegraph.scene import SCENE_KEYS, build_solar_scene, build_springs_scene
from step05_scenegraph.systems import GravitySystem, SpinSystem, SpringSystem

REFERENCES = Path(__file__).parent / "references"
VARIANTS = {"opengl": opengl, "webgpu": webgpu}


def named(scene: Scene, name: str):
    return next(e for e, (info,) in scene.view(InfoComponent) if info.name == name)


def run_scene(scene: Scene, frames: int, dt: float = 1 / 60) -> None:
    if not any(isinstance(s, TransformSystem) for s in scene.systems):
        scene.add_system(TransformSystem())
    for _ in range(frames):
        scene.update(dt)


# --- hierarchy ---------------------------------------------------------------------------------------------
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


# --- custom systems -------------------------------------------------------------------------------------------
def test_spin_system_turns_about_the_own_axis():
    scene = Scene("spin")
    e = scene.create_entity(TransformComponent(rotation=(0, 0, 90)), SpinComponent((0, 1, 0), 90.0))
    scene.add_system(SpinSystem())
    run_scene(scene, 60)
    world = scene.get_component(e, TransformComponent).world[:3, :3]
    # About its OWN (tilted) y-axis: R = R_tilt @ R_y(90°), not R_y(90°) @ R_tilt.
    tilt = quat_to_matrix3(quat_from_euler((0, 0, 90)))
    turn = quat_to_matrix3(quat_from_axis_angle((0, 1, 0), np.pi / 2))
    assert np.allclose(world, tilt @ turn, atol=1e-9)


def test_gravity_integrates_velocity_the_same_at_any_frame_rate():
    finals = []
    for fps in (30, 60, 120):
        scene = Scene("fall")
        e = scene.create_entity(TransformComponent((0, 10, 0)), GravityComponent(gravity=9.81))
        scene.add_system(GravitySystem(dt=1 / 120))
        run_scene(scene, fps, dt=1 / fps)  # one second
        finals.append(scene.get_component(e, TransformComponent).translation[1])
    # Semi-implicit Euler after n steps: y = 10 - g dt^2 n (n + 1) / 2. The picture is interpolated between
    # the last two states, so at t = 1 s (alpha = 0) it shows step n = 119 of 120: one fixed step behind.
    n, dt = 119, 1 / 120
    assert np.allclose(finals, 10 - 9.81 * dt * dt * n * (n + 1) / 2, atol=1e-9)


def test_gravity_bounces_lose_height():
    scene = Scene("bounce")
    ball = GravityComponent(floor=0.0, restitution=0.8)
    e = scene.create_entity(TransformComponent((0, 2, 0)), ball)
    scene.add_system(GravitySystem())
    heights = []
    for _ in range(300):
        run_scene(scene, 1)
        heights.append(scene.get_component(e, TransformComponent).translation[1])
    assert min(heights) >= 0.0 and max(heights[100:]) < 2.0 * 0.8 + 0.05


def test_springs_each_integrator_behaves_as_taught():
    scene = build_springs_scene()
    with pytest.warns(UserWarning, match="explicit_euler .* ran away"):  # the reset never hides the blow-up
        run_scene(scene, 60 * 30)  # 30 seconds
    springs = {c.integrator: (c, scene.get_component(e, TransformComponent)) for e, (c,) in scene.view(SpringComponent)}
    assert springs["explicit_euler"][0].resets >= 1  # it blew up (and was put back)
    for name in ("semi_implicit_euler", "rk4", "implicit_euler"):
        assert springs[name][0].resets == 0
    exact, _ = damped_spring_exact(1.0, 0.0, 40.0, 1.0, 0.2, 30.0)
    for name in ("semi_implicit_euler", "rk4"):
        spring, transform = springs[name]
        assert transform.translation[1] - 2.0 == pytest.approx(exact, abs=0.02)


@pytest.mark.parametrize(("integrator", "stiffness", "warns"), [
    ("semi_implicit_euler", 14400.0 * 4.1, True),  # omega*dt = 2.02 at dt = 1/120: beyond 2
    ("semi_implicit_euler", 14400.0 * 3.9, False),
    ("rk4", 14400.0 * 8.2, True),  # beyond 2*sqrt(2)
    ("implicit_euler", 1e12, False),  # stable at any stiffness
])
def test_a_stiff_spring_says_it_will_blow_up(integrator, stiffness, warns):
    import warnings

    scene = Scene("stiff")
    scene.add_system(SpringSystem())
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scene.create_entity(TransformComponent((0, 1, 0)), SpringComponent(rest=(0, 0, 0), stiffness=stiffness,
                                                                           integrator=integrator))
    said = [w for w in caught if "stability limit" in str(w.message)]
    assert bool(said) == warns, [str(w.message) for w in caught]


def test_springs_survive_a_huge_frame_time():
    scene = Scene("stall")
    e = scene.create_entity(TransformComponent((0, 1, 0)), SpringComponent(rest=(0, 0, 0), integrator="rk4"))
    system = scene.add_system(SpringSystem())
    with pytest.warns(UserWarning, match="dropped"):  # never silently
        run_scene(scene, 1, dt=5.0)  # a five-second stall: clamped, capped at max_steps
    assert system.clock.steps == system.clock.max_steps
    assert system.clock.dropped > 4.0
    assert np.all(np.isfinite(scene.get_component(e, TransformComponent).translation))


# --- FixedStep -------------------------------------------------------------------------------------------------
def test_fixed_step_counts_whole_steps_and_keeps_the_rest():
    clock = FixedStep(1 / 120)
    assert [clock.advance(1 / 60) for _ in range(600)] == [2] * 600
    assert clock.alpha == pytest.approx(0.0, abs=1e-6)
    clock = FixedStep(0.01)
    rng = np.random.default_rng(1)
    frames = rng.uniform(0.0, 0.03, 1000)
    steps = sum(clock.advance(f) for f in frames)
    assert abs(steps * 0.01 + clock.accumulator - frames.sum()) < 1e-9 and clock.dropped == 0.0
    assert 0.0 <= clock.alpha < 1.0


def test_fixed_step_clamps_and_caps():
    clock = FixedStep(0.01, max_frame_time=0.25, max_steps=8)
    with pytest.warns(UserWarning, match="9.920 s of simulated time dropped"):  # reported, never silent
        assert clock.advance(10.0) == 8
    assert clock.dropped == pytest.approx(10.0 - 0.08, abs=1e-9)
    assert 0.0 <= clock.alpha < 1.0
    for bad in (-1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="frame time"):
            clock.advance(bad)
    with pytest.raises(ValueError, match="dt"):
        FixedStep(0.0)


# --- several scenes ---------------------------------------------------------------------------------------------
def test_keys_switch_scenes_at_the_next_frame(backend):
    with VARIANTS[backend].create_app(headless=True, width=32, height=24) as app:
        assert [s.name for s in app.scenes.scenes] == list(SCENE_KEYS.values())
        app.step()
        for key, name in (("2", "house"), ("3", "springs"), ("1", "solar"), ("TAB", "house"), ("TAB", "springs"),
                          ("TAB", "solar")):
            app.input.key(key)
            before = app.scene.name
            app.step()
            assert app.scene.name == before  # deferred: this frame still ran the old scene
            app.input.key(key, "release")
            app.step()
            assert app.scene.name == name
        app.switch_scene("house")
        app.step()
        assert app.scene.name == "house"


def test_a_thousand_switches_leak_nothing(backend):
    with VARIANTS[backend].create_app(headless=True, width=16, height=12) as app:
        names = list(SCENE_KEYS.values())
        for name in names:  # first round: every scene builds its GPU objects once
            app.switch_scene(name)
            app.step()
        live = app.renderer.live_objects()
        for i in range(1000):
            app.switch_scene(names[i % 3])
            app.step()
        assert app.renderer.live_objects() == live


# --- pictures ---------------------------------------------------------------------------------------------------
def _scene_images(backend: str) -> list[np.ndarray]:
    images = []
    with VARIANTS[backend].create_app(headless=True, width=160, height=120) as app:
        for name in SCENE_KEYS.values():
            app.switch_scene(name)
            app.run(frames=60)
            images.append(app.capture())
    return images


def test_both_apis_draw_the_same_scenes():
    # Measured: identical up to one 8-bit step on a few edge pixels; 40 dB is the stated tolerance.
    for name, gl, wg in zip(SCENE_KEYS.values(), _scene_images("opengl"), _scene_images("webgpu")):
        compare_images(wg, gl, f"step05-{name}-webgpu-vs-opengl", min_psnr=40.0)


@pytest.mark.parametrize("backend_name", ["opengl"])
def test_scenes_match_their_references(backend_name):
    for name, image in zip(SCENE_KEYS.values(), _scene_images(backend_name)):
        compare_to_reference(image, REFERENCES / f"scene_{name}.png", min_psnr=35.0)


def test_solutions_package_exposes_the_exercise_api():
    for attr in ("house_meshes", "brick_texture_data", "house_material_data", "house_camera",
                 "HouseRotationSystem", "semi_implicit_euler_step", "rk4_step"):
        assert callable(getattr(solutions, attr))
    assert LinkComponent  # the scenes are built from LinkComponents (imported for the reader)
