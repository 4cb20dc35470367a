"""Scene benchmark of the gandalf engine: frames per second, frame-time percentiles and peak memory.

Scenes (after the pyGandalf paper; no skybox):

=========  ========  ========
scene      models    rotating
=========  ========  ========
scene1     1         no
scene2     10        no
scene3     50        no
scene4     50        yes
scene5     100       yes
cubes1k    1,000     yes
cubes10k   10,000    yes
cubes100k  100,000   yes
cubes1m    1,000,000 yes
static100k 100,001   one (100k static models and 1 rotating one)
=========  ========  ========

Every configuration (backend x scene) runs in a fresh Python process, so its peak RSS
(``ru_maxrss``) belongs to that configuration alone. Each prints one JSON line.

The engine is used as an application would use it: a headless :class:`~gandalf_core.Application`,
entities with Transform/Mesh/Material components, a camera entity, and a rotate system. The rotate
system comes in two forms (``--rotate``):

* ``batch`` (default): one vectorised quaternion product over the TransformComponent store's
  ``quaternion`` column per frame;
* ``entity``: the teaching form, ``on_update_entity`` called once per entity;
* ``angle``: each entity's rotation set from an absolute angle (``phase + speed * time``) straight into
  the quaternion column, as ``raw_ceiling.py`` builds its matrices: no quaternion product, so what is
  left is the engine's own per-frame cost;
* ``gpu``: step 07's ``GpuSpinSystem`` (``step07_advanced.gpu_motion``): no per-frame CPU work for the models,
  a compute pass the renderer runs turns their instance rows (GPU-driven motion).

Every measured frame ends with a read-back (``--sync``) so the GPU has finished the frame:

* ``pixel`` (default): one pixel of the colour target;
* ``full``: the whole frame through ``app.capture()`` (adds a full-frame copy and row flip);
* ``inflight``: two frames in flight, as a swap chain of two images allows: each frame copies a pixel into a
  read-back buffer of its own and waits for the *previous* frame's pixel, so the GPU draws frame N while the CPU
  builds frame N+1 (``bench_common.GLFramesInFlight`` / ``WgpuFramesInFlight``; ``raw_ceiling.py`` has the same
  mode, ``SYNC=inflight``);
* ``none``: no wait (measures CPU submission only; the GPU may still be queueing work).

Run by hand, never in CI::

    python benchmarks/bench_scenes.py                       # every scene, both backends, 1280x720
    python benchmarks/bench_scenes.py --quick               # a smoke run of a few seconds per backend
    python benchmarks/bench_scenes.py --backends opengl --scenes scene5,cubes100k --frames 300
    python benchmarks/bench_scenes.py --scenes cubes100k --profile 25   # cProfile top functions to stderr
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import sys
import time
from pathlib import Path
from typing import Any

import bench_common
import numpy as np
from bench_common import BACKENDS, PAPER_SCENES, ROOT, SHADERS, grid_positions, rss_mb, run_child

#: scene name -> (number of models, whether they rotate): the paper's scenes, then many rotating cubes
SCENES: dict[str, tuple[int, bool]] = {
    **PAPER_SCENES,
    "cubes1k": (1_000, True),
    "cubes10k": (10_000, True),
    "cubes100k": (100_000, True),
    "cubes1m": (1_000_000, True),
    "static100k": (100_001, "one"),  # 100k static models and one rotating: what did not change must cost nothing
}
MODELS = ("cube", "sphere")
ROTATE_MODES = ("batch", "entity", "angle", "gpu")
SYNC_MODES = ("pixel", "full", "inflight", "none")


# ------------------------------------------------------------------------------------------------
# The scene (runs in the child process)
# ------------------------------------------------------------------------------------------------
def build_scene(n: int, rotating: bool | str, model: str, rotate_mode: str, spawn: str = "bulk") -> tuple[Any, Any]:
    """The benchmark scene and its model's MeshData: ``n`` lit models on a grid, a camera that sees them all;
    ``rotating``: all of them turn (True), none (False), or only the last one (``"one"``)."""
    from bench_rotate import RotateComponent, RotateEntitySystem

    from gandalf_core import Scene, System, TransformComponent
    from gandalf_core.components import CameraComponent, ClearColorComponent, MaterialComponent, MeshComponent
    from gandalf_core.math import quat_from_axis_angle, quat_mul
    from gandalf_core.resources import MaterialData, primitives
    from gandalf_core.systems.spin import SpinComponent
    from step07_advanced.gpu_motion.system import GpuSpinSystem

    class RotateBatchSystem(System):
        """Fast form: one vectorised quaternion product over the store's quaternion column."""

        def __init__(self) -> None:
            super().__init__([TransformComponent, RotateComponent])
            self._version = -1

        def _plan(self) -> None:
            # Rows, axes and speeds change only when entities come or go: gather them once then.
            store = self.scene.store(TransformComponent)
            self._rows = store.rows_of(self.column(TransformComponent))
            rotates = self.column(RotateComponent)
            self._axes = np.array([r.axis for r in rotates], dtype=np.float64).reshape(-1, 3)
            self._axes /= np.linalg.norm(self._axes, axis=1, keepdims=True)
            self._speeds = np.radians([r.speed for r in rotates])
            self._version = self.scene.membership_version

        def on_update_system(self, ts: float) -> None:
            if self._version != self.scene.membership_version:
                self._plan()
            if len(self._rows) == 0:
                return
            half = 0.5 * self._speeds * ts
            step = np.concatenate([np.cos(half)[:, None], np.sin(half)[:, None] * self._axes], axis=1)
            store = self.scene.store(TransformComponent)
            q = store.columns["quaternion"]
            q[self._rows] = quat_mul(step, q[self._rows])
            store.touch(self._rows)  # only these rows changed: the engine recomputes and uploads them alone

    class RotateAngleSystem(RotateBatchSystem):
        """Absolute angles: q = (cos(a/2), sin(a/2) * axis) with a = phase + speed * time, written in place."""

        def _plan(self) -> None:
            super()._plan()
            q = self.scene.store(TransformComponent).read("quaternion")[self._rows]
            self._phase = 2.0 * np.arctan2(np.linalg.norm(q[:, 1:], axis=1), q[:, 0])
            rows = self._rows
            consecutive = len(rows) and rows[-1] - rows[0] == len(rows) - 1 and np.all(np.diff(rows) == 1)
            self._target = slice(int(rows[0]), int(rows[-1]) + 1) if consecutive else rows
            self._time = 0.0

        def on_update_system(self, ts: float) -> None:
            if self._version != self.scene.membership_version:
                self._plan()
            if len(self._rows) == 0:
                return
            self._time += ts
            half = 0.5 * (self._phase + self._speeds * self._time)
            store = self.scene.store(TransformComponent)
            q = store.columns["quaternion"]
            q[self._target, 0] = np.cos(half)
            q[self._target, 1:] = np.sin(half)[:, None] * self._axes
            store.touch(self._target)

    scene = Scene(f"bench-{n}")
    mesh = primitives.cube() if model == "cube" else primitives.uv_sphere(0.6, 32, 16)
    scene.assets.mesh("model", mesh)
    scene.assets.material("lit", MaterialData("lit", color=(0.9, 0.6, 0.3)))
    scene.create_entity(ClearColorComponent((0.05, 0.05, 0.1)))
    g = math.ceil(round(n ** (1.0 / 3.0), 9))
    scene.create_entity(
        TransformComponent((0.0, 0.0, 1.6 * g + 2.0)), CameraComponent(60.0, 0.1, 10.0 * g + 100.0)
    )
    y_axis = (0.0, 1.0, 0.0)
    if spawn == "bulk":  # one call: Scene.create_entities with the transforms as columns
        half = 0.05 * np.arange(n)
        quats = np.zeros((n, 4))
        quats[:, 0], quats[:, 2] = np.cos(half), np.sin(half)
        parts: list[Any] = [TransformComponent.batch(translations=grid_positions(n), quaternions=quats),
                            MeshComponent("model"), MaterialComponent("lit")]
        if rotating is True and rotate_mode == "gpu":
            parts.append([SpinComponent(y_axis, 30.0 + 10.0 * (i % 7)) for i in range(n)])
        elif rotating is True:
            parts.append([RotateComponent(y_axis, 30.0 + 10.0 * (i % 7)) for i in range(n)])
        ids = scene.create_entities(n, *parts)
        if rotating == "one":
            scene.add_component(ids[-1], SpinComponent(y_axis, 45.0) if rotate_mode == "gpu"
                                else RotateComponent(y_axis, 45.0))
    for i, position in enumerate(grid_positions(n) if spawn == "loop" else ()):
        components: list[Any] = [
            TransformComponent(position, quaternion=quat_from_axis_angle(y_axis, 0.1 * i)),
            MeshComponent("model"),
            MaterialComponent("lit"),
        ]
        if rotating is True or (rotating == "one" and i == n - 1):
            speed = 30.0 + 10.0 * (i % 7)
            components.append(SpinComponent(y_axis, speed) if rotate_mode == "gpu" else RotateComponent(y_axis, speed))
        scene.create_entity(*components)
    if rotating:
        systems = {"batch": RotateBatchSystem, "entity": RotateEntitySystem, "angle": RotateAngleSystem,
                   "gpu": GpuSpinSystem}
        scene.add_system(systems[rotate_mode]())
    return scene, mesh


