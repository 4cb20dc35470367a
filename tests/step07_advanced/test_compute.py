"""Exercise 3: the compute kernel ``particle_step`` in GLSL (OpenGL compute shader) and WGSL (WebGPU compute
pipeline), graded against the float32 numpy twin after many steps, with births (respawns) along the way.

Tolerance: largest absolute difference of any position, life or velocity component <= 1e-4 after 120 steps of
1000 particles. The reference solution measures 0 (bit-identical) in both APIs. The non-graded tests check the
twin itself (the physics) and the shared byte layout.
"""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core import Application
from gandalf_tools.grading.shader_box import on_shader_box
from step07_advanced.showcase.particles import (
    SimParams,
    hash_u32,
    initial_particles,
    particle_step_np,
    random01,
    step_particles_np,
)

STEPS = 120
TOLERANCE = 1e-4


def _kernel(backend: str, app: Application, impl, state: np.ndarray):
    if backend == "opengl":
        from step07_advanced.showcase.compute_gl import GLParticleKernel

        return GLParticleKernel(app.renderer.ctx, impl, state)
    from step07_advanced.showcase.compute_wgpu import WGPUParticleKernel

    return WGPUParticleKernel(app.renderer.device, impl, state)


@on_shader_box  # the student's shaders run in the grader's shader process
def _simulate(backend: str, impl, state: np.ndarray, params: SimParams, steps: int) -> np.ndarray:
    with Application(backend, 8, 8, headless=True) as app:
        kernel = _kernel(backend, app, impl, state)
        try:
            for k in range(steps):
                kernel.step(SimParams(**{**params.__dict__, "seed": k}))
            return kernel.read()
        finally:
            kernel.release()


@pytest.mark.exercise("particle_step")
@pytest.mark.parametrize("count", [1000, 37])  # 37: a partly filled work group
def test_gpu_particles_match_the_numpy_twin(impl, backend, count):
    params = SimParams(restitution=0.6, floor_y=0.05)
    state = initial_particles(count, params, warmup=1.0)
    expected = state
    for k in range(STEPS):
        expected = step_particles_np(expected, SimParams(**{**params.__dict__, "seed": k}))
    got = _simulate(backend, impl, state, params, STEPS)
    case = f"for {count} particles after {STEPS} steps of dt {params.dt:g}"
    assert np.all(np.isfinite(got)), f"{case}: {_worst(got, expected)}: NaN or Inf"
    error = float(np.abs(got - expected).max())
    assert error <= TOLERANCE, (
        f"{case}: {_worst(got, expected)} (largest difference {error:.3g}, tolerance {TOLERANCE})")


def _worst(got: np.ndarray, expected: np.ndarray) -> str:
    """The particle that differs most, as (position xyz, life), (velocity xyz, 0): got against expected."""
    diff = np.nan_to_num(np.abs(got - expected), nan=np.inf).reshape(len(got), -1).max(axis=1)
    i = int(np.argmax(diff))
    rows = [np.round(v.astype(np.float64), 4).tolist() for v in (got[i], expected[i])]
    return f"particle {i} (position, life; velocity) got {rows[0]}, expected {rows[1]}"


def test_params_pack_to_the_48_bytes_of_the_struct():
    data = SimParams(dt=0.5, seed=2**32 + 3).pack()
    assert len(data) == 48
    assert np.frombuffer(data[32:36], np.float32)[0] == 0.5
    assert np.frombuffer(data[44:48], np.uint32)[0] == 3


def test_hash_is_lowbias32_and_random_is_in_unit_interval():
    def lowbias32(x: int) -> int:  # with Python's unbounded ints, masked to 32 bits
        x ^= x >> 16
        x = (x * 0x7FEB352D) & 0xFFFFFFFF
        x ^= x >> 15
        x = (x * 0x846CA68B) & 0xFFFFFFFF
        return x ^ (x >> 16)

    values = [0, 1, 12345, 2**31, 2**32 - 1]
    assert hash_u32(np.array(values, np.uint32)).tolist() == [lowbias32(v) for v in values]
    r = random01(np.arange(100_000, dtype=np.uint32))
    assert r.min() >= 0.0 and r.max() < 1.0 and abs(r.mean() - 0.5) < 0.01


def test_twin_falls_bounces_and_loses_energy():
    state = np.zeros((1, 2, 4), np.float32)
    state[0, 0] = (0.0, 1.0, 0.0, 100.0)
    params = SimParams(restitution=0.5, floor_y=0.0)
    heights, speeds = [], []
    for _ in range(240):
        state = particle_step_np(state, params)
        heights.append(state[0, 0, 1])
        speeds.append(state[0, 1, 1])
    assert min(heights) >= 0.0  # never below the floor
    assert max(speeds) > 0.0  # it bounced up
    assert max(heights[60:]) < 0.5  # each bounce keeps restitution² of the energy
    assert state[0, 0, 3] == pytest.approx(100.0 - 240 / 60, abs=1e-3)


def test_dead_particles_are_born_at_the_emitter_within_the_launch_cone():
    params = SimParams(emitter=(1.0, 2.0, 3.0), max_life=2.0)
    state = np.zeros((500, 2, 4), np.float32)  # every life is 0: all die on the first step
    out = step_particles_np(state, params)
    assert np.allclose(out[:, 0, :3], (1.0, 2.0, 3.0))
    assert np.all((out[:, 0, 3] >= 1.0) & (out[:, 0, 3] <= 2.0))
    assert np.all(np.abs(out[:, 1, [0, 2]]) <= 1.2) and np.all((out[:, 1, 1] >= 5.0) & (out[:, 1, 1] <= 6.5))


# --- the fountain's time step: the same simulated time at any frame rate ------------------------------
class _CountingKernel:
    """Counts steps; holds a fixed state (the system reads positions after stepping)."""

    def __init__(self) -> None:
        self.steps = 0

    def step(self, params: SimParams) -> None:
        self.steps += 1

    def read(self) -> np.ndarray:
        return np.zeros((1, 2, 4), dtype=np.float32)

    def release(self) -> None:
        pass


@pytest.mark.parametrize("fps", [30, 60, 120, 144, 47])
def test_the_fountain_simulates_one_second_per_second_at_any_frame_rate(fps):
    from step07_advanced.showcase.particles import ParticleSystem

    kernel = _CountingKernel()
    system = ParticleSystem(kernel, SimParams())
    for _ in range(fps * 3):  # three seconds of frames
        system.on_update_system(1.0 / fps)
    simulated = kernel.steps * SimParams().dt + system.owed
    assert abs(simulated - 3.0) < 1e-9, f"{fps} fps: {simulated} simulated seconds in 3 s"
    assert abs(kernel.steps * SimParams().dt - 3.0) <= SimParams().dt
    assert system.dropped_time == 0.0


def test_a_hitch_is_capped_and_reported():
    from step07_advanced.showcase.particles import ParticleSystem

    kernel = _CountingKernel()
    system = ParticleSystem(kernel, SimParams())
    with pytest.warns(UserWarning, match="dropping"):
        system.on_update_system(1.0)  # one frame of a whole second: 60 steps owed
    assert kernel.steps == ParticleSystem.max_steps
    assert abs(kernel.steps * SimParams().dt + system.dropped_time + system.owed - 1.0) < 1e-9
