"""The particle time-step study: ``python -m step07_advanced.showcase.study_particles --out DIR [--quick]
[--backends numpy opengl webgpu]``.

The fountain's kernel steps every particle with semi-implicit Euler at a fixed ``dt`` (``SimParams.dt``, 1/60 s in
the demo). How large an error does that step make, and what does a smaller step cost?

* the case: ``--particles`` projectiles (no floor, no respawn: the floor is put at -1e9 and every life at 1e9)
  launched from the emitter with the fountain's spread of velocities, simulated for ``DURATION`` seconds;
* the reference: the exact float64 trajectory ``x0 + v0 t + g t² / 2`` at the simulated time ``n · dt``;
* the error: the largest distance (metres) of a particle from its exact position at the end; semi-implicit Euler
  is exact in velocity and ``|g| · dt · t / 2`` off in position under constant gravity (the line in the plot), so
  the error halves when the step halves, until float32 rounding of ``n`` small increments takes over;
* the time: the median over ``--repeats`` runs of the wall time for one simulated second (``1 / dt`` kernel
  steps, then one read-back so the GPU's work is inside the measurement), per backend: ``numpy`` (the float32
  twin ``particle_step_np``), ``opengl`` (the GLSL compute kernel on a headless app's context) and ``webgpu``
  (the WGSL kernel on its device), both with the reference solution's ``particle_step``.

Writes ``step07_study_particles.json``, ``.md`` (the table) and ``.png`` (error against time per simulated
second) to ``--out``. Runs headless and prints progress.
"""

from __future__ import annotations

import statistics
import time
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, groups, markdown_table, run_info, write_study

from .particles import SimParams, particle_step_np

STEM = "step07_study_particles"
DTS = (1 / 15, 1 / 30, 1 / 60, 1 / 120, 1 / 240, 1 / 480, 1 / 960)
QUICK_DTS = (1 / 15, 1 / 60, 1 / 240)
DURATION = 2.0
BACKENDS = ("numpy", "opengl", "webgpu")
GRAVITY = (0.0, -9.81, 0.0)


def launch_state(count: int, seed: int = 7) -> np.ndarray:
    """``count`` particles at the emitter with the fountain's spread of velocities, immortal (life 1e9)."""
    rng = np.random.default_rng(seed)
    state = np.zeros((count, 2, 4), dtype=np.float32)
    state[:, 0, :3] = SimParams().emitter
    state[:, 0, 3] = 1e9
    state[:, 1, 0] = rng.uniform(-1.2, 1.2, count)
    state[:, 1, 1] = rng.uniform(5.0, 6.5, count)
    state[:, 1, 2] = rng.uniform(-1.2, 1.2, count)
    return state


def study_params(dt: float) -> SimParams:
    """The fountain's parameters with the floor out of reach, so every particle is a plain projectile."""
    return SimParams(dt=dt, gravity=GRAVITY, floor_y=-1e9, max_life=1e9)


def exact_positions(state: np.ndarray, t: float) -> np.ndarray:
    """Float64 projectile positions at time ``t``."""
    x0 = state[:, 0, :3].astype(np.float64)
    v0 = state[:, 1, :3].astype(np.float64)
    return x0 + v0 * t + 0.5 * np.asarray(GRAVITY, dtype=np.float64) * t * t


class _NumpyRunner:
    device_name = "numpy (float32 twin of the kernel)"

    def __init__(self, state: np.ndarray) -> None:
        self.start = np.array(state, dtype=np.float32)
        self.state = self.start.copy()

    def reset(self) -> None:
        self.state = self.start.copy()

    def step(self, params: SimParams) -> None:
        self.state = particle_step_np(self.state, params)

    def read(self) -> np.ndarray:
        return self.state.copy()

    def release(self) -> None:
        """Nothing to free."""


class _GPURunner:
    """A GPU kernel of the showcase on the context/device of a tiny headless app (compute runs there, as in the
    demo), reset by re-uploading the start state."""

    def __init__(self, backend: str, state: np.ndarray) -> None:
        from gandalf_core import Application
        from gandalf_core.app.cli import load_impl

        reference_impl = load_impl("step07_advanced")  # the solutions, or your exercises where there are none

        self.backend, self.start = backend, np.array(state, dtype=np.float32)
        self.app = Application(backend, 8, 8, headless=True)
        renderer = self.app.renderer
        if backend == "opengl":
            from .compute_gl import GLParticleKernel

            self.kernel = GLParticleKernel(renderer.ctx, reference_impl, self.start)
            self.device_name = renderer.ctx.info.get("GL_RENDERER", "OpenGL")
        else:
            from .compute_wgpu import WGPUParticleKernel

            self.kernel = WGPUParticleKernel(renderer.device, reference_impl, self.start)
            self.device_name = str(renderer.adapter.info.get("device", "WebGPU"))

    def reset(self) -> None:
        if self.backend == "opengl":
            self.kernel.particles.write(self.start.tobytes())
        else:
            self.app.renderer.device.queue.write_buffer(self.kernel.particles, 0, self.start.tobytes())

    def step(self, params: SimParams) -> None:
        self.kernel.step(params)

    def read(self) -> np.ndarray:
        return self.kernel.read()

    def release(self) -> None:
        self.kernel.release()
        self.app.close()


