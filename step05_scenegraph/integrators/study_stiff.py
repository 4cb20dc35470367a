"""The stiff-spring study: ``python -m step05_scenegraph.integrators.study_stiff --out DIR [--quick]``.

Bounded is not right. Each integrator follows a lightly damped spring (m = 1, damping ratio 0.01, x0 = 1,
v0 = 0) at the SpringSystem's fixed step (1/120 s) for ``DURATION`` seconds, with k/m from 1 to 1e6:

* the error: the largest distance from the exact solution over the run (the amplitude is 1, so an error near
  1 means the motion is lost); a run that leaves the finite numbers or passes 1e6 *blew up*, and the table
  says at which simulated time — it is reported, never reset;
* the time: the median over ``--repeats`` runs of the CPU time of the whole run, in one process.

Writes ``step05_study_stiff.json``, ``.md`` (the table) and ``.png`` (error and time against k/m) to
``--out``; the JSON and the table name the machine. No GPU is needed.
"""

from __future__ import annotations

import os
import platform
import statistics
import time
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, markdown_table, run_info, write_study

from .methods import damped_spring_exact
from .study import INTEGRATOR_NAMES, steppers

STEM = "step05_study_stiff"
RATIOS = (1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6)
QUICK_RATIOS = (1.0, 1e2, 1e4, 1e6)
DT = 1.0 / 120.0
DURATION = 5.0
DAMPING_RATIO = 0.01
BLOWN_UP = 1e6


def run(name: str, ratio: float, measure: bool = True, dt: float = DT,
        duration: float = DURATION) -> tuple[float, float | None]:
    """(largest position error, the simulated time it blew up or None) of ``name`` on the spring k/m = ``ratio``.

    With ``measure=False`` only the steps run (the timed runs): the error is 0 and no blow-up is looked for.
    """
    c = 2.0 * DAMPING_RATIO * float(np.sqrt(ratio))
    step = steppers(float(ratio), 1.0, c)[name]
    n = round(duration / dt)
    x, v = 1.0, 0.0
    if not measure:
        with np.errstate(over="ignore", invalid="ignore"):
            for _ in range(n):
                x, v = step(x, v, dt)
        return 0.0, None
    exact, _ = damped_spring_exact(1.0, 0.0, float(ratio), 1.0, c, np.arange(1, n + 1) * dt)
    worst = 0.0
    with np.errstate(over="ignore", invalid="ignore"):
        for i in range(n):
            x, v = step(x, v, dt)
            if not np.isfinite(x) or abs(x) > BLOWN_UP:
                return float("inf"), (i + 1) * dt
            worst = max(worst, abs(float(x) - float(exact[i])))
    return worst, None


def run_study(ratios, repeats: int) -> dict:
    rows = []
    for ratio in ratios:
        for name in INTEGRATOR_NAMES:
            error, blew_up = run(name, ratio)
            runs = []
            for _ in range(repeats):
                start = time.perf_counter()
                run(name, ratio, measure=False)
                runs.append(time.perf_counter() - start)
            rows.append({"k_over_m": ratio, "omega_dt": float(np.sqrt(ratio) * DT), "integrator": name,
                         "max_error": error, "blew_up_at_s": blew_up, "ms": 1000.0 * statistics.median(runs)})
            said = f"blew up at {blew_up:.3g} s" if blew_up is not None else f"error {error:.2e}"
            print(f"k/m {ratio:8.3g} {name:20s} {said}, {rows[-1]['ms']:.2f} ms", flush=True)
    return {"rows": rows, "dt": DT, "duration_s": DURATION, "damping_ratio": DAMPING_RATIO,
            "time": f"median of {repeats} runs in one process, CPU time of the whole run",
            "machine": machine(), **run_info()}


def machine() -> str:
    """The machine in words: processor, cores, Python and numpy."""
    cpu = platform.processor() or platform.machine()
    return f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}, numpy {np.__version__}"


def _cell(row: dict) -> str:
    if row["blew_up_at_s"] is not None:
        return f"**blew up** at {row['blew_up_at_s']:.3g} s"
    return f"{row['max_error']:.1e} ({row['ms']:.1f} ms)"


def markdown(result: dict) -> str:
    by_ratio: dict[float, dict[str, dict]] = {}
    for r in result["rows"]:
        by_ratio.setdefault(r["k_over_m"], {})[r["integrator"]] = r
    table = markdown_table(
        ["k/m", "ω·dt", *INTEGRATOR_NAMES],
        ([f"{ratio:.0e}", f"{np.sqrt(ratio) * result['dt']:.3g}", *(_cell(cells[n]) for n in INTEGRATOR_NAMES)]
         for ratio, cells in by_ratio.items()), left=0)
    return table + (f"\nLargest position error over {result['duration_s']:g} s (run time); measured on "
                    f"{result['machine']} ({result['host']}), {result['date']}.\n")


def plot(result: dict, path: Path) -> None:
    fig, (left, right) = figure(1, 2, figsize=(9.0, 3.6))
    for name in INTEGRATOR_NAMES:
        mine = [r for r in result["rows"] if r["integrator"] == name]
        ratios = [r["k_over_m"] for r in mine]
        errors = [max(r["max_error"], 1e-16) if r["blew_up_at_s"] is None else np.nan for r in mine]
        line = left.loglog(ratios, errors, "o-", label=name, ms=4)[0]
        blown = [r["k_over_m"] for r in mine if r["blew_up_at_s"] is not None]
        left.scatter(blown, [1e2] * len(blown), marker="x", color=line.get_color())
        right.loglog(ratios, [r["ms"] for r in mine], "o-", label=name, ms=4)
    left.axhline(1.0, color="grey", ls="--", lw=0.8)
    label_axes(left, "k/m (1/s²)", "largest position error (x: blew up)",
               f"Error at dt = 1/{1 / result['dt']:.0f} s, {result['duration_s']:g} s", legend=7)
    label_axes(right, "k/m (1/s²)", "run time (ms, median)", "Cost of the same runs", legend=None)
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    args = StudyParser("step05_scenegraph.integrators.study_stiff", __doc__, outputs=f"{STEM}.json/.md/.png",
                       quick="four stiffnesses", backends=None, repeats=(7, 3)).parse_args(argv)
    result = run_study(QUICK_RATIOS if args.quick else RATIOS, args.repeats)
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
