"""The pyGANDALF comparison work, exactly: the paper's five scenes with a skybox, per API, fps and peak memory.

The work (the same as the side-by-side runs with pyGANDALF described in DESIGN.md):

* scenes 1-5 of the paper: 1, 10, 50, 50 rotating and 100 rotating models;
* a skybox from six 2048² images (PNG files, decoded by the engine: ``CubeTextureData.from_files``);
* one light (a point light), Blinn-Phong shading (``benchmarks/shaders/blinn_phong.*``);
* the rotating scenes turn every model with a per-entity system in the teaching form
  (``on_update_entity`` with ``quat_from_axis_angle`` and ``quat_mul``);
* a 1280x720 glfw window when a display is there (run under ``xvfb-run -a -s "-screen 0 1280x720x24"``),
  else offscreen with a one-pixel read-back per frame (the JSON says which: ``surface``);
* a small model (a 48-triangle sphere) or a large one (a ~70k-triangle torus), both made procedurally.

``cpu_ms_per_frame`` is the process's CPU time per measured frame: on the software renderers it includes their
rendering threads, so on a machine shared with other jobs it is steadier than fps. Every configuration runs in a
fresh process (its own ``ru_maxrss``); ``--repeats`` runs are interleaved
(scene by scene, API by API, then again) and the summary lines give the median fps and the largest peak RSS.
Each run prints one JSON line (``"bench": "pygandalf-work"``), then one summary line per scene, API and model
(``"bench": "pygandalf-work-summary"``) with pyGANDALF's published figures on a machine like ours where known
(``ref_fps``, ``ref_rss_mb``) and the ratios.

    xvfb-run -a -s "-screen 0 1280x720x24" python benchmarks/bench_pygandalf_work.py      # all, 3 repeats
    python benchmarks/bench_pygandalf_work.py --offscreen --model large --scenes scene1,scene5
    python benchmarks/bench_pygandalf_work.py --quick       # 2 scenes, 256² sky, 320x180, a few frames
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import bench_common
from bench_common import BACKENDS, PAPER_SCENES, ROOT, SHADERS, grid_positions, rss_mb, run_child, sky_files

SCENES = PAPER_SCENES
MODELS = ("small", "large")

#: pyGANDALF on a machine like ours (llvmpipe/lavapipe, 1280x720 window under Xvfb, median of 3), measured side by side
REF_FPS: dict[tuple[str, str], dict[str, float]] = {
    ("opengl", "small"): {"scene1": 34.9, "scene2": 28.6, "scene3": 14.9, "scene4": 20.4, "scene5": 13.3},
    ("webgpu", "small"): {"scene1": 33.6, "scene2": 24.4, "scene3": 20.3, "scene4": 26.0, "scene5": 20.6},
    ("opengl", "large"): {"scene1": 38.1, "scene5": 1.5},
    ("webgpu", "large"): {"scene1": 25.6, "scene5": 1.3},
}
#: pyGANDALF's peak RSS (MiB): the smallest figure of the published range (the strictest comparison)
REF_RSS: dict[tuple[str, str], float] = {("opengl", "small"): 437.0, ("webgpu", "small"): 624.0,
                                         ("opengl", "large"): 692.0, ("webgpu", "large"): 692.0}


def model_mesh(model: str) -> Any:
    """The small model: a 48-triangle sphere; the large one: a 70,000-triangle torus."""
    from gandalf_core.resources import primitives

    if model == "small":
        return primitives.uv_sphere(0.6, 8, 4)
    return primitives.torus(0.45, 0.18, 350, 100)


# ------------------------------------------------------------------------------------------------
# One configuration (child process)
# ------------------------------------------------------------------------------------------------
def run_config(cfg: dict[str, Any]) -> dict[str, Any]:
    import numpy as np
    from bench_rotate import RotateComponent, RotateEntitySystem

    from gandalf_core import Application, Scene, TransformComponent
    from gandalf_core.components import (
        CameraComponent,
        LightComponent,
        MaterialComponent,
        MeshComponent,
        SkyboxComponent,
    )
    from gandalf_core.math import quat_from_axis_angle
    from gandalf_core.render.gpu_memory import in_mib
    from gandalf_core.resources import CubeTextureData, MaterialData

    n, rotating = SCENES[cfg["scene"]]
    width, height = cfg["size"]
    if cfg.get("gpu_passes"):
        bench_common.request_gpu_timing()
    t_start = time.perf_counter()
    app = Application(cfg["backend"], width, height, headless=cfg["offscreen"], fixed_dt=1 / 60,
                      title=f"pygandalf-work {cfg['scene']}")
    if cfg["backend"] == "opengl":
        app.renderer.shaders.build("blinn_phong", SHADERS / "blinn_phong.vert", SHADERS / "blinn_phong.frag")
    else:
        app.renderer.shaders.build("blinn_phong", SHADERS / "blinn_phong.wgsl")
    surface = "offscreen" if app.window is None else "window"

    scene = Scene(cfg["scene"])
    scene.assets.texture("sky", CubeTextureData.from_files([Path(p) for p in cfg["sky"]], name="sky"))
    mesh = model_mesh(cfg["model"])
    scene.assets.mesh("model", mesh)
    scene.assets.material("blinn_phong", MaterialData("blinn_phong", color=(0.85, 0.55, 0.3)))
    g = math.ceil(round(n ** (1.0 / 3.0), 9))
    scene.create_entity(TransformComponent((0.0, 0.0, 1.6 * g + 2.0)), CameraComponent(60.0, 0.1, 10.0 * g + 100.0))
    scene.create_entity(SkyboxComponent("sky"))
    scene.create_entity(TransformComponent((4.0, 6.0, 8.0)), LightComponent("point", intensity=1.0))
    axis = (0.0, 1.0, 0.0)
    for i, position in enumerate(grid_positions(n)):
        components: list[Any] = [TransformComponent(position, quaternion=quat_from_axis_angle(axis, 0.1 * i)),
                                 MeshComponent("model"), MaterialComponent("blinn_phong")]
        if rotating:
            components.append(RotateComponent(axis, 30.0 + 10.0 * (i % 7)))
        scene.create_entity(*components)
    if rotating:
        scene.add_system(RotateEntitySystem())
    app.add_scene(scene)
    t_scene = time.perf_counter()

    renderer = app.renderer
    sync = (lambda: renderer.read_pixel(renderer.width // 2, renderer.height // 2)) if surface == "offscreen" \
        else (lambda: None)  # a window's swap is the frame's end, as in pyGANDALF's loop
    app.step()
    sync()
    t_first = time.perf_counter()
    for _ in range(cfg["warmup"]):
        app.step()
        sync()
    times = []
    deadline = time.perf_counter() + cfg["max_seconds"]
    cpu0 = time.process_time()  # this process's CPU time, llvmpipe's/lavapipe's rendering threads included
    t0 = time.perf_counter()
    for _ in range(cfg["frames"]):
        a = time.perf_counter()
        app.step()
        sync()
        times.append(time.perf_counter() - a)
        if time.perf_counter() > deadline:
            break
    wall = time.perf_counter() - t0
    cpu = time.process_time() - cpu0
    gpu_passes = bench_common.gpu_ms_per_pass(app, cfg["gpu_passes"]) if cfg.get("gpu_passes") else None
    if cfg.get("png"):
        Path(cfg["png"]).mkdir(parents=True, exist_ok=True)
        app.save_png(Path(cfg["png"]) / f"pygandalf_work-{cfg['backend']}-{cfg['scene']}-{cfg['model']}.png")
    ms = np.array(times) * 1e3
    record = {
        "bench": "pygandalf-work", "backend": cfg["backend"], "scene": cfg["scene"], "models": n,
        "rotating": rotating, "model": cfg["model"], "triangles_per_model": mesh.triangle_count,
        "surface": surface, "size": [width, height], "sky_face": cfg["sky_size"], "repeat": cfg["repeat"],
        "frames": len(times), "fps": round(len(times) / wall, 2),
        "cpu_ms_per_frame": round(cpu * 1e3 / len(times), 2),
        "frame_ms_p50": round(float(np.percentile(ms, 50)), 2), "frame_ms_p95": round(float(np.percentile(ms, 95)), 2),
        "setup_s": {"app_and_scene": round(t_scene - t_start, 3), "first_frame": round(t_first - t_scene, 3)},
        "renderer": str(renderer.ctx.info.get("GL_RENDERER", "?")) if cfg["backend"] == "opengl"
        else str(getattr(renderer.adapter, "summary", "?")),
    }
    if gpu_passes is not None:
        record["gpu_ms_per_pass"] = gpu_passes
    # The buffers and textures the renderer holds (as asked of the API: gandalf_core/render/gpu_memory.py), in MiB.
    record["gpu_memory_mib"] = in_mib(renderer.gpu_memory())
    app.close()
    record["peak_rss_mb"] = rss_mb()
    return record


# ------------------------------------------------------------------------------------------------
# The driver (parent process)
# ------------------------------------------------------------------------------------------------
def summarize(records: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    keys = sorted({(r["scene"], r["backend"], r["model"]) for r in records})
    for scene, backend, model in keys:
        runs = [r for r in records if (r["scene"], r["backend"], r["model"]) == (scene, backend, model)]
        fps = statistics.median(r["fps"] for r in runs)
        rss = max(r["peak_rss_mb"] for r in runs)
        line: dict[str, Any] = {"bench": "pygandalf-work-summary", "scene": scene, "backend": backend,
                                "model": model, "surface": runs[0]["surface"], "runs": len(runs),
                                "fps_median": round(fps, 2), "peak_rss_mb_max": rss}
        # pyGANDALF's figures are for the full work in a window: compare only that.
        same_work = runs[0]["surface"] == "window" and runs[0]["size"] == [1280, 720] and runs[0]["sky_face"] == 2048
        line["same_work_as_reference"] = same_work
        ref = REF_FPS.get((backend, model), {}).get(scene) if same_work else None
        if ref is not None:
            line["ref_fps"] = ref
            line["fps_ratio"] = round(fps / ref, 2)
        ref_rss = REF_RSS.get((backend, model)) if same_work else None
        if ref_rss is not None:
            line["ref_rss_mb"] = ref_rss
            line["rss_ratio"] = round(rss / ref_rss, 2)
        out.append(line)
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--backends", default="opengl,webgpu", help="comma list of opengl, webgpu")
    parser.add_argument("--scenes", default=None, help=f"comma list of {', '.join(SCENES)} (default: all)")
    parser.add_argument("--model", choices=(*MODELS, "both"), default="small",
                        help="small (48 triangles), large (~70k) or both (default small)")
    parser.add_argument("--repeats", type=int, default=None, help="interleaved runs per configuration (default 3)")
    parser.add_argument("--frames", type=int, default=None, help="measured frames per run (default 300)")
    parser.add_argument("--warmup", type=int, default=None, help="frames before measuring (default 20)")
    parser.add_argument("--max-seconds", type=float, default=None, help="cap on measuring one run (default 20)")
    parser.add_argument("--sky-size", type=int, default=None, help="edge of each sky face (default 2048)")
    parser.add_argument("--size", default=None, help="WIDTHxHEIGHT (default 1280x720)")
    parser.add_argument("--offscreen", action="store_true", help="no window even when a display is there")
    parser.add_argument("--cache", default="/tmp/gandalf_bench_sky", help="folder for the generated sky PNGs")
    parser.add_argument("--quick", action="store_true",
                        help="smoke run: scene1,scene5, 1 repeat, 5 frames, 256² sky, 320x180, offscreen")
    parser.add_argument("--png", default=None, metavar="DIR", help="save each run's last frame here")
    parser.add_argument("--gpu-passes", type=int, default=0, metavar="FRAMES",
                        help="after measuring, capture FRAMES frames and add each pass's median GPU ms to the record")
    args = bench_common.parse_or_answer(parser, argv, run_config)
    if args is None:  # a child: it printed its record
        return 0

    quick = args.quick
    scenes = [s.strip() for s in (args.scenes or ("scene1,scene5" if quick else ",".join(SCENES))).split(",")]
    backends = [b.strip() for b in args.backends.split(",") if b.strip()]
    bad = [s for s in scenes if s not in SCENES] + [b for b in backends if b not in BACKENDS]
    if bad:
        raise SystemExit(f"unknown scene/backend {bad}; scenes: {', '.join(SCENES)}; backends: {', '.join(BACKENDS)}")
    models = list(MODELS) if args.model == "both" else [args.model]
    repeats = args.repeats or (1 if quick else 3)
    frames = args.frames or (5 if quick else 300)
    warmup = args.warmup if args.warmup is not None else (1 if quick else 20)
    max_seconds = args.max_seconds or (10.0 if quick else 20.0)
    sky_size = args.sky_size or (256 if quick else 2048)
    size = tuple(int(v) for v in (args.size or ("320x180" if quick else "1280x720")).lower().split("x"))
    offscreen = args.offscreen or quick or not os.environ.get("DISPLAY")

    print(json.dumps({"bench": "pygandalf-work-host", "python": platform.python_version(), "cpus": os.cpu_count(),
                      "platform": platform.platform(), "display": os.environ.get("DISPLAY"),
                      "surface": "offscreen" if offscreen else "window"}), flush=True)
    sky = [str(p) for p in sky_files(Path(args.cache), sky_size)]
    plan = [(rep, model, scene, backend) for rep in range(repeats) for model in models for scene in scenes
            for backend in backends]
    records: list[dict[str, Any]] = []
    failures = 0
    started = time.perf_counter()
    for k, (rep, model, scene, backend) in enumerate(plan, 1):
        print(f"# [{k}/{len(plan)}] {backend} {scene} {model} (repeat {rep + 1}/{repeats}, "
              f"{time.perf_counter() - started:.0f} s so far)", file=sys.stderr, flush=True)
        cfg = {"backend": backend, "scene": scene, "model": model, "size": list(size), "frames": frames,
               "warmup": warmup, "max_seconds": max_seconds, "sky": sky, "sky_size": sky_size,
               "offscreen": offscreen, "repeat": rep, "png": args.png, "gpu_passes": args.gpu_passes}
        record = run_child(__file__, cfg, {"bench": "pygandalf-work", "backend": backend, "scene": scene,
                                           "model": model})
        if record is None:
            failures += 1
            continue
        records.append(record)
    for line in summarize(records):
        print(json.dumps(line), flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    raise SystemExit(main())
