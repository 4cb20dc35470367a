"""Step 05's custom systems (not graded: no exercise): GravitySystem on a fixed step, FixedStep's accumulator,
and the bouncing balls in both APIs.

Pictures (160 × 120, 60 frames): the two APIs agree to PSNR ≥ 40 dB (measured: identical) and OpenGL matches
``references/scene_gravity.png`` to ≥ 35 dB.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from step05_helpers import check_both_apis_agree, picture, run_scene

from gandalf_core import Scene, TransformComponent
from gandalf_tools.testing import compare_to_reference
from step05_scenegraph.custom_systems import opengl, webgpu
from step05_scenegraph.custom_systems.components import GravityComponent
from step05_scenegraph.custom_systems.fixed_step import FixedStep
from step05_scenegraph.custom_systems.systems import FixedStepSystem, GravitySystem

REFERENCES = Path(__file__).parent / "references"
VARIANTS = {"opengl": opengl, "webgpu": webgpu}


def test_gravity_integrates_velocity_the_same_at_any_frame_rate():
    finals = []
    for fps in (30, 60, 120):
        scene = Scene("fall")
        e = scene.create_entity(TransformComponent((0, 10, 0)), GravityComponent(gravity=9.81))
        scene.add_system(GravitySystem(dt=1 / 120))
        run_scene(scene, fps, dt=1 / fps)  # one second
        finals.append(scene.get_component(e, TransformComponent).translation[1])
    # The exact step after n steps: y = 10 - g (n dt)^2 / 2. The picture is interpolated between the last two
    # states, so at t = 1 s (alpha = 0) it shows step n = 119 of 120: one fixed step behind.
    n, dt = 119, 1 / 120
    assert np.allclose(finals, 10 - 9.81 * (n * dt) ** 2 / 2, atol=1e-9)


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


def test_bad_gravity_values_are_named():
    with pytest.raises(ValueError, match="GravityComponent.restitution"):
        GravityComponent(restitution=1.5)
    with pytest.raises(ValueError, match="GravityComponent.velocity"):
        GravityComponent(velocity=(0.0, float("nan"), 0.0))


def test_a_fixed_step_system_without_a_step_names_what_is_missing():
    scene = Scene("bare")
    scene.create_entity(TransformComponent(), GravityComponent())
    scene.add_system(FixedStepSystem([GravityComponent, TransformComponent], 0.01))
    with pytest.raises(NotImplementedError, match=r"FixedStepSystem.step\(body, dt\)"):
        run_scene(scene, 1)


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


# --- pictures ---------------------------------------------------------------------------------------------------
def test_both_apis_draw_the_same_balls():
    check_both_apis_agree(VARIANTS, "gravity")


def test_the_balls_match_their_reference():
    compare_to_reference(picture(VARIANTS, "opengl"), REFERENCES / "scene_gravity.png", min_psnr=35.0)