def open_runner(backend: str, state: np.ndarray):
    if backend not in BACKENDS:
        raise ValueError(f"study_particles: backend must be one of {BACKENDS}, got {backend!r}")
    return _NumpyRunner(state) if backend == "numpy" else _GPURunner(backend, state)


def simulate(runner, dt: float, duration: float) -> tuple[np.ndarray, float]:
    """Step ``duration / dt`` steps from the start state; (final state, simulated time)."""
    runner.reset()
    steps = max(1, round(duration / dt))
    params = study_params(dt)
    for _ in range(steps):
        runner.step(params)
    return runner.read(), steps * dt


def measure(runner, state: np.ndarray, dt: float, duration: float, repeats: int) -> dict:
    """Largest position error (m) at the end, and the median wall time per simulated second (ms)."""
    final, t = simulate(runner, dt, duration)
    error = np.linalg.norm(final[:, 0, :3].astype(np.float64) - exact_positions(state, t), axis=1)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        simulate(runner, dt, 1.0)
        times.append(time.perf_counter() - start)
    return {"dt": dt, "steps": round(duration / dt), "max_error_m": float(error.max()),
            "predicted_error_m": 0.5 * abs(GRAVITY[1]) * dt * t,
            "ms_per_simulated_second": 1000.0 * statistics.median(times)}


def run_study(backends, dts, particles: int, duration: float, repeats: int) -> dict:
    state = launch_state(particles)
    rows, devices = [], {}
    for backend in backends:
        runner = open_runner(backend, state)
        devices[backend] = runner.device_name
        print(f"[{backend}] {runner.device_name}", flush=True)
        try:
            for dt in dts:
                row = {"backend": backend, **measure(runner, state, dt, duration, repeats)}
                rows.append(row)
                print(f"[{backend}] dt = 1/{1 / dt:.0f} s: max error {row['max_error_m']:.2e} m (Euler bound "
                      f"{row['predicted_error_m']:.2e}), {row['ms_per_simulated_second']:.2f} ms per simulated s",
                      flush=True)
        finally:
            runner.release()
    return {"rows": rows, "devices": devices, "particles": particles, "duration_s": duration,
            "reference": "exact float64 projectile x0 + v0 t + g t^2/2 at t = steps * dt",
            "time": f"median of {repeats} runs of one simulated second (1/dt steps + one read-back)",
            **run_info()}


def markdown(result: dict) -> str:
    return markdown_table(
        ["backend", "dt (s)", "steps", "max position error (m)", "Euler bound g·dt·t/2 (m)", "ms per simulated second"],
        ([r["backend"], f"1/{1 / r['dt']:.0f}", r["steps"], f"{r['max_error_m']:.2e}", f"{r['predicted_error_m']:.2e}",
          f"{r['ms_per_simulated_second']:.2f}"] for r in result["rows"]))


def plot(result: dict, path: Path) -> None:
    fig, ax = figure(figsize=(6.4, 4.2))
    for backend, mine in groups(result["rows"], "backend"):
        ax.loglog([r["ms_per_simulated_second"] for r in mine], [r["max_error_m"] for r in mine], "o-",
                  label=backend, ms=4)
        for r in mine:
            ax.annotate(f"1/{1 / r['dt']:.0f}", (r["ms_per_simulated_second"], r["max_error_m"]), fontsize=6,
                        xytext=(3, 3), textcoords="offset points")
    label_axes(ax, "wall time per simulated second (ms, median)",
               f"largest position error after {result['duration_s']:g} s (m)",
               f"Particle step (semi-implicit Euler, float32), {result['particles']} projectiles")
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    parser = StudyParser("step07_advanced.showcase.study_particles", __doc__, outputs=f"{STEM}.json/.md/.png",
                         quick="three time steps, fewer particles and repeats", backends=BACKENDS, repeats=(5, 2))
    parser.add_argument("--particles", type=int, default=None, help="projectiles (default 4096, quick 256)")
    args = parser.parse_args(argv)
    particles = args.particles or (256 if args.quick else 4096)
    repeats = args.repeats
    if particles < 1:
        parser.error("--particles must be at least 1")
    dts = QUICK_DTS if args.quick else DTS
    print(f"particle study: {particles} projectiles for {DURATION} s, dt from 1/{1 / dts[0]:.0f} to "
          f"1/{1 / dts[-1]:.0f} s, backends {', '.join(args.backends)}", flush=True)
    result = run_study(args.backends, dts, particles, DURATION, repeats)
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
