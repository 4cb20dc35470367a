"""The integrator study: ``python -m step05_scenegraph.integrators.study [--out DIR]`` (plots: ``out/``).

(a) Accuracy against cost: each integrator follows a damped oscillator (k = 10, m = 1, c = 0.4, x0 = 1,
    v0 = 0) for 10 seconds at several time steps; the largest position error against the exact solution is
    set against the measured run time (a table, and ``step05_integrators_error.png``).
(b) Stability: undamped springs with k/m from 1 to 1e6, stepped at 60 Hz for 10,000 steps, are reported
    bounded or unstable per integrator (a table, and ``step05_stiffness.png``). Undamped is the hardest case:
    any energy an integrator adds is never taken away again.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure

from .methods import (
    damped_spring_exact,
    explicit_euler_step,
    implicit_euler_spring_step,
    reference_step,
)

INTEGRATOR_NAMES = ("explicit_euler", "semi_implicit_euler", "rk4", "implicit_euler")
ERROR_CASE = {"k": 10.0, "m": 1.0, "c": 0.4, "x0": 1.0, "v0": 0.0, "duration": 10.0}
ERROR_DTS = (0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001)
STIFFNESS_RATIOS = tuple(float(r) for r in np.logspace(0, 6, 25))
SWEEP_DT = 1.0 / 60.0
SWEEP_STEPS = 10_000

Stepper = Callable[[np.ndarray, np.ndarray, float], tuple[np.ndarray, np.ndarray]]


def steppers(
    k: float | np.ndarray, m: float, c: float, overrides: dict[str, Callable] | None = None
) -> dict[str, Stepper]:
    """``name -> step(x, v, dt)`` for the damped spring ``(k, m, c)``; ``overrides`` swaps in other
    implementations of the generic integrators (the graded exercises use this)."""
    generic = {"explicit_euler": explicit_euler_step, "semi_implicit_euler": reference_step("semi_implicit_euler_step"),
               "rk4": reference_step("rk4_step")}
    generic.update(overrides or {})

    def accel(x: np.ndarray, v: np.ndarray) -> np.ndarray:
        return (-k * x - c * v) / m

    def make(step: Callable) -> Stepper:
        return lambda x, v, dt: step(x, v, accel, dt)

    result: dict[str, Stepper] = {name: make(step) for name, step in generic.items()}
    result["implicit_euler"] = lambda x, v, dt: implicit_euler_spring_step(x, v, k, m, c, dt)
    return {name: result[name] for name in INTEGRATOR_NAMES}


def error_study(dts: Sequence[float] = ERROR_DTS, repeats: int = 7) -> list[dict[str, float | str]]:
    """Largest position error over the run, and the median of ``repeats`` run times, per integrator and dt."""
    case = ERROR_CASE
    rows = []
    for name, step in steppers(case["k"], case["m"], case["c"]).items():
        for dt in dts:
            n = round(case["duration"] / dt)
            times = np.arange(1, n + 1) * dt
            exact, _ = damped_spring_exact(case["x0"], case["v0"], case["k"], case["m"], case["c"], times)
            runs = []
            for _ in range(repeats):
                x, v = case["x0"], case["v0"]
                xs = np.empty(n)
                start = time.perf_counter()
                for i in range(n):
                    x, v = step(x, v, dt)
                    xs[i] = x
                runs.append(time.perf_counter() - start)
            error = float(np.max(np.abs(xs - exact))) if np.all(np.isfinite(xs)) else float("inf")
            rows.append({"integrator": name, "dt": dt, "steps": n, "max_error": error,
                         "seconds": float(np.median(runs))})
    return rows


def stiffness_sweep(
    ratios: Sequence[float] = STIFFNESS_RATIOS,
    dt: float = SWEEP_DT,
    steps: int = SWEEP_STEPS,
    overrides: dict[str, Callable] | None = None,
    names: Sequence[str] = INTEGRATOR_NAMES,
) -> dict[str, np.ndarray]:
    """``name -> bool array`` (bounded per k/m ratio) for undamped springs started at x = 1, v = 0.

    All ratios run at once (numpy arrays). A run is *unstable* when it leaves the finite numbers, exceeds
    1e6, or when its largest amplitude over the last 1,000 steps is more than 1.5 times that over the first
    1,000 steps (it is still growing). Otherwise it is *bounded*. ``names`` picks the integrators to run.
    """
    k = np.asarray(ratios, dtype=np.float64)
    window = min(1000, steps // 2)
    result = {}
    for name in names:
        step = steppers(k, 1.0, 0.0, overrides)[name]
        x, v = np.ones_like(k), np.zeros_like(k)
        first = np.zeros_like(k)
        last = np.zeros_like(k)
        runaway = np.zeros(k.shape, dtype=bool)
        with np.errstate(over="ignore", invalid="ignore"):
            for i in range(steps):
                x, v = step(x, v, dt)
                amplitude = np.abs(x)
                runaway |= ~np.isfinite(amplitude) | (amplitude > 1e6)
                if i < window:
                    first = np.maximum(first, amplitude)
                elif i >= steps - window:
                    last = np.maximum(last, amplitude)
        result[name] = ~runaway & (last <= 1.5 * first)
    return result


def _format_error_table(rows: list[dict[str, float | str]]) -> str:
    lines = ["| integrator | dt (s) | steps | max error | run time (ms) |", "|---|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(
            f"| {r['integrator']} | {r['dt']:g} | {r['steps']} | {r['max_error']:.2e} | {1000 * r['seconds']:.2f} |"
        )
    return "\n".join(lines)


def _format_sweep_table(ratios: Sequence[float], sweep: dict[str, np.ndarray]) -> str:
    lines = ["| k/m | ω·dt | " + " | ".join(INTEGRATOR_NAMES) + " |", "|---:|---:|" + "---|" * len(INTEGRATOR_NAMES)]
    for i, r in enumerate(ratios):
        marks = " | ".join("bounded" if sweep[name][i] else "**unstable**" for name in INTEGRATOR_NAMES)
        lines.append(f"| {r:.3g} | {np.sqrt(r) * SWEEP_DT:.3g} | {marks} |")
    return "\n".join(lines)


def plot_errors(rows: list[dict[str, float | str]], path: Path) -> Path:
    """Log-log plot of the largest error against the run time, one line per integrator."""
    fig, ax = figure(figsize=(6.0, 3.8), dpi=100)
    for name in INTEGRATOR_NAMES:
        mine = [r for r in rows if r["integrator"] == name and np.isfinite(r["max_error"]) and r["max_error"] < 10]
        ax.loglog([1000 * r["seconds"] for r in mine], [r["max_error"] for r in mine], "o-", label=name, ms=4)
    label_axes(ax, "run time for 10 s of simulation (ms)", "largest position error",
               "Damped spring (k=10, m=1, c=0.4): error against cost")
    path.parent.mkdir(parents=True, exist_ok=True)
    return save_figure(fig, path)


def plot_sweep(ratios: Sequence[float], sweep: dict[str, np.ndarray], path: Path) -> Path:
    """One row of markers per integrator: green bounded, red unstable, with the theoretical limits."""
    fig, ax = figure(figsize=(6.0, 2.8), dpi=100)
    for row, name in enumerate(INTEGRATOR_NAMES):
        ok = sweep[name]
        r = np.asarray(ratios)
        ax.scatter(r[ok], np.full(ok.sum(), row), c="tab:green", marker="o", s=18)
        ax.scatter(r[~ok], np.full((~ok).sum(), row), c="tab:red", marker="x", s=18)
    for limit, label, side in ((4 / SWEEP_DT**2, "ω·dt = 2 ", "right"), (8 / SWEEP_DT**2, " ω·dt = 2√2", "left")):
        ax.axvline(limit, color="grey", ls="--", lw=0.8)
        ax.text(limit, len(INTEGRATOR_NAMES) - 0.45, label, fontsize=7, ha=side)
    ax.set_xscale("log")
    ax.set_yticks(range(len(INTEGRATOR_NAMES)), INTEGRATOR_NAMES, fontsize=8)
    ax.set_ylim(-0.6, len(INTEGRATOR_NAMES) - 0.1)
    ax.set_xlabel("k/m (1/s²), 60 Hz, 10,000 steps; green bounded, red unstable")
    path.parent.mkdir(parents=True, exist_ok=True)
    return save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=Path("out"),
                        help="folder for the two plots (default: out; the course site's are in docs/images)")
    parser.add_argument("--no-plots", action="store_true", help="print the tables only")
    args = parser.parse_args(argv)
    rows = error_study()
    print("(a) error against run time\n")
    print(_format_error_table(rows))
    sweep = stiffness_sweep()
    print("\n(b) stiffness sweep (undamped, dt = 1/60 s, 10,000 steps)\n")
    print(_format_sweep_table(STIFFNESS_RATIOS, sweep))
    args.out.mkdir(parents=True, exist_ok=True)
    table = args.out / "step05_integrators_error.md"
    table.write_text(_format_error_table(rows) + "\n")
    print(f"\nsaved {table}")
    if not args.no_plots:
        print(f"saved {plot_errors(rows, args.out / 'step05_integrators_error.png')}")
        print(f"saved {plot_sweep(STIFFNESS_RATIOS, sweep, args.out / 'step05_stiffness.png')}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
