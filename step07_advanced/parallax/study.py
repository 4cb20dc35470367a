"""Error against run time: how many layers steep parallax and parallax occlusion mapping need, and what the four
methods cost.

``python -m step07_advanced.parallax.study --out DIR [--backends opengl webgpu] [--quick]`` renders the demo's view
(:func:`scene.study_scene`: all four strips read by one method) headless, for steep parallax and parallax occlusion
mapping at 1, 2, 4, 8, 16, 32 and 64 layers and for normal mapping and simple parallax, and measures against the
reference, **parallax occlusion mapping with 256 layers**:

* the image error: RMSE in 8-bit steps over the strips' pixels, against the same API's reference picture;
* the uv error: where each method looks the maps up, against the reference's uv, in texels of the 256² brick
  maps (mean and 99th percentile over the strips' pixels) — computed in float64 numpy with the exercise's
  reference functions (:mod:`.reference`) on the same height map, sampled bilinearly at full resolution, for the
  pixel rays of the study's orthographic camera (the same view vectors the shader builds);
* the frame time: the median over repeats of (``frames`` frames, then one read-back of the picture, which waits
  for the GPU) / ``frames``, per API — with the engine's per-frame Python work, as an app sees it. The repeats go
  round all the configs, so a burst of other work on the machine does not spoil one of them.

It prints a table, writes ``DIR/parallax_study.json``, ``DIR/parallax_study.md`` and ``DIR/parallax_study.png``.
It needs no display.
"""

from __future__ import annotations

import argparse
import importlib
import json
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, save_figure
from gandalf_tools.studies import markdown_table

from .reference import bilinear_sampler, march_np, parallax_offset_np
from .scene import (
    DISTANCE,
    ELEVATION,
    HEIGHT_SCALE,
    LABELS,
    STRIP,
    TARGET,
    UV_SCALE,
    VIEW_HEIGHT,
    camera_eye,
    strip_positions,
    study_scene,
)

LAYERS = (1, 2, 4, 8, 16, 32, 64)
QUICK_LAYERS = (1, 4, 16, 64)
REFERENCE_LAYERS = 256
#: The brick maps' size in texels (scene.add_textures' default).
MAP_SIZE = 256


def configs(layers: tuple[int, ...]) -> list[tuple[str, int]]:
    """(method, layers) of every measured picture; the reference comes first."""
    rows = [("occlusion", REFERENCE_LAYERS), ("normal", 1), ("offset", 1)]
    rows += [(method, n) for method in ("steep", "occlusion") for n in layers]
    return rows


# --- the uv error, in numpy -----------------------------------------------------------------------
def pixel_rays(width: int, height: int, step: int = 1) -> dict[str, np.ndarray]:
    """For every ``step``-th pixel centre of the study's orthographic view that sees a strip: its uv (repeated
    texture units) and the view vector in texture space the shader builds from the camera's position."""
    eye = np.array(camera_eye())
    forward = np.asarray(TARGET) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, (0.0, 1.0, 0.0))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    rows, cols = np.mgrid[0:height:step, 0:width:step].astype(np.float64)
    x = ((cols + 0.5) / width * 2.0 - 1.0) * VIEW_HEIGHT * width / height / 2.0
    y = (1.0 - (rows + 0.5) / height * 2.0) * VIEW_HEIGHT / 2.0
    origin = eye + x.reshape(-1, 1) * right + y.reshape(-1, 1) * up
    uv = np.full((len(origin), 2), np.nan)
    points = np.full((len(origin), 3), np.nan)
    for centre in strip_positions():
        t = (centre[1] - origin[:, 1]) / forward[1]
        p = origin + t[:, None] * forward
        local = p - np.asarray(centre)
        inside = (np.abs(local[:, 0]) <= STRIP[0] / 2) & (np.abs(local[:, 2]) <= STRIP[1] / 2)
        uv[inside] = np.c_[(local[inside, 0] / STRIP[0] + 0.5) * UV_SCALE[0],
                           (local[inside, 2] / STRIP[1] + 0.5) * UV_SCALE[1]]
        points[inside] = p[inside]
    hit = ~np.isnan(uv[:, 0])
    v = eye - points[hit]
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    # A strip's tangent frame: T = +x (+u), B = -z (image up, -v), n = +y; texture space is (+u, +v, n).
    view_ts = np.c_[v[:, 0], v[:, 2], v[:, 1]]
    mask = hit.reshape(rows.shape)
    return {"uv": uv[hit], "view": view_ts, "mask": mask}


