"""The performance targets, judged from one run's JSON: the engine's CPU path and GPU-driven path against the raw
ceiling, many spinning cubes on the GPU, 100k static models with one moving, one entity's frame.

usage: python benchmarks/perf_targets.py OUT_DIR   (reads the files ``run_perf_targets.sh`` writes there,
writes ``OUT_DIR/targets.md`` and ``OUT_DIR/targets.json`` and prints the table)

Inputs: ``scenes-*.json`` (``bench_scenes.py --json``: a list of records, the host first), ``raw*.jsonl``
(``raw_ceiling.py``'s JSON lines) and, where the run sampled them, the GPU's clocks (``clocks.csv``). Ratios are of
fps measured in the same run, with the same wait: every target is judged with a read-back of each frame (``pixel``,
the CPU waits for the frame it drew); the runs with two frames in flight (``inflight``: each frame waits for the one
before, as a swap chain lets a real application) are judged again by the same targets, in rows of their own."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

#: (what, backend-independent threshold, how it is judged)
TARGETS = [
    ("1k rotating, CPU path / raw", 0.8), ("10k rotating, CPU path / raw", 0.8),
    ("1k rotating, CPU angle path / raw", 0.8), ("10k rotating, CPU angle path / raw", 0.8),
    ("1k rotating, GPU path / raw", 1.0), ("10k rotating, GPU path / raw", 1.0),
    ("100k rotating, GPU path fps", 600.0), ("1M rotating, GPU path fps", 60.0),
    ("100k static + 1 moving / one entity (fps)", 0.8),
]
ONE_ENTITY_MS = {"opengl": 0.2, "webgpu": 0.4}


SYNCS = {"pixel": "", "inflight": ", two frames in flight"}


def load(out: Path) -> tuple[list[dict[str, Any]], dict[tuple[str, int, str], float]]:
    records = []
    for path in sorted(out.glob("scenes-*.json")):
        records += [r for r in json.loads(path.read_text()) if r.get("bench") == "gandalf-scenes" and "fps" in r]
    raw = {}
    for raw_path in sorted(out.glob("raw*.jsonl")):
        for line in raw_path.read_text().splitlines():
            if line.startswith("{"):
                r = json.loads(line)
                raw[(r["backend"], int(r["n"]), r.get("sync", "pixel"))] = float(r["fps"])
    return records, raw


def find(records: list[dict[str, Any]], backend: str, scene: str, rotate: str | None,
         sync: str = "pixel") -> dict[str, Any] | None:
    for r in records:
        if (r["backend"] == backend and r["scene"] == scene and (rotate is None or r.get("rotate") == rotate)
                and r.get("sync", "pixel") == sync):
            return r
    return None


def judge(records: list[dict[str, Any]], raw_fps: dict[tuple[str, int, str], float],
          sync: str = "pixel") -> list[dict[str, Any]]:
    """The targets' rows for the runs with the wait ``sync``; with ``inflight``, only the rows that were measured."""
    rows = []
    raw = {(b, n): v for (b, n, s), v in raw_fps.items() if s == sync}
    for backend in ("opengl", "webgpu"):
        def fps(scene: str, rotate: str | None, backend: str = backend) -> float | None:
            r = find(records, backend, scene, rotate, sync)
            return None if r is None else float(r["fps"])

        def ratio(a: float | None, b: float | None) -> float | None:
            return None if a is None or not b else a / b

        one = find(records, backend, "scene1", None, sync)
        values = {
            "1k rotating, CPU path / raw": ratio(fps("cubes1k", "batch"), raw.get((backend, 1000))),
            "10k rotating, CPU path / raw": ratio(fps("cubes10k", "batch"), raw.get((backend, 10000))),
            "1k rotating, CPU angle path / raw": ratio(fps("cubes1k", "angle"), raw.get((backend, 1000))),
            "10k rotating, CPU angle path / raw": ratio(fps("cubes10k", "angle"), raw.get((backend, 10000))),
            "1k rotating, GPU path / raw": ratio(fps("cubes1k", "gpu"), raw.get((backend, 1000))),
            "10k rotating, GPU path / raw": ratio(fps("cubes10k", "gpu"), raw.get((backend, 10000))),
            "100k rotating, GPU path fps": fps("cubes100k", "gpu"),
            "1M rotating, GPU path fps": fps("cubes1m", "gpu"),
            "100k static + 1 moving / one entity (fps)": ratio(fps("static100k", "batch"), fps("scene1", None)),
        }
        for what, threshold in TARGETS:
            value = values[what]
            rows.append({"backend": backend, "target": what + SYNCS[sync], "value": value, "threshold": threshold,
                         "met": value is not None and value >= threshold})
        p50 = None if one is None else float(one["frame_ms"]["p50"])
        rows.append({"backend": backend, "target": "one entity, p50 ms a frame" + SYNCS[sync], "value": p50,
                     "threshold": ONE_ENTITY_MS[backend], "met": p50 is not None and p50 <= ONE_ENTITY_MS[backend]})
    return rows if sync == "pixel" else [row for row in rows if row["value"] is not None]


