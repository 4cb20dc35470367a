"""Frames per second against the number of rotating cubes: the engine's CPU path, its GPU-driven path and the raw
ceiling, per API, from one ``run_perf_targets.sh`` folder (``scenes-*.json`` and ``raw*.jsonl``): each frame waited
for, and (where the folder has them) the GPU path and the ceiling with two frames in flight.

    python benchmarks/plot_fps_against_n.py benchmarks/results/h200-2026-12-03 docs/images/fps_against_n_h200.png
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from perf_targets import load  # noqa: E402

from gandalf_tools.plots import figure, label_axes, save_figure  # noqa: E402

#: (label, the scene records' rotate path, their wait) of the engine's curves.
PATHS = (("engine, CPU path (batch)", "batch", "pixel"), ("engine, CPU path (angle)", "angle", "pixel"),
         ("engine, GPU path", "gpu", "pixel"), ("engine, GPU path, two frames in flight", "gpu", "inflight"))


def main(folder: str, out: str) -> int:
    records, raw = load(Path(folder))
    fig, axes = figure(1, 2, figsize=(10, 4), sharey=True)
    for ax, api in zip(axes, ("opengl", "webgpu")):
        for label, path, sync in PATHS:
            points = sorted((r["models"], r["fps"]) for r in records
                            if r["backend"] == api and r.get("rotate") == path and r["scene"].startswith("cubes")
                            and r.get("sync", "pixel") == sync)
            if points:
                ax.plot(*zip(*points), marker="o", label=label)
        for sync, style, suffix in (("pixel", "--", ""), ("inflight", ":", ", two frames in flight")):
            ceiling = sorted((n, fps) for (backend, n, s), fps in raw.items() if backend == api and n > 1 and s == sync)
            if ceiling:
                ax.plot(*zip(*ceiling), marker="s", linestyle=style, color="black",
                        label="raw API, matrices on the CPU" + suffix)
        ax.set_xscale("log")
        ax.set_yscale("log")
        label_axes(ax, "rotating cubes", "frames per second", "OpenGL" if api == "opengl" else "WebGPU")
    print(save_figure(fig, Path(out)))
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
