"""The GPU-driven motion study: ``python -m step07_advanced.gpu_motion.study --out DIR [--backends ...] [--quick]``.

What a frame of N spinning cubes costs when the spin runs on the CPU (``SpinSystem`` path ``batch``: one numpy
quaternion product, the rows recomputed and uploaded every frame) and when it runs on the GPU (path ``gpu``: a
compute pass turns the instance rows; no CPU work per cube), and whether the pictures agree:

* N: 100, 1k, 10k, 100k cubes (``--quick``: 100, 1k), the technique's scene;
* time: the median over ``--repeats`` runs of the mean frame time of ``--frames`` frames, each frame waited for
  with a one-pixel read-back (the GPU's work is inside); the first frames (compile, upload) are not timed. Beside
  it, the engine's own Python a frame (the systems' updates and the render system's gathering, not the driver's
  work): on a software rasteriser the drawing itself runs on the same CPU and hides what the path saves;
* GPU memory: what the renderer holds after the timed frames (``Renderer.gpu_memory()``), the motion pass's rows
  and moved copy included;
* error, against the per-entity CPU path (``entity``, the teaching form) at the same time t: the pixels that
  differ by more than 1/255 and the largest channel difference. The float32 argument (``tests/step07_advanced/
  test_gpu_motion.py``) bounds it by a few edge pixels; the study shows what it is.

Writes ``gpu_motion_study.json``, ``.md`` (the table) and ``.png`` (frame time against N, log-log).
"""

from __future__ import annotations

import platform
import statistics
import time
from pathlib import Path

import numpy as np

from gandalf_core.render.gpu_memory import MIB
from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, groups, markdown_table, write_study

COUNTS = (100, 1_000, 10_000, 100_000)
PATHS = ("batch", "gpu")
#: Frames run before the picture is compared (and before the timing starts).
SETTLE = 20
#: The picture's size (the timing runs at ``--size``).
PICTURE = (320, 240)


def _app(backend: str, path: str, count: int, size: tuple[int, int]):
    from gandalf_core import Application

    from .scene import build_scene

    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    app.add_scene(build_scene(path=path, count=count))
    return app


def picture(backend: str, path: str, count: int) -> np.ndarray:
    app = _app(backend, path, count, PICTURE)
    try:
        for _ in range(SETTLE):
            app.step()
        return app.capture()
    finally:
        app.close()


def timed_run(app, frames: int) -> tuple[float, float]:
    """(ms a frame, ms of the engine's Python a frame) over ``frames`` frames, each waited for with a one-pixel
    read-back. The Python is the scene's systems but the render system (their ``update_seconds``) plus the render
    system's ``frame_data`` (gathering what the renderer draws)."""
    from gandalf_core.render import RenderSystem

    scene = app.scene
    render = next(s for s in scene.systems if isinstance(s, RenderSystem))
    gather = render.frame_data
    spent = [0.0]

    def timed_gather(ts: float):
        t0 = time.perf_counter()
        data = gather(ts)
        spent[0] += time.perf_counter() - t0
        return data

    render.frame_data = timed_gather
    python = 0.0
    start = time.perf_counter()
    for _ in range(frames):
        app.step()
        app.renderer.read_pixel(0, 0)
        python += sum(s.update_seconds for s in scene.systems if s is not render)
    elapsed = time.perf_counter() - start
    del render.frame_data
    return 1000.0 * elapsed / frames, 1000.0 * (python + spent[0]) / frames