def frame_cost_rows(out: Path) -> list[dict[str, Any]]:
    """The frame's Python at 1k (``frame-cost-*.json``): the target is at most 0.2 ms on a CPU path."""
    rows = []
    for path in sorted(out.glob("frame-cost-*.json")):
        for r in json.loads(path.read_text()):
            rows.append({"backend": r["backend"], "target": f"Python a frame at {r['n']}, {r['rotate']} path (ms)",
                         "value": r["python_ms"], "threshold": 0.2, "met": r["python_ms"] <= 0.2})
    return rows


def load_clocks(path: Path) -> list[tuple[str, float]]:
    """``clocks.csv`` (nvidia-smi's ``--query-gpu=timestamp,clocks.sm,...`` lines): (timestamp, SM MHz) in order;
    empty when there is no such file."""
    samples = []
    if path.exists():
        for line in path.read_text().splitlines()[1:]:
            fields = [f.strip() for f in line.split(",")]
            if len(fields) > 1 and fields[1].endswith("MHz"):
                samples.append((fields[0], float(fields[1].split()[0])))
    return samples


def median_clock(samples: list[tuple[str, float]], span: list[str] | None) -> float | None:
    """The median SM clock (MHz) of the samples taken within ``span`` ([start, end], timestamps as nvidia-smi
    writes them, which sort as text), or None when there is none."""
    if not span or len(span) != 2:
        return None
    inside = sorted(mhz for when, mhz in samples if span[0] <= when <= span[1])
    return inside[len(inside) // 2] if inside else None


def time_table(records: list[dict[str, Any]], clocks: list[tuple[str, float]] = ()) -> str:
    """Where each scene's frame goes: CPU ms per system, the wait, GPU ms per pass (when the run timed them:
    ``--gpu-passes``) and the GPU memory the renderer holds; with ``clocks`` (:func:`load_clocks`), the GPU's median
    SM clock while the measured frames ran and while the passes were timed."""
    lines = ["| backend | scene | path | wait | fps | p50 ms | rotate ms | transform ms | render ms (gather) "
             "| sync ms | GPU ms per pass | GPU MiB |" + (" SM MHz (measured / timed) |" if clocks else ""),
             "|---|---|---|---|---:|---:|---:|---:|---:|---:|---|---:|" + ("---|" if clocks else "")]
    doubtful = False
    for r in records:
        c = r["cpu_ms"]
        passes = r.get("gpu_ms_per_pass")
        gpu = ", ".join(f"{k} {v}" for k, v in passes.items()) if passes else "—"
        if passes and not plausible_gpu_times(r):
            gpu, doubtful = gpu + " ‡", True
        held = r.get("gpu_memory_mib", {}).get("total", "—")
        lines.append(f"| {r['backend']} | {r['scene']} | {r.get('rotate') or 'static'} | {r.get('sync', 'pixel')} | "
                     f"{r['fps']} | "
                     f"{r['frame_ms']['p50']} | {c['update']} | {c['transform']} | {c['render']} "
                     f"({c.get('gather', '—')}) | {c['sync']} | {gpu} | {held} |"
                     + (f" {clock_cell(clocks, r.get('wall_clock', {}))} |" if clocks else ""))
    if doubtful:
        lines.append("\n‡ The captured frames' GPU time is longer than the measured frames' whole time (p50): those "
                     "captures did not run as the measured frames did (lower GPU clocks, or CPU work inside the "
                     "timed spans), and their milliseconds are not the frame's.")
    return "\n".join(lines) + "\n"


def clock_cell(clocks: list[tuple[str, float]], spans: dict[str, list[str]]) -> str:
    """'measured / timed' median SM clocks of a scene's two phases (— where a phase has no sample)."""
    def show(mhz: float | None) -> str:
        return "—" if mhz is None else f"{mhz:.0f}"
    measured, timed = (median_clock(clocks, spans.get(phase)) for phase in ("measured", "gpu_passes"))
    return f"{show(measured)} / {show(timed)}"


def plausible_gpu_times(record: dict[str, Any]) -> bool:
    """Whether a scene's GPU ms per pass can be those of its measured frames: with every frame waited for, no pass
    and not the whole GPU frame may take longer than the frame did on the wall clock (p50, 10 % allowed for the
    median's spread). Frames in flight overlap, so they are not checked."""
    passes = record.get("gpu_ms_per_pass") or {}
    if record.get("sync", "pixel") == "inflight" or not passes:
        return True
    return max(passes.values()) <= 1.1 * record["frame_ms"]["p50"]


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    out = Path(argv[0])
    records, raw = load(out)
    rows = judge(records, raw) + judge(records, raw, "inflight") + frame_cost_rows(out)
    lines = ["| backend | target | measured | threshold | met |", "|---|---|---:|---:|---|"]
    for row in rows:
        value = "missing" if row["value"] is None else f"{row['value']:.3g}"
        met = "—" if row["value"] is None else "yes" if row["met"] else "no"
        # Thresholds are floors, except times (ms): those are ceilings.
        lines.append(f"| {row['backend']} | {row['target']} | {value} | {row['threshold']} | {met} |")
    table = "\n".join(lines) + "\n\n" + time_table(records, load_clocks(out / "clocks.csv"))
    (out / "targets.md").write_text(table)
    raw_fps = {f"{b}-{n}" + ("" if s == "pixel" else f"-{s}"): v for (b, n, s), v in raw.items()}
    (out / "targets.json").write_text(json.dumps({"targets": rows, "raw_fps": raw_fps}, indent=1))
    print(table)
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