def uv_errors(layers: tuple[int, ...], width: int, height: int, step: int) -> dict[tuple[str, int], dict]:
    """The uv error of every config against the 256-layer occlusion uv (texels: mean, p99, max)."""
    from ..showcase.textures import brick_height

    height_map = bilinear_sampler(brick_height(MAP_SIZE))
    rays = pixel_rays(width, height, step)
    uv, view = rays["uv"], rays["view"]
    reference = march_np(height_map, uv, view, HEIGHT_SCALE, REFERENCE_LAYERS)["occlusion"]
    found: dict[tuple[str, int], np.ndarray] = {("normal", 1): uv, ("offset", 1):
                                                 parallax_offset_np(height_map, uv, view, HEIGHT_SCALE)}
    for n in layers:
        march = march_np(height_map, uv, view, HEIGHT_SCALE, n)
        found[("steep", n)] = march["steep"]
        found[("occlusion", n)] = march["occlusion"]
    found[("occlusion", REFERENCE_LAYERS)] = reference
    errors = {}
    for key, got in found.items():
        texels = np.linalg.norm(got - reference, axis=1) * MAP_SIZE
        errors[key] = {"mean": float(texels.mean()), "p99": float(np.percentile(texels, 99)),
                       "max": float(texels.max())}
    return errors


# --- the pictures and the clock -------------------------------------------------------------------
def device_name(app) -> str:
    renderer = app.renderer
    try:
        if hasattr(renderer, "ctx"):
            return str(renderer.ctx.info["GL_RENDERER"])
        info = renderer.adapter.info
        return str(info.get("device", "") or info.get("description", "") or info)
    except Exception:  # noqa: BLE001 - a name is only a label
        return "unknown"


def measure_backend(backend: str, rows: list[tuple[str, int]], width: int, height: int, frames: int, repeats: int,
                    mask: np.ndarray, student: bool = False) -> tuple[str, dict[tuple[str, int], dict]]:
    """(device name, {config: {"rmse", "ms", "ms_all"}}) of ``backend``: one app, one scene per config.

    The timed repeats go round the configs (config 1, 2, ..., n, then again), so that a burst of other work on
    the machine spreads over all of them instead of spoiling one; each starts with an untimed frame after the
    scene switch.
    """
    from gandalf_core import Application
    from gandalf_core.app.cli import load_impl

    from . import STEP

    impl = load_impl(STEP, student)
    results: dict[tuple[str, int], dict] = {}
    with Application(backend, width, height, headless=True, fixed_dt=1 / 60) as app:
        importlib.import_module(f"{__package__}.{backend}").register_shaders(app, impl)
        device = device_name(app)
        scenes = {}
        reference = None
        for method, layers in rows:
            scene = scenes[(method, layers)] = app.add_scene(study_scene(method, layers))
            app.switch_scene(scene)
            app.run(frames=2)  # switch, build the pipeline, draw
            picture = app.capture()[..., :3].astype(np.float64)
            if reference is None:
                reference = picture
            diff = (picture - reference)[mask]
            results[(method, layers)] = {"rmse": float(np.sqrt(np.mean(diff * diff))), "ms_all": []}
        for repeat in range(repeats):
            for key, scene in scenes.items():
                app.switch_scene(scene)
                app.run(frames=1)
                app.capture()
                start = time.perf_counter()
                app.run(frames=frames)
                app.capture()  # waits for the GPU
                results[key]["ms_all"].append((time.perf_counter() - start) / frames * 1000.0)
            print(f"  {backend}: repeat {repeat + 1} of {repeats} done", flush=True)
        for (method, layers), entry in results.items():
            entry["ms"] = float(statistics.median(entry["ms_all"]))
            print(f"  {backend:7s} {LABELS[method]:19s} {layers:4d} layers: {entry['ms']:8.2f} ms, "
                  f"RMSE {entry['rmse']:6.2f}", flush=True)
    return device, results


# --- the outputs ----------------------------------------------------------------------------------
def table(rows: list[tuple[str, int]], uv: dict, measured: dict[str, dict], backends: list[str]) -> str:
    header = ["method", "layers", "uv error mean (texels)", "uv error p99 (texels)"]
    for b in backends:
        header += [f"{b} RMSE (8-bit)", f"{b} ms/frame"]
    cells = []
    for key in rows:
        method, layers = key
        name = LABELS[method] + (" (reference)" if layers == REFERENCE_LAYERS else "")
        shown = layers if method in ("steep", "occlusion") else "–"
        row = [name, shown, f"{uv[key]['mean']:.3f}", f"{uv[key]['p99']:.3f}"]
        for b in backends:
            row += [f"{measured[b][key]['rmse']:.2f}", f"{measured[b][key]['ms']:.2f}"]
        cells.append(row)
    return markdown_table(header, cells)


