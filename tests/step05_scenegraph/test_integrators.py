"""Grades the integrator exercise numerically, and checks the lesson's other integrators, the study and the
springs scene.

Orders of convergence are measured from the error ratio when dt is halved: ``p = log2(e(dt) / e(dt/2))``.
The springs scene's pictures (160 × 120, 60 frames): the two APIs agree to PSNR ≥ 40 dB (measured: identical)
and OpenGL matches ``references/scene_springs.png`` to ≥ 35 dB.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from step05_helpers import check_both_apis_agree, picture, run_scene

from gandalf_core import Scene, TransformComponent
from gandalf_tools.testing import compare_to_reference
from step05_scenegraph.integrators import methods as lesson
from step05_scenegraph.integrators import opengl, webgpu
from step05_scenegraph.integrators.components import SpringComponent
from step05_scenegraph.integrators.scene import build_springs_scene
from step05_scenegraph.integrators.study import stiffness_sweep
from step05_scenegraph.integrators.systems import SpringSystem

REFERENCES = Path(__file__).parent / "references"
VARIANTS = {"opengl": opengl, "webgpu": webgpu}

K, M, C = 4.0, 1.0, 0.4  # a lightly damped spring, period about 3.1 s


def _final_error(step, dt: float, duration: float = 2.0, c: float = C) -> float:
    accel = lesson.spring_acceleration(K, M, c)
    x, v = 1.0, 0.0
    for _ in range(round(duration / dt)):
        x, v = step(x, v, accel, dt)
    exact, _ = lesson.damped_spring_exact(1.0, 0.0, K, M, c, duration)
    return abs(x - float(exact))


def _order(step, dt: float) -> float:
    return math.log2(_final_error(step, dt) / _final_error(step, dt / 2))


def _assert_order(step, dt: float, low: float, high: float, expected: int) -> None:
    """The order measured from ``dt`` and ``dt / 2`` lies strictly between ``low`` and ``high``."""
    p = _order(step, dt)
    assert low < p < high, f"measured order {p:.3f}, expected about {expected}"


def _energy_over(step, steps: int = 10_000, dt: float = 0.05) -> np.ndarray:
    accel = lesson.spring_acceleration(1.0, 1.0, 0.0)
    x, v = 1.0, 0.0
    energy = np.empty(steps)
    for i in range(steps):
        x, v = step(x, v, accel, dt)
        energy[i] = lesson.spring_energy(x, v, 1.0, 1.0)
    return energy / 0.5  # relative to the start energy k x0^2 / 2


# --- semi-implicit Euler -----------------------------------------------------------------------------------
@pytest.mark.exercise("semi_implicit_euler_step")
def test_semi_implicit_euler_one_step(impl):
    accel = lesson.spring_acceleration(K, M, C)
    x, v = impl.semi_implicit_euler_step(1.0, 2.0, accel, 0.1)
    v_new = 2.0 + 0.1 * (-K * 1.0 - C * 2.0) / M
    assert v == pytest.approx(v_new, abs=1e-12) and x == pytest.approx(1.0 + 0.1 * v_new, abs=1e-12)
    xs, vs = impl.semi_implicit_euler_step(np.ones(3), np.zeros(3), accel, 0.1)  # vectors work too
    assert xs.shape == (3,) and np.allclose(vs, -0.4)


@pytest.mark.exercise("semi_implicit_euler_step")
def test_semi_implicit_euler_keeps_energy_bounded(impl):
    # omega*dt = 0.05: the energy of the symplectic method oscillates within about omega*dt/2 and never drifts.
    energy = _energy_over(impl.semi_implicit_euler_step)
    assert np.all(np.abs(energy - 1.0) < 0.05), (
        f"over 10,000 steps of dt 0.05 from x = 1, v = 0 the energy ranged {energy.min():.4g} .. {energy.max():.4g}; "
        "expected it to stay within 1 ± 0.05. Hint: update v with the acceleration first, then x with the NEW v")
    drift = abs(energy[-1000:].mean() - energy[:1000].mean())
    assert drift < 1e-3, f"the mean energy drifted by {drift:.3g} over 10,000 steps; expected less than 1e-3"


@pytest.mark.exercise("semi_implicit_euler_step")
def test_semi_implicit_euler_is_first_order(impl):
    _assert_order(impl.semi_implicit_euler_step, 0.01, 0.85, 1.15, 1)


# --- RK4 ------------------------------------------------------------------------------------------------------
@pytest.mark.exercise("rk4_step")
def test_rk4_one_step_matches_the_taylor_polynomial(impl):
    # For a linear system y' = A y, one RK4 step is exactly (I + hA + (hA)^2/2 + (hA)^3/6 + (hA)^4/24) y.
    h = 0.3
    a = np.array([[0.0, 1.0], [-K / M, -C / M]])
    ha = h * a
    expected = (np.eye(2) + ha + ha @ ha / 2 + ha @ ha @ ha / 6 + ha @ ha @ ha @ ha / 24) @ np.array([1.0, -0.5])
    x, v = impl.rk4_step(1.0, -0.5, lesson.spring_acceleration(K, M, C), h)
    assert np.allclose([x, v], expected, atol=1e-12)


@pytest.mark.exercise("rk4_step")
def test_rk4_is_fourth_order(impl):
    _assert_order(impl.rk4_step, 0.1, 3.7, 4.3, 4)


@pytest.mark.exercise("rk4_step")
def test_rk4_energy_drift_is_tiny(impl):
    energy = _energy_over(impl.rk4_step)
    assert np.all(np.abs(energy - 1.0) < 1e-5), f"energy drifted to {energy[-1]:.8f}"


# --- the stiffness sweep: 60 Hz, 10,000 steps, k/m from 1 to 1e6 --------------------------------------------
SWEEP_RATIOS = (1.0, 100.0, 1e4, 2e4, 1e5, 1e6)  # omega*dt = 0.017, 0.17, 1.67, 2.36, 5.3, 16.7


@pytest.mark.exercise("semi_implicit_euler_step")
def test_sweep_semi_implicit_bounded_exactly_below_omega_dt_2(impl):
    sweep = stiffness_sweep(SWEEP_RATIOS, overrides={"semi_implicit_euler": impl.semi_implicit_euler_step},
                             names=["semi_implicit_euler"])
    assert sweep["semi_implicit_euler"].tolist() == [True, True, True, False, False, False]


@pytest.mark.exercise("rk4_step")
def test_sweep_rk4_bounded_below_its_limit(impl):
    sweep = stiffness_sweep(SWEEP_RATIOS, overrides={"rk4": impl.rk4_step}, names=["rk4"])
    assert sweep["rk4"].tolist() == [True, True, True, True, False, False]


def test_sweep_explicit_always_unstable_implicit_always_bounded():
    sweep = stiffness_sweep(SWEEP_RATIOS, names=["explicit_euler", "implicit_euler"])
    assert not sweep["explicit_euler"].any()
    assert sweep["implicit_euler"].all()


# --- the lesson's reference pieces (not graded) -----------------------------------------------------------------
@pytest.mark.parametrize("c", [0.0, 0.4, 4.0, 6.0])  # undamped, under-, critically, over-damped (k = 4, m = 1)
def test_exact_solution_solves_the_ode(c):
    t = np.linspace(0.0, 5.0, 2001)
    x, v = lesson.damped_spring_exact(1.0, -0.7, K, M, c, t)
    assert x[0] == pytest.approx(1.0) and v[0] == pytest.approx(-0.7)
    h = t[1] - t[0]
    assert np.allclose(np.gradient(x, h)[1:-1], v[1:-1], atol=1e-4)
    acc = np.gradient(v, h)[1:-1]
    assert np.allclose(M * acc + c * v[1:-1] + K * x[1:-1], 0.0, atol=1e-3)


def test_exact_solution_is_continuous_through_critical_damping():
    near = [lesson.damped_spring_exact(1.0, 0.5, K, M, 4.0 + d, 2.0)[0] for d in (-1e-9, 0.0, 1e-9)]
    assert max(near) - min(near) < 1e-8
    x, v = lesson.damped_spring_exact(1.0, 0.0, 1.0, 1.0, 1e3, 1e4)  # strongly overdamped, long time
    assert np.isfinite(x) and np.isfinite(v)


def test_implicit_euler_is_stable_for_any_stiffness_and_step():
    for k, dt in ((1e12, 1.0), (1.0, 1e3), (1e6, 1 / 60)):
        x, v = 1.0, 0.0
        for _ in range(1000):
            x, v = lesson.implicit_euler_spring_step(x, v, k, 1.0, 0.0, dt)
            assert abs(x) <= 1.0 + 1e-12 and np.isfinite(v)
    p = math.log2(_final_error(lambda x, v, a, dt: lesson.implicit_euler_spring_step(x, v, K, M, C, dt), 0.01)
                  / _final_error(lambda x, v, a, dt: lesson.implicit_euler_spring_step(x, v, K, M, C, dt), 0.005))
    assert 0.85 < p < 1.15


def test_explicit_euler_gains_energy():
    energy = _energy_over(lesson.explicit_euler_step, steps=1000)
    assert energy[-1] > 10.0  # (1 + (omega dt)^2)^1000 = 12.1


def test_bad_spring_parameters_are_named():
    with pytest.raises(ValueError, match="mass m"):
        lesson.spring_acceleration(1.0, 0.0)
    with pytest.raises(ValueError, match="stiffness k"):
        lesson.implicit_euler_spring_step(0.0, 0.0, -1.0, 1.0, 0.0, 0.1)
    with pytest.raises(ValueError, match="dt"):
        lesson.implicit_euler_spring_step(0.0, 0.0, 1.0, 1.0, 0.0, float("nan"))


# --- the springs scene (not graded: it runs the reference integrators) ------------------------------------------
def test_springs_each_integrator_behaves_as_taught():
    scene = build_springs_scene()
    with pytest.warns(UserWarning, match="explicit_euler .* ran away"):  # the blow-up is reported
        run_scene(scene, 60 * 30)  # 30 seconds
    springs = {c.integrator: (c, scene.get_component(e, TransformComponent)) for e, (c,) in scene.view(SpringComponent)}
    assert springs["explicit_euler"][0].ran_away_at > 0.0  # it blew up (and stopped there)
    for name in ("semi_implicit_euler", "rk4", "implicit_euler"):
        assert springs[name][0].ran_away_at == -1.0
    exact, _ = lesson.damped_spring_exact(1.0, 0.0, 40.0, 1.0, 0.2, 30.0)
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


def test_a_spring_names_a_bad_integrator():
    with pytest.raises(ValueError, match="SpringComponent.integrator must be one of"):
        SpringComponent(rest=(0, 0, 0), integrator="verlet")


def test_both_apis_draw_the_same_springs():
    check_both_apis_agree(VARIANTS, "springs")


def test_the_springs_match_their_reference():
    compare_to_reference(picture(VARIANTS, "opengl"), REFERENCES / "scene_springs.png", min_psnr=35.0)