# ------------------------------------------------------------------------------------------------
# Synchronisation: make the GPU finish the frame
# ------------------------------------------------------------------------------------------------
def make_sync(app: Any, mode: str) -> tuple[Any, str]:
    """A callable that waits for the frame, and the mode used: a 1-pixel or a full read-back, or none."""
    if mode == "none":
        return (lambda: None), "none"
    if mode == "full":
        return app.capture, "full"
    r = app.renderer
    x, y = r.width // 2, r.height // 2
    if mode == "inflight":
        if app.backend == "opengl":
            return bench_common.GLFramesInFlight(r.ctx, r.framebuffer, x, r.height - 1 - y), "inflight"
        return bench_common.WgpuFramesInFlight(r.device, lambda: r.frame_texture, x, y), "inflight"
    return (lambda: r.read_pixel(x, y)), "pixel"


def renderer_name(app: Any) -> str:
    r = app.renderer
    if app.backend == "opengl":
        return str(r.ctx.info.get("GL_RENDERER", "?"))
    return str(getattr(r.adapter, "summary", "?"))


class Timed:
    """Wraps a system's ``on_update_system`` and accumulates its time per frame into a bucket."""

    def __init__(self, system: Any, bucket: str, totals: dict[str, float]) -> None:
        self.inner = system.on_update_system
        self.bucket = bucket
        self.totals = totals
        system.on_update_system = self  # instance attribute shadows the method; the scene calls this

    def __call__(self, ts: float) -> None:
        t0 = time.perf_counter()
        self.inner(ts)
        self.totals[self.bucket] += time.perf_counter() - t0


