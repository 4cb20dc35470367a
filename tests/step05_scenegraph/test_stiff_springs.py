"""Stiff springs are solved right, not only kept bounded: the exact step, the SpringSystem with it, a blow-up
reported (never reset away), and the stiff-spring study's claims (not graded: the lesson's own code)."""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest
from step05_helpers import run_scene

from gandalf_core import Scene, TransformComponent
from step05_scenegraph.integrators import methods as lesson
from step05_scenegraph.integrators import study_stiff
from step05_scenegraph.integrators.components import SpringComponent
from step05_scenegraph.integrators.systems import SpringSystem


@pytest.mark.parametrize(("k", "c"), [(1e6, 0.0), (1e12, 0.0), (1e6, 20.0), (4.0, 10.0), (4.0, 4.0)])
def test_the_exact_step_follows_the_solution_at_any_stiffness(k, c):
    """Under-, critically and over-damped, k/m up to 1e12 at 120 Hz: 1,200 steps stay on the exact curve."""
    dt, n = 1.0 / 120.0, 1200
    x, v = np.array([1.0, -0.5, 0.25]), np.array([0.0, 2.0, 0.0])
    x0, v0 = x.copy(), v.copy()
    for _ in range(n):
        x, v = lesson.exact_spring_step(x, v, k, 1.0, c, dt)
    want_x, want_v = lesson.damped_spring_exact(x0, v0, k, 1.0, c, n * dt)
    np.testing.assert_allclose(x, want_x, atol=1e-9 * max(1.0, float(np.max(np.abs(x0)))))
    np.testing.assert_allclose(v, want_v, atol=1e-9 * max(1.0, float(np.sqrt(k))))
    if c == 0.0:  # undamped: no energy gained or lost
        assert lesson.spring_energy(x, v, k, 1.0) == pytest.approx(lesson.spring_energy(x0, v0, k, 1.0), rel=1e-9)


def test_the_exact_solution_takes_one_spring_per_element():
    k = np.array([1.0, 1e6, 4.0, 0.0])
    c = np.array([0.0, 10.0, 5.0, 0.0])
    x, v = lesson.damped_spring_exact(1.0, 0.5, k, 1.0, c, 0.7)
    for i in range(len(k)):
        xi, vi = lesson.damped_spring_exact(1.0, 0.5, float(k[i]), 1.0, float(c[i]), 0.7)
        assert (x[i], v[i]) == pytest.approx((float(xi), float(vi)), rel=1e-12, abs=1e-12)


def test_a_very_stiff_spring_in_the_system_moves_as_the_physics_says():
    """k/m = 1e6 at the system's 1/120 s: no warning, and the mass where the exact solution puts it."""
    scene = Scene("stiff")
    scene.add_system(SpringSystem())
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        e = scene.create_entity(TransformComponent((0, 1, 0)),
                                SpringComponent(rest=(0, 0, 0), stiffness=1e6, damping=0.0, integrator="exact"))
        run_scene(scene, 60, dt=1 / 60)
    spring = scene.get_component(e, SpringComponent)
    exact, _ = lesson.damped_spring_exact(1.0, 0.0, 1e6, 1.0, 0.0, 1.0)
    assert spring.position[1] == pytest.approx(float(exact), abs=1e-9)
    assert spring.ran_away_at == -1.0


def test_a_blow_up_is_reported_and_stays_in_sight():
    """Semi-implicit Euler beyond its limit (omega*dt = 2.12): warned at creation, reported when it runs away,
    and stopped where it was last bounded (never reset to its start)."""
    scene = Scene("blow-up")
    scene.add_system(SpringSystem())
    with pytest.warns(UserWarning, match="stability limit"):
        e = scene.create_entity(TransformComponent((0, 1, 0)),
                                SpringComponent(rest=(0, 0, 0), stiffness=14400.0 * 4.5, damping=0.0,
                                                integrator="semi_implicit_euler"))
    with pytest.warns(UserWarning, match=r"semi_implicit_euler .* ran away after .* s simulated: it is stopped there"):
        run_scene(scene, 30, dt=1 / 60)
    spring = scene.get_component(e, SpringComponent)
    assert 0.0 < spring.ran_away_at < 0.5
    stopped = spring.position.copy()
    assert 1.0 < np.linalg.norm(stopped) <= spring.runaway_distance  # grown, not put back to its start
    run_scene(scene, 10, dt=1 / 60)
    np.testing.assert_array_equal(spring.position, stopped)
    transform = scene.get_component(e, TransformComponent)
    np.testing.assert_allclose(transform.translation, stopped)


def test_the_stiff_study_tells_bounded_from_right(tmp_path):
    """The study's claims: at k/m = 1e6 the explicit methods blow up, implicit Euler is bounded yet loses the
    motion, the exact step is right; its table names the machine."""
    assert study_stiff.run("exact", 1e6) == (pytest.approx(0.0, abs=1e-9), None)
    error, blew_up = study_stiff.run("rk4", 1e6)
    assert error == float("inf") and 0.0 < blew_up < 0.1
    error, blew_up = study_stiff.run("implicit_euler", 1e6)
    assert blew_up is None and error > 0.5
    study_stiff.main(["--out", str(tmp_path), "--quick", "--repeats", "1"])
    result = json.loads((tmp_path / "step05_study_stiff.json").read_text())
    assert len(result["rows"]) == len(study_stiff.QUICK_RATIOS) * 5 and "cores" in result["machine"]
    table = (tmp_path / "step05_study_stiff.md").read_text()
    assert "**blew up**" in table and "measured on" in table
    assert (tmp_path / "step05_study_stiff.png").stat().st_size > 1000
