"""Exercise 3's stated rule: constant gravity is integrated exactly, so the path does not depend on the step.

64 projectiles (no floor, no deaths) flown for 1 s at dt = 1/30 and 1/240 (30 and 240 steps) by the numpy twin and
by the student's kernel in each API end within 1e-3 m of each other and of the float64 parabola (float32 rounding:
the reference measures under 1e-5 m). Semi-implicit Euler ends 0.14 m apart.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_compute import _simulate

from step07_advanced.showcase.particles import particle_step_np
from step07_advanced.showcase.study_particles import exact_positions, launch_state, study_params

DTS = (1 / 30, 1 / 240)
TOLERANCE = 1e-3


def _numpy(state: np.ndarray, dt: float) -> np.ndarray:
    for _ in range(round(1.0 / dt)):
        state = particle_step_np(state, study_params(dt))
    return state


def test_the_twin_flies_the_same_path_at_any_step():
    state = launch_state(64)
    exact = exact_positions(state, 1.0)
    for dt in DTS:
        got = _numpy(state, dt)[:, 0, :3]
        assert np.abs(got - exact).max() <= TOLERANCE, f"dt = {dt}: {np.abs(got - exact).max():.3g} m off"


@pytest.mark.exercise("particle_step")
def test_the_kernel_flies_the_same_path_at_any_step(impl, backend):
    state = launch_state(64)
    exact = exact_positions(state, 1.0)
    ends = {}
    for dt in DTS:
        ends[dt] = _simulate(backend, impl, state, study_params(dt), round(1.0 / dt))[:, 0, :3]
        off = float(np.abs(ends[dt] - exact).max()) if np.all(np.isfinite(ends[dt])) else float("inf")
        assert off <= TOLERANCE, (
            f"{backend}: after 1 s at dt = 1/{1 / dt:.0f} s a projectile is {off:.3g} m from x0 + v0 t + g t²/2 "
            f"(tolerance {TOLERANCE} m). Hint: x += v dt + g dt²/2 with the old v, then v += g dt: exact at any dt")
    apart = float(np.abs(ends[DTS[0]] - ends[DTS[1]]).max())
    assert apart <= TOLERANCE, f"{backend}: dt = 1/30 and 1/240 end {apart:.3g} m apart"
