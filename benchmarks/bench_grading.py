"""How long grading one student's whole submission takes: ``python benchmarks/bench_grading.py``.

The submission is the reference solutions of every step (a complete one: every graded test runs to its end,
which is the slow case), overlaid as each step's ``exercises`` through ``GANDALF_IMPL`` — exactly how the
batch grader grades a student. Each configuration runs ``python -m gandalf_tools.grading`` on all the steps'
tests in a fresh process and is timed wall-clock (the median of ``--repeat`` runs); the slowest tests and
the time per step come from pytest's own durations.

Configurations (``--configs``): ``serial`` (``--jobs 0``: one process, no isolation), ``n1`` (one xdist
worker: isolation, no parallelism), ``n2`` (two workers, the front end's default), ``n4``, and ``n2-lp1``
(two workers with ``LP_NUM_THREADS=1``: one software-rasteriser thread each), ``n1-lp1`` (one worker, one
rasteriser thread).

Wall-clock seconds depend on what else the machine runs; the CPU seconds (user + system of the grading processes and
of the sandboxed processes they start, the software rasterisers' threads included) much less, so both are printed,
with the load average before each run.
Prints a table and, with ``--json FILE``, writes the figures.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CONFIGS = {
    "serial": ["--jobs", "0"],
    "n1": ["--jobs", "1"],
    "n2": ["--jobs", "2"],
    "n4": ["--jobs", "4"],
    "n2-lp1": ["--jobs", "2"],
    "n1-lp1": ["--jobs", "1"],
}
# Extra environment per configuration: one llvmpipe/lavapipe thread per worker, so two workers do not
# each start a rasteriser thread per core on a 2-core machine.
ENVS = {"n2-lp1": {"LP_NUM_THREADS": "1"}, "n1-lp1": {"LP_NUM_THREADS": "1"}}
DURATION = re.compile(r"^\s*([\d.]+)s (call|setup|teardown)\s+(\S+)")


def steps(selected: list[str] | None) -> list[str]:
    found = sorted(p.parent.parent.name for p in ROOT.glob("step*/solutions/__init__.py"))
    found = [s for s in found if (ROOT / "tests" / s).is_dir()]
    return [s for s in found if not selected or any(s.startswith(x) for x in selected)]


def _adopt_orphans() -> None:
    """Make this process the reaper of its descendants' orphans (Linux): the sandboxed processes run under
    ``unshare --fork``, whose parent is ended before it waits for them, so their CPU time never reached this
    process's children's account; adopted and reaped here, it does."""
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER
    except (OSError, AttributeError):
        pass


def _reap_orphans(wait: float = 2.0) -> None:
    """Wait (up to ``wait`` seconds) for the adopted orphans, so that their CPU time is counted."""
    deadline = time.monotonic() + wait
    while time.monotonic() < deadline:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            time.sleep(0.05)


def run(config: str, chosen: list[str], durations: int) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "grade.json"
        env = {**os.environ, "GANDALF_IMPL": os.pathsep.join(f"{s}={ROOT / s / 'solutions'}" for s in chosen)}
        env.update(ENVS.get(config, {}))
        cmd = [sys.executable, "-m", "gandalf_tools.grading", *[f"tests/{s}" for s in chosen], "--json", str(out)]
        cmd += [*CONFIGS[config], "--durations=0", "--durations-min=0"]
        load = os.getloadavg()[0]
        _adopt_orphans()
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        proc = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True)
        _reap_orphans()
        seconds = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        result = json.loads(out.read_text()) if out.exists() else {}
    per_test: dict[str, float] = defaultdict(float)
    for line in proc.stdout.splitlines():
        m = DURATION.match(line)
        if m:
            per_test[m.group(3)] += float(m.group(1))
    return {
        "config": config,
        "seconds": seconds,
        "cpu_seconds": cpu,
        "load_before": load,
        "exit": proc.returncode,
        "graded_tests": result.get("graded_tests", 0),
        "passed": result.get("graded_tests_passed", 0),
        "score": result.get("score", 0.0),
        "slowest": sorted(per_test.items(), key=lambda kv: -kv[1])[:durations],
        "per_step": {
            step: round(sum(v for k, v in per_test.items() if k.startswith(f"tests/{step}/")), 2) for step in chosen
        },
        "tail": proc.stdout.strip().splitlines()[-3:],
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--configs", nargs="+", default=["serial", "n2"], choices=sorted(CONFIGS))
    parser.add_argument("--steps", nargs="+", default=None, help="step prefixes (default: every step)")
    parser.add_argument("--repeat", type=int, default=1, help="runs per configuration (median reported)")
    parser.add_argument("--durations", type=int, default=15, help="how many of the slowest tests to show")
    parser.add_argument("--json", type=Path, help="write the figures to this file")
    args = parser.parse_args(argv)
    chosen = steps(args.steps)
    print(f"grading the solutions of {', '.join(chosen)} as one student's submission; cpu_count={os.cpu_count()}")
    rows = []
    for config in args.configs:
        runs = []
        for i in range(args.repeat):
            print(f"  {config} run {i + 1}/{args.repeat} ...", flush=True)
            runs.append(run(config, chosen, args.durations))
        best = sorted(runs, key=lambda r: r["seconds"])[len(runs) // 2]
        best["median_seconds"] = statistics.median(r["seconds"] for r in runs)
        best["median_cpu_seconds"] = statistics.median(r["cpu_seconds"] for r in runs)
        best["runs"] = [{"seconds": r["seconds"], "cpu_seconds": r["cpu_seconds"], "load_before": r["load_before"]}
                        for r in runs]
        rows.append(best)
        print(
            f"  {config:<7} {best['median_seconds']:7.1f} s  (CPU {best['median_cpu_seconds']:.1f} s)  "
            f"{best['passed']}/{best['graded_tests']} graded tests passed (score {best['score']:.0%}, "
            f"exit {best['exit']})",
            flush=True,
        )
    print("\n| configuration | seconds (median) | CPU seconds (median) | load before (1 min) | graded tests | passed |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        loads = ", ".join(f"{x['load_before']:.1f}" for x in r["runs"])
        print(f"| {r['config']} | {r['median_seconds']:.1f} | {r['median_cpu_seconds']:.1f} | {loads} "
              f"| {r['graded_tests']} | {r['passed']} |")
    slow = rows[0]["slowest"]
    if slow:
        print(f"\nslowest tests ({rows[0]['config']}; setup + call + teardown):")
        for nodeid, seconds in slow:
            print(f"  {seconds:6.2f} s  {nodeid}")
    print(f"\ntest time per step ({rows[0]['config']}; summed over tests, excluding start-up and collection):")
    for step, seconds in rows[0]["per_step"].items():
        print(f"  {seconds:7.2f} s  {step}")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=2))
    return 0 if all(r["exit"] == 0 for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
