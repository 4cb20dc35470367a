"""The fixed-step study: ``python -m step05_scenegraph.integrators.study_fixed_step --out DIR [--quick]``.

:class:`~step05_scenegraph.custom_systems.fixed_step.FixedStep` has two knobs: the step ``dt`` and ``max_steps``,
the most steps one frame may run (time beyond that is dropped). This study sets the error of what the player SEES
against the cost of the simulation, for each pair of knobs:

* the case: a projectile (launched at (3, 10, 0) m/s from the origin, gravity -9.81 m/s², no floor) stepped with
  the reference semi-implicit Euler integrator inside ``FixedStep(dt, max_steps=...)``, driven by a stream of
  frame times: 60 Hz with ±25 % jitter and a 0.1 s hitch once a second (a stall, a loading spike), for
  ``DURATION`` seconds (the same seeded stream for every case);
* what is seen: after each frame, the interpolated position ``previous + alpha · (current - previous)``;
* the reference: the exact float64 projectile ``v0 t + g t² / 2`` at the frame's wall-clock time;
* the error: the largest distance (metres) over all frames. It has three parts: Euler's ``|g| dt t / 2``, the
  interpolation's lag of one step (about ``|v| dt``) and the time ``max_steps`` drops (the simulation falls
  behind the clock for good when a hitch needs more steps than allowed);
* the time: the median over ``--repeats`` runs of the CPU time for the whole run, per simulated second.

Writes ``step05_study_fixed_step.json``, ``.md`` (the table) and ``.png`` (error against time, one line per
``max_steps``) to ``--out``. No GPU is needed; prints progress.
"""

from __future__ import annotations

import statistics
import time
import warnings
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, groups, markdown_table, run_info, write_study

from ..custom_systems.fixed_step import FixedStep
from .methods import reference_step

STEM = "step05_study_fixed_step"
DTS = (1 / 30, 1 / 60, 1 / 120, 1 / 240, 1 / 480, 1 / 960)
QUICK_DTS = (1 / 30, 1 / 120, 1 / 480)
MAX_STEPS = (2, 4, 8, 32)
QUICK_MAX_STEPS = (2, 8)
DURATION = 2.0
V0 = np.array([3.0, 10.0, 0.0])
GRAVITY = np.array([0.0, -9.81, 0.0])


def frame_times(duration: float = DURATION, seed: int = 5) -> np.ndarray:
    """A seeded stream of frame times: 60 Hz ± 25 % jitter, a 0.1 s hitch at 0.5 s and once a second after."""
    rng = np.random.default_rng(seed)
    times, total, next_hitch = [], 0.0, 0.5
    while total < duration:
        ts = 1.0 / 60.0 * rng.uniform(0.75, 1.25)
        if total >= next_hitch:
            ts, next_hitch = 0.1, next_hitch + 1.0
        times.append(ts)
        total += ts
    return np.array(times)


def exact(t: float) -> np.ndarray:
    return V0 * t + 0.5 * GRAVITY * t * t


def run_case(dt: float, max_steps: int, frames: np.ndarray, measure: bool = True) -> tuple[float, float]:
    """(largest error of the interpolated position over all frames (m), seconds of simulated time dropped).

    With ``measure=False`` only the simulation and the interpolation run (the timed runs): the error is 0.
    """
    fixed = FixedStep(dt=dt, max_steps=max_steps)

    def accel(_x: np.ndarray, _v: np.ndarray) -> np.ndarray:
        return GRAVITY

    semi_implicit_euler_step = reference_step("semi_implicit_euler_step")
    x, v = np.zeros(3), V0.copy()
    previous = x
    wall = 0.0
    worst = 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # FixedStep warns once about dropped time: the study counts it
        for ts in frames:
            wall += ts
            for _ in range(fixed.advance(float(ts))):
                previous = x
                x, v = semi_implicit_euler_step(x, v, accel, dt)
            seen = previous + fixed.alpha * (x - previous)
            if measure:
                worst = max(worst, float(np.linalg.norm(seen - exact(wall))))
    return worst, fixed.dropped


def run_study(dts, max_steps_list, repeats: int, duration: float = DURATION) -> dict:
    frames = frame_times(duration)
    simulated = float(frames.sum())
    rows = []
    for max_steps in max_steps_list:
        for dt in dts:
            error, dropped = run_case(dt, max_steps, frames)
            runs = []
            for _ in range(repeats):
                start = time.perf_counter()
                run_case(dt, max_steps, frames, measure=False)
                runs.append(time.perf_counter() - start)
            row = {"dt": dt, "max_steps": max_steps, "max_error_m": error, "dropped_s": dropped,
                   "ms_per_simulated_second": 1000.0 * statistics.median(runs) / simulated}
            rows.append(row)
            print(f"max_steps {max_steps:2d}, dt 1/{1 / dt:.0f} s: error {error:.3e} m, dropped {dropped:.3f} s, "
                  f"{row['ms_per_simulated_second']:.3f} ms per simulated s", flush=True)
    return {"rows": rows, "frames": len(frames), "duration_s": simulated,
            "frame_stream": "60 Hz +-25 % jitter, a 0.1 s hitch once a second (seeded)",
            "reference": "exact float64 projectile at each frame's wall-clock time",
            "time": f"median of {repeats} runs (stepping + interpolation only), CPU time per simulated second",
            **run_info()}


def markdown(result: dict) -> str:
    return markdown_table(
        ["max_steps", "dt (s)", "largest error seen (m)", "time dropped (s)", "CPU ms per simulated second"],
        ([r["max_steps"], f"1/{1 / r['dt']:.0f}", f"{r['max_error_m']:.2e}", f"{r['dropped_s']:.3f}",
          f"{r['ms_per_simulated_second']:.3f}"] for r in result["rows"]), left=0)


def plot(result: dict, path: Path) -> None:
    fig, ax = figure(figsize=(6.4, 4.2))
    for max_steps, mine in groups(result["rows"], "max_steps"):
        ax.loglog([r["ms_per_simulated_second"] for r in mine], [r["max_error_m"] for r in mine], "o-",
                  label=f"max_steps = {max_steps}", ms=4)
        for r in mine:
            ax.annotate(f"1/{1 / r['dt']:.0f}", (r["ms_per_simulated_second"], r["max_error_m"]), fontsize=6,
                        xytext=(3, 3), textcoords="offset points")
    label_axes(ax, "CPU time per simulated second (ms, median)", "largest error of the seen position (m)",
               "FixedStep: projectile, jittery 60 Hz frames with 0.1 s hitches")
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    args = StudyParser("step05_scenegraph.integrators.study_fixed_step", __doc__, outputs=f"{STEM}.json/.md/.png",
                       quick="three time steps and two max_steps", backends=None, repeats=(9, 3)).parse_args(argv)
    repeats = args.repeats
    dts, max_steps = (QUICK_DTS, QUICK_MAX_STEPS) if args.quick else (DTS, MAX_STEPS)
    print(f"fixed-step study: {len(dts)} time steps x {len(max_steps)} max_steps, {repeats} timed runs each",
          flush=True)
    result = run_study(dts, max_steps, repeats)
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
