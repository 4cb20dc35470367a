"""Turn the JSON lines of bench_scenes.py (and optionally raw_ceiling.py) into markdown tables.

usage: python benchmarks/summarize.py scenes.jsonl [ceiling.jsonl] [--plot OUT.png]

``--plot`` also draws fps against the number of rotating cubes, engine against the raw ceiling in both APIs,
and each scene's peak memory (matplotlib, Agg).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

#: engine scene -> raw_ceiling.py instance count it matches (same grid and camera)
CEILING_MATCH = {"scene1": 1, "scene5": 100, "cubes1k": 1000, "cubes10k": 10000, "cubes100k": 100000}


def load(path: str) -> list[dict[str, Any]]:
    """The JSON records of a file, skipping lines that are not JSON objects."""
    records = []
    for line in Path(path).read_text().splitlines():
        if line.startswith("{"):
            records.append(json.loads(line))
    return records


def scenes_table(records: list[dict[str, Any]]) -> str:
    """One row per configuration: fps, frame-time percentiles, CPU split, draw calls, memory."""
    head = ("| backend | scene | models | triangles | fps | p50 ms | p95 ms | p99 ms | rotate ms | transform ms "
            "| render ms | sync ms | draws | peak RSS MiB |")
    rows = [head, "|" + "---|" * (head.count("|") - 1)]
    for r in records:
        if r.get("bench") != "gandalf-scenes":
            continue
        if "error" in r:
            rows.append(f"| {r['backend']} | {r['scene']} | failed: {r['error']} |" + " |" * 11)
            continue
        f, c = r["frame_ms"], r["cpu_ms"]
        rows.append(
            f"| {r['backend']} | {r['scene']} | {r['models']:,} | {r['triangles']:,} | {r['fps']:,.1f} "
            f"| {f['p50']:.2f} | {f['p95']:.2f} | {f['p99']:.2f} | {c['update']:.2f} | {c['transform']:.2f} "
            f"| {c['render']:.2f} | {c['sync']:.2f} | {r['draw_calls']} | {r['peak_rss_mb']:.0f} |"
        )
    return "\n".join(rows)


def ceiling_table(scenes: list[dict[str, Any]], ceiling: list[dict[str, Any]]) -> str:
    """Engine fps next to the raw-API ceiling's for the matching instance counts."""
    raw = {(r["backend"], r["n"]): r["fps"] for r in ceiling}
    rows = ["| backend | scene | N | engine fps | raw ceiling fps | engine / ceiling |", "|---|---|---|---|---|---|"]
    for r in scenes:
        n = CEILING_MATCH.get(r.get("scene", ""))
        if r.get("bench") != "gandalf-scenes" or "error" in r or n is None or (r["backend"], n) not in raw:
            continue
        top = raw[(r["backend"], n)]
        rows.append(f"| {r['backend']} | {r['scene']} | {n:,} | {r['fps']:,.1f} | {top:,.1f} | {r['fps'] / top:.2f} |")
    return "\n".join(rows)


def plot(scenes: list[dict[str, Any]], ceiling: list[dict[str, Any]], out: str) -> None:
    """fps against N (engine and raw ceiling, both APIs, log-log) and peak RSS per scene, as one PNG."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = [r for r in scenes if r.get("bench") == "gandalf-scenes" and "error" not in r]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = {"opengl": "tab:blue", "webgpu": "tab:orange"}
    for backend, colour in colours.items():
        engine = sorted((CEILING_MATCH[r["scene"]], r["fps"]) for r in runs
                        if r["backend"] == backend and r["scene"] in CEILING_MATCH)
        raw = sorted((r["n"], r["fps"]) for r in ceiling if r.get("backend") == backend and "n" in r)
        if engine:
            left.plot(*zip(*engine), "o-", color=colour, label=f"engine, {backend}")
        if raw:
            left.plot(*zip(*raw), "s--", color=colour, alpha=0.6, label=f"raw ceiling, {backend}")
    left.set(xscale="log", yscale="log", xlabel="rotating cubes (N)", ylabel="frames per second",
             title="engine against the raw API")
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=8)
    names = [r["scene"] for r in runs if r["backend"] == "opengl"]
    for i, (backend, colour) in enumerate(colours.items()):
        rss = {r["scene"]: r["peak_rss_mb"] for r in runs if r["backend"] == backend}
        right.bar([j + 0.4 * i for j in range(len(names))], [rss.get(n, 0) for n in names], 0.4,
                  color=colour, label=backend)
    right.set_xticks([j + 0.2 for j in range(len(names))], names, rotation=30, fontsize=8)
    right.set(ylabel="peak RSS (MiB)", title="memory per scene")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main(argv: list[str]) -> int:
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__, file=sys.stderr if not argv else sys.stdout)
        return 2 if not argv else 0
    out = None
    if "--plot" in argv:
        i = argv.index("--plot")
        out = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    scenes = load(argv[0])
    print(scenes_table(scenes))
    if len(argv) > 1:
        print()
        print(ceiling_table(scenes, load(argv[1])))
    if out:
        plot(scenes, load(argv[1]) if len(argv) > 1 else [], out)
        print(f"wrote {out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