def plot(path: Path, layers: tuple[int, ...], uv: dict, measured: dict[str, dict], backends: list[str]) -> None:
    fig, axes = figure(1, 3, figsize=(14, 4.2))
    styles = {"steep": "--", "occlusion": "-"}
    colors = {"opengl": "tab:blue", "webgpu": "tab:orange"}
    for method in ("steep", "occlusion"):
        axes[1].plot(layers, [uv[(method, n)]["mean"] for n in layers], styles[method], marker="o",
                     color="k", label=LABELS[method])
        for b in backends:
            axes[0].plot(layers, [measured[b][(method, n)]["rmse"] for n in layers], styles[method], marker="o",
                         color=colors[b], label=f"{LABELS[method]} ({b})")
            axes[2].plot(layers, [measured[b][(method, n)]["ms"] for n in layers], styles[method], marker="o",
                         color=colors[b], label=f"{LABELS[method]} ({b})")
    for method, style in (("normal", ":"), ("offset", "-.")):
        axes[1].axhline(uv[(method, 1)]["mean"], linestyle=style, color="grey", label=LABELS[method])
        for b in backends:
            axes[0].axhline(measured[b][(method, 1)]["rmse"], linestyle=style, color=colors[b], alpha=0.6,
                            label=f"{LABELS[method]} ({b})")
            axes[2].axhline(measured[b][(method, 1)]["ms"], linestyle=style, color=colors[b], alpha=0.6,
                            label=f"{LABELS[method]} ({b})")
    titles = ("image error against occlusion, 256 layers", "uv error against occlusion, 256 layers",
              "frame time (median)")
    ylabels = ("RMSE (8-bit steps)", "mean uv error (texels of 256²)", "ms per frame")
    for ax, title, ylabel in zip(axes, titles, ylabels, strict=True):
        ax.set_xscale("log", base=2)
        ax.set_xlabel("layers")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    for ax in axes:
        ax.set_yscale("log")
        ax.set_xticks(layers, [str(n) for n in layers])
    axes[0].legend(fontsize=6)
    axes[1].legend(fontsize=7)
    save_figure(fig, path, dpi=110)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="out", help="folder for parallax_study.json/.md/.png (default: out)")
    parser.add_argument("--backends", nargs="+", default=["opengl", "webgpu"], choices=["opengl", "webgpu"])
    parser.add_argument("--quick", action="store_true", help="fewer layer counts, 320x240, fewer repeats")
    parser.add_argument("--size", default=None, help="WIDTHxHEIGHT (default 640x480; --quick: 320x240)")
    parser.add_argument("--frames", type=int, default=None, help="frames per timed repeat (default 5; quick 3)")
    parser.add_argument("--repeats", type=int, default=None, help="timed repeats per config (default 7; quick 3)")
    parser.add_argument("--student", action="store_true", help="measure your exercises/ instead of solutions/")
    args = parser.parse_args(argv)
    size = args.size or ("320x240" if args.quick else "640x480")
    width, height = (int(v) for v in size.lower().split("x"))
    layers = QUICK_LAYERS if args.quick else LAYERS
    frames = args.frames or (3 if args.quick else 5)
    repeats = args.repeats or (3 if args.quick else 7)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = configs(layers)

    print(f"parallax study: {width}x{height}, layers {list(layers)}, reference: occlusion with {REFERENCE_LAYERS} "
          f"layers; {repeats} repeats of {frames} frames", flush=True)
    print("uv errors (numpy, float64) ...", flush=True)
    step = 2 if width * height > 100_000 else 1
    uv = uv_errors(layers, width, height, step)
    mask = pixel_rays(width, height)["mask"]
    measured: dict[str, dict] = {}
    devices: dict[str, str] = {}
    for backend in args.backends:
        print(f"{backend} ...", flush=True)
        devices[backend], measured[backend] = measure_backend(backend, rows, width, height, frames, repeats, mask,
                                                              args.student)

    text = table(rows, uv, measured, args.backends)
    print()
    print(text)
    result = {
        "technique": "parallax",
        "size": [width, height],
        "reference": f"parallax occlusion mapping with {REFERENCE_LAYERS} layers",
        "height_scale": HEIGHT_SCALE,
        "view": {"elevation_deg": ELEVATION, "distance": DISTANCE, "projection": "orthographic"},
        "frames_per_repeat": frames,
        "repeats": repeats,
        "devices": devices,
        "host": {"machine": platform.machine(), "python": platform.python_version()},
        "rows": [
            {"method": m, "layers": n, "uv_error_texels": uv[(m, n)],
             **{b: measured[b][(m, n)] for b in args.backends}}
            for m, n in rows
        ],
    }
    (out / "parallax_study.json").write_text(json.dumps(result, indent=2) + "\n")
    caption = (f"{width}×{height}, {', '.join(f'{b}: {devices[b]}' for b in args.backends)}; reference: parallax "
               f"occlusion mapping with {REFERENCE_LAYERS} layers; frame time: median of {repeats} × {frames} "
               f"frames, each repeat ending with a read-back.\n\n")
    (out / "parallax_study.md").write_text(caption + text)
    plot(out / "parallax_study.png", layers, uv, measured, args.backends)
    print(f"wrote {out / 'parallax_study.json'}, {out / 'parallax_study.md'}, {out / 'parallax_study.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