class TimedCall(Timed):
    """Accumulates the time of one method of an object (``frame_data``: the render system's Python part)."""

    def __init__(self, owner: Any, method: str, bucket: str, totals: dict[str, float]) -> None:
        self.inner = getattr(owner, method)
        self.bucket = bucket
        self.totals = totals
        setattr(owner, method, self)

    def __call__(self, *args: Any) -> Any:
        t0 = time.perf_counter()
        result = self.inner(*args)
        self.totals[self.bucket] += time.perf_counter() - t0
        return result


def clock_now() -> str:
    """The wall clock to the millisecond as nvidia-smi's ``timestamp`` reads it: the machine's local time,
    ``2026/12/08 02:20:01.123``."""
    import datetime

    return datetime.datetime.now().strftime("%Y/%m/%d %H:%M:%S.%f")[:-3]


# ------------------------------------------------------------------------------------------------
# One configuration (child process)
# ------------------------------------------------------------------------------------------------
def run_config(cfg: dict[str, Any]) -> dict[str, Any]:
    """Build the scene, warm up, measure; return the result record."""
    from gandalf_core import Application, TransformSystem
    from gandalf_core.render import RenderSystem
    from gandalf_core.render.gpu_memory import in_mib

    n, rotating = SCENES[cfg["scene"]]
    width, height = cfg["size"]
    if cfg.get("gpu_passes"):
        bench_common.request_gpu_timing()
    t_start = time.perf_counter()
    app = Application(cfg["backend"], width, height, headless=True, fixed_dt=1 / 60)
    if cfg["backend"] == "opengl":
        app.renderer.shaders.build("lit", SHADERS / "lit.vert", SHADERS / "lit.frag")
    else:
        app.renderer.shaders.build("lit", SHADERS / "lit.wgsl")
    t_app = time.perf_counter()
    scene, mesh = build_scene(n, rotating, cfg["model"], cfg["rotate"], cfg.get("spawn", "bulk"))
    app.add_scene(scene)
    t_scene = time.perf_counter()
    sync, sync_used = make_sync(app, cfg["sync"])

    app.step()  # first frame: core systems join, batches are planned, GPU objects are built
    sync()
    t_first = time.perf_counter()
    for _ in range(cfg["warmup"]):
        app.step()
        sync()

    totals = {"update": 0.0, "transform": 0.0, "render": 0.0, "gather": 0.0, "sync": 0.0}
    for system in scene.systems:
        if isinstance(system, RenderSystem):
            Timed(system, "render", totals)
            TimedCall(system, "frame_data", "gather", totals)  # the render system's own Python, inside "render"
        elif isinstance(system, TransformSystem):
            Timed(system, "transform", totals)
        else:
            Timed(system, "update", totals)

    profiler = None
    if cfg.get("profile"):
        import cProfile

        profiler = cProfile.Profile()
        profiler.enable()
    times = []
    deadline = time.perf_counter() + cfg["max_seconds"]
    spans = {"measured": [clock_now()]}  # wall-clock times, to line the phases up with a clock log (nvidia-smi's)
    t0 = time.perf_counter()
    for _ in range(cfg["frames"]):
        a = time.perf_counter()
        app.step()
        b = time.perf_counter()
        sync()
        c = time.perf_counter()
        totals["sync"] += c - b
        times.append(c - a)
        if c > deadline:
            break
    getattr(sync, "drain", lambda: None)()  # two frames in flight: the last frame has finished too
    wall = time.perf_counter() - t0
    spans["measured"].append(clock_now())
    if profiler is not None:
        import pstats

        profiler.disable()
        stats = pstats.Stats(profiler, stream=sys.stderr)
        stats.sort_stats("tottime").print_stats(cfg["profile"])
        stats.sort_stats("cumulative").print_stats(cfg["profile"])

    if cfg.get("png"):
        Path(cfg["png"]).mkdir(parents=True, exist_ok=True)
        app.save_png(Path(cfg["png"]) / f"{cfg['backend']}-{cfg['scene']}-{cfg['model']}.png")

    frames = len(times)
    ms = np.array(times) * 1e3
    tris = mesh.triangle_count
    record = {
        "bench": "gandalf-scenes",
        "backend": cfg["backend"],
        "scene": cfg["scene"],
        "models": n,
        "rotating": rotating,
        "rotate": cfg["rotate"] if rotating else None,
        "model": cfg["model"],
        "triangles_per_model": tris,
        "triangles": tris * n,
        "size": [width, height],
        "sync": sync_used,
        "warmup": cfg["warmup"],
        "frames": frames,
        "fps": round(frames / wall, 1),
        "frame_ms": {
            "mean": round(float(ms.mean()), 3),
            "p50": round(float(np.percentile(ms, 50)), 3),
            "p95": round(float(np.percentile(ms, 95)), 3),
            "p99": round(float(np.percentile(ms, 99)), 3),
        },
        # CPU time per frame in each part: the rotate system, the transform system, the render system
        # (gather + upload + draw submission; "gather" is its Python part, frame_data) and the read-back wait.
        "cpu_ms": {k: round(v * 1e3 / frames, 3) for k, v in totals.items()},
        "draw_calls": int(app.renderer.stats["draw_calls"]),
        "spawn": cfg.get("spawn", "bulk"),
        "setup_s": {
            "app": round(t_app - t_start, 3),
            "scene": round(t_scene - t_app, 3),
            "first_frame": round(t_first - t_scene, 3),
        },
        "renderer": renderer_name(app),
    }
    # The buffers and textures the renderer holds (as asked of the API: gandalf_core/render/gpu_memory.py), in MiB.
    record["gpu_memory_mib"] = in_mib(app.renderer.gpu_memory())
    if cfg.get("gpu_passes"):
        # After the measured frames, so the timer's queries cost the fps figures nothing.
        spans["gpu_passes"] = [clock_now()]
        record["gpu_ms_per_pass"] = bench_common.gpu_ms_per_pass(app, cfg["gpu_passes"])
        spans["gpu_passes"].append(clock_now())
    record["wall_clock"] = spans
    app.close()
    # Linux reports ru_maxrss in KiB (macOS in bytes).
    record["peak_rss_mb"] = rss_mb()
    return record