def run_study(backends: list[str], counts: tuple[int, ...], size: tuple[int, int], frames: int,
              repeats: int) -> list[dict]:
    rows = []
    for backend in backends:
        for count in counts:
            reference = picture(backend, "entity", count)
            for path in PATHS:
                print(f"  {backend} {path} N={count}", flush=True)
                row = {"backend": backend, "path": path, "count": count}
                if reference is not None:
                    diff = np.abs(picture(backend, path, count).astype(int) - reference.astype(int)).max(axis=-1)
                    row.update(pixels_off=int(np.count_nonzero(diff > 1)), max_diff=int(diff.max()))
                app = _app(backend, path, count, size)
                try:
                    for _ in range(SETTLE):
                        app.step()
                    runs = [timed_run(app, frames) for _ in range(repeats)]
                    row["gpu_mib"] = round(app.renderer.gpu_memory()["total"] / MIB, 2)
                finally:
                    app.close()
                row["frame_ms"] = round(statistics.median(r[0] for r in runs), 3)
                row["python_ms"] = round(statistics.median(r[1] for r in runs), 4)
                rows.append(row)
    return rows


def format_table(rows: list[dict]) -> str:
    def error(r: dict) -> str:
        return "—" if "pixels_off" not in r else f"{r['pixels_off']} px, max {r['max_diff']}/255"

    return markdown_table(["API", "N", "frame, CPU path (ms)", "frame, GPU path (ms)", "Python, CPU path (ms)",
                           "Python, GPU path (ms)", "GPU memory, CPU / GPU path (MiB)", "error of the GPU path"],
                          [(b, f"{n:,}", f"{cpu['frame_ms']:.2f}", f"{gpu['frame_ms']:.2f}",
                            f"{cpu['python_ms']:.3f}", f"{gpu['python_ms']:.3f}",
                            f"{cpu['gpu_mib']:.2f} / {gpu['gpu_mib']:.2f}", error(gpu))
                           for (b, n), (cpu, gpu) in _pairs(rows)], left=2)


def _pairs(rows: list[dict]) -> list[tuple[tuple[str, int], tuple[dict, dict]]]:
    out = []
    for (backend, count), mine in groups([{**r, "key": (r["backend"], r["count"])} for r in rows], "key"):
        by_path = {r["path"]: r for r in mine}
        out.append(((backend, count), (by_path["batch"], by_path["gpu"])))
    return out


def plot(rows: list[dict], path: Path, title: str) -> Path:
    fig, (frame_ax, python_ax) = figure(1, 2, figsize=(10, 4.2))
    for (backend, route), mine in groups([{**r, "key": (r["backend"], r["path"])} for r in rows], "key"):
        style = "o-" if route == "gpu" else "s--"
        counts = [r["count"] for r in mine]
        frame_ax.loglog(counts, [r["frame_ms"] for r in mine], style, label=f"{backend} {route}")
        python_ax.loglog(counts, [max(r["python_ms"], 1e-3) for r in mine], style, label=f"{backend} {route}")
    label_axes(frame_ax, "spinning cubes N", "frame time (ms, median)", title, legend=None)
    label_axes(python_ax, "spinning cubes N", "engine Python a frame (ms, median)", "the CPU work the path costs",
               legend=None)
    frame_ax.legend()
    python_ax.legend()
    return save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    args = StudyParser("step07_advanced.gpu_motion.study", __doc__, outputs="the JSON, table and plot",
                       quick="N = 100 and 1k, fewer frames", size=((640, 480), (320, 240)), frames=(20, 8),
                       repeats=(5, 3)).parse_args(argv)
    counts = COUNTS[:2] if args.quick else COUNTS
    print(f"gpu motion study: {', '.join(args.backends)}; N {counts}; {args.frames} frames x {args.repeats} runs "
          f"at {args.size[0]}x{args.size[1]}", flush=True)
    rows = run_study(args.backends, counts, args.size, args.frames, args.repeats)
    meta = {"machine": platform.node(), "python": platform.python_version(), "size": list(args.size),
            "frames": args.frames, "repeats": args.repeats, "settle_frames": SETTLE, "picture": list(PICTURE)}
    write_study(args.out, "gpu_motion_study", {"meta": meta, "rows": rows}, format_table(rows),
                lambda result, path: plot(result["rows"], path, f"Spinning cubes, {args.size[0]}x{args.size[1]}"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
