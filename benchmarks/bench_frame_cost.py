"""The engine's fixed cost a frame, in Python: the median time of the rotate system, the transform system and the
render system's gathering (``frame_data``: camera, lights, instance rows) over many frames, without the driver's
work and without waiting for the GPU (those are in ``bench_scenes.py``'s ``render`` and ``sync``).

usage: python benchmarks/bench_frame_cost.py [--backend opengl] [--n 1000] [--rotate batch,angle,gpu]
                                              [--frames 2000] [--json FILE]

Each rotate mode runs in a fresh process (``bench_scenes.py``'s scene, 64×36 target). Prints one JSON line per mode
(medians in ms, and their sum: the frame's Python) and a readable line on stderr.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import bench_common
from bench_common import ROOT, SHADERS, run_child

MODES = ("batch", "angle", "entity", "gpu")


def run_config(cfg: dict[str, Any]) -> dict[str, Any]:
    from bench_scenes import build_scene

    from gandalf_core import Application
    from gandalf_core.render import RenderSystem

    app = Application(cfg["backend"], 64, 36, headless=True, fixed_dt=1 / 60)
    if cfg["backend"] == "opengl":
        app.renderer.shaders.build("lit", SHADERS / "lit.vert", SHADERS / "lit.frag")
    else:
        app.renderer.shaders.build("lit", SHADERS / "lit.wgsl")
    scene, _mesh = build_scene(cfg["n"], True, "cube", cfg["rotate"])
    app.add_scene(scene)
    for _ in range(20):  # plans, buffers and pipelines built; the GPU path's motion rows uploaded
        app.step()
    render = next(s for s in scene.systems if isinstance(s, RenderSystem))
    rotate, *others = [s for s in scene.systems if s is not render]
    times: dict[str, list[float]] = {"rotate": [], "transform": [], "gather": []}
    ts = 1 / 60
    for _ in range(cfg["frames"]):
        t0 = time.perf_counter()
        rotate.on_update_system(ts)
        t1 = time.perf_counter()
        for system in others:  # the transform system (and the light system, a few µs)
            system.on_update_system(ts)
        t2 = time.perf_counter()
        render.frame_data(ts)
        t3 = time.perf_counter()
        times["rotate"].append(t1 - t0)
        times["transform"].append(t2 - t1)
        times["gather"].append(t3 - t2)
    app.close()
    ms = {k: round(1e3 * statistics.median(v), 4) for k, v in times.items()}
    return {"bench": "gandalf-frame-cost", "backend": cfg["backend"], "n": cfg["n"], "rotate": cfg["rotate"],
            "frames": cfg["frames"], "median_ms": ms, "python_ms": round(sum(ms.values()), 4)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--backend", default="opengl", choices=bench_common.BACKENDS)
    parser.add_argument("--n", type=int, default=1000, help="rotating cubes (default 1000)")
    parser.add_argument("--rotate", default="batch,angle,gpu", help=f"comma list of {', '.join(MODES)}")
    parser.add_argument("--frames", type=int, default=2000, help="frames timed per mode (default 2000)")
    parser.add_argument("--json", default=None, metavar="FILE", help="also write the records to FILE (a JSON list)")
    args = bench_common.parse_or_answer(parser, argv, run_config)
    if args is None:
        return 0
    modes = [m.strip() for m in args.rotate.split(",") if m.strip()]
    if not modes or any(m not in MODES for m in modes):
        raise SystemExit(f"--rotate: choose from {', '.join(MODES)}")
    records = []
    for mode in modes:
        cfg = {"backend": args.backend, "n": args.n, "rotate": mode, "frames": args.frames}
        record = run_child(__file__, cfg, {"bench": "gandalf-frame-cost", "rotate": mode})
        if record is None:
            return 1
        records.append(record)
        m = record["median_ms"]
        print(f"#   {args.backend} n={args.n} {mode:6s} rotate {m['rotate']:.4f} transform {m['transform']:.4f} "
              f"gather {m['gather']:.4f} = {record['python_ms']:.4f} ms of Python a frame", file=sys.stderr, flush=True)
    if args.json:
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json).write_text(json.dumps(records, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    raise SystemExit(main())