# ------------------------------------------------------------------------------------------------
# The driver (parent process)
# ------------------------------------------------------------------------------------------------
def parse_size(text: str) -> tuple[int, int]:
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"--size must look like 1280x720, got {text!r}") from None
    if w <= 0 or h <= 0:
        raise argparse.ArgumentTypeError(f"--size must be positive, got {text!r}")
    return w, h


def parse_list(text: str, allowed: tuple[str, ...] | list[str], option: str) -> list[str]:
    items = [t.strip() for t in text.split(",") if t.strip()]
    bad = [t for t in items if t not in allowed]
    if bad or not items:
        raise SystemExit(f"{option}: unknown {bad or 'empty list'}; choose from {', '.join(allowed)}")
    return items


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--backends", default="opengl,webgpu", help="comma list of opengl, webgpu")
    parser.add_argument("--scenes", default=",".join(SCENES), help=f"comma list of {', '.join(SCENES)}")
    parser.add_argument("--size", type=parse_size, default=None, help="WIDTHxHEIGHT (default 1280x720)")
    parser.add_argument("--frames", type=int, default=None, help="measured frames (default 300)")
    parser.add_argument("--warmup", type=int, default=None, help="frames before measuring (default 30)")
    parser.add_argument("--max-seconds", type=float, default=30.0,
                        help="stop measuring a configuration after this long, whatever --frames says")
    parser.add_argument("--model", choices=MODELS, default="cube", help="cube (12 triangles) or sphere (960)")
    parser.add_argument("--rotate", choices=ROTATE_MODES, default="batch", help="rotate system form")
    parser.add_argument("--spawn", choices=("bulk", "loop"), default="bulk",
                        help="create the models with Scene.create_entities (bulk, default) or one by one (loop)")
    parser.add_argument("--sync", choices=SYNC_MODES, default="pixel", help="read-back after every frame")
    parser.add_argument("--quick", action="store_true",
                        help="smoke run: 320x180, 10 frames, scenes scene1,scene5,cubes1k unless given")
    parser.add_argument("--profile", type=int, default=0, metavar="N",
                        help="cProfile the measured frames and print the top N functions to stderr")
    parser.add_argument("--png", default=None, metavar="DIR", help="save each configuration's last frame here")
    parser.add_argument("--json", default=None, metavar="FILE",
                        help="also write every record (and the host line) to FILE as one JSON list")
    parser.add_argument("--gpu-passes", type=int, default=0, metavar="FRAMES",
                        help="after measuring, time FRAMES more frames on the GPU and record each pass's median ms "
                             "(timestamp queries; llvmpipe's OpenGL draws at the flush, after them)")
    args = bench_common.parse_or_answer(parser, argv, run_config)
    if args is None:  # a child: it printed its record
        return 0

    default_scenes = "scene1,scene5,cubes1k" if args.quick else ",".join(SCENES)
    scenes_text = args.scenes if args.scenes != ",".join(SCENES) else default_scenes
    scenes = parse_list(scenes_text, list(SCENES), "--scenes")
    backends = parse_list(args.backends, BACKENDS, "--backends")
    size = args.size or ((320, 180) if args.quick else (1280, 720))
    frames = args.frames if args.frames is not None else (10 if args.quick else 300)
    warmup = args.warmup if args.warmup is not None else (2 if args.quick else 30)
    if frames < 1 or warmup < 0:
        raise SystemExit("--frames must be >= 1 and --warmup >= 0")

    host = {"bench": "gandalf-scenes-host", "python": platform.python_version(), "machine": platform.machine(),
            "cpus": os.cpu_count(), "platform": platform.platform(), "rotate": args.rotate}
    print(json.dumps(host), flush=True)
    records: list[dict[str, Any]] = [host]
    failures = 0
    plan = [(backend, scene) for backend in backends for scene in scenes]
    started = time.perf_counter()
    for k, (backend, scene) in enumerate(plan, 1):
        # Progress on stderr (the JSON lines stay alone on stdout): a full run takes minutes.
        print(f"# [{k}/{len(plan)}] {backend} {scene} ({time.perf_counter() - started:.0f} s so far)",
              file=sys.stderr, flush=True)
        cfg = {"backend": backend, "scene": scene, "size": size, "frames": frames, "warmup": warmup,
               "max_seconds": args.max_seconds, "model": args.model, "rotate": args.rotate,
               "sync": args.sync, "profile": args.profile, "png": args.png, "spawn": args.spawn,
               "gpu_passes": args.gpu_passes}
        record = run_child(__file__, cfg, {"bench": "gandalf-scenes", "backend": backend, "scene": scene})
        if record is None:
            failures += 1
            continue
        records.append(record)
        cpu = record["cpu_ms"]
        # The figures, readable, on stderr (stdout keeps the JSON lines alone).
        print(f"#   {backend:6s} {scene:10s} {record['rotate'] or 'static':6s} {record['fps']:9.1f} fps  "
              f"frame p50 {record['frame_ms']['p50']:.3f} ms  CPU ms: update {cpu['update']:.3f} "
              f"transform {cpu['transform']:.3f} render {cpu['render']:.3f} (gather {cpu['gather']:.3f}) "
              f"sync {cpu['sync']:.3f}", file=sys.stderr, flush=True)
        held = record["gpu_memory_mib"]
        print(f"#   GPU memory {held['total']:.1f} MiB: " + ", ".join(
            f"{k} {v:.1f}" for k, v in held.items() if k != "total" and v), file=sys.stderr, flush=True)
        if "gpu_ms_per_pass" in record:
            print("#   GPU ms: " + ", ".join(f"{k} {v:.3f}" for k, v in record["gpu_ms_per_pass"].items()),
                  file=sys.stderr, flush=True)
    if args.json:
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json).write_text(json.dumps(records, indent=1) + "\n")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    raise SystemExit(main())
