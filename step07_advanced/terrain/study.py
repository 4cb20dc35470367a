"""The terrain study: ``python -m step07_advanced.terrain.study --out DIR [--backends opengl webgpu] [--quick]``.

How far the tessellated terrain is from the full-resolution heightfield, against what a frame costs, as the
tessellation level grows: every patch at the same level L = 1, 2, 4, 8, 16, 32, 64 (``--quick``: 1, 4, 16),
and the scene's own distance-based level of detail (levels 1 to 16, ``lod_scale`` 40) for comparison:

* the scene: the tour's terrain (16 × 16 patches over 20 × 20 units, a 256² heightmap) from the tour's camera at
  640×480; the levels come from the reference ``tess_level`` (for a uniform L: clamped to [L, L]);
* error, in float64 numpy against the full-resolution heightfield (the bilinear interpolation of the 16-bit
  texels, exactly what ``terrain_height`` returns): the patches' levels from the same rule, the vertices placed
  as WebGPU's compute pass places them (``patches.patch_vertices``: an n × n grid with its edges snapped to the
  outer levels; OpenGL's tessellator places the same vertices wherever a patch's outer levels equal its inner
  one, and differs only in the transition ring), each triangle sampled at least twice per texel; reported as the
  largest vertical error in world units (over the whole terrain) and the largest error in pixels on screen (the
  true and the tessellated point projected with the tour's camera, over the points inside the view);
* time: the median over ``--repeats`` of the frame time, each frame waited for with a one-pixel read-back (so
  the GPU's work — WebGPU's compute pass included — is inside the measurement); the first frames (compile,
  upload) are not timed; a setting stops repeating after ``--budget`` seconds (software tessellation of half a
  million triangles takes many seconds per frame), with at least one frame timed.

Writes ``terrain_study.json``, ``terrain_study.md`` (the table), ``terrain_study.png`` (error against frame
time) and ``terrain_levels.png`` (the level each patch gets from the tour's camera) to ``--out``.
Runs headless; prints progress.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, save_figure

LEVELS = (1, 2, 4, 8, 16, 32, 64)
QUICK_LEVELS = (1, 4, 16)
SIZE = (640, 480)


def _barycentric(k: int) -> np.ndarray:
    """(m, 3) barycentric weights of a triangle sampled with k steps per side (corners and edges included)."""
    i, j = np.meshgrid(np.arange(k + 1), np.arange(k + 1), indexing="ij")
    keep = i + j <= k
    a, b = i[keep] / k, j[keep] / k
    return np.stack([1.0 - a - b, a, b], axis=1)


def geometric_error(heights: np.ndarray, params, eye: np.ndarray, view_projection: np.ndarray,
                    size: tuple[int, int]) -> dict:
    """Largest vertical error (world units) and largest on-screen error (pixels) of the tessellated terrain."""
    from .heightfield import height_np
    from .patches import patch_corner_uvs, patch_levels, patch_vertices

    outer, inner = patch_levels(heights, params, eye)
    st, used = patch_vertices(outer, inner, params.budget)
    corners = patch_corner_uvs(params)
    texels = heights.shape[0]
    worst_world, worst_pixels, triangles = 0.0, 0.0, 0
    for k in range(len(inner)):
        s, t = st[k][used[k]][:, :1], st[k][used[k]][:, 1:]
        c = corners[k]
        uv = (c[0] * (1 - s) + c[1] * s) * (1 - t) + (c[3] * (1 - s) + c[2] * s) * t
        tri_uv = uv.reshape(-1, 3, 2)
        tri_y = params.height_scale * height_np(heights, tri_uv)
        e1, e2 = tri_uv[:, 1] - tri_uv[:, 0], tri_uv[:, 2] - tri_uv[:, 0]
        keep = np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]) > 0  # drop the degenerate (snapped) triangles
        tri_uv, tri_y = tri_uv[keep], tri_y[keep]
        triangles += len(tri_uv)
        n = int(np.ceil(inner[k]))
        steps = max(2, int(np.ceil(2 * texels / (params.patches * n))))  # at least two samples per texel
        weights = _barycentric(steps)
        sample_uv = np.einsum("mi,tid->tmd", weights, tri_uv).reshape(-1, 2)
        approx = np.einsum("mi,ti->tm", weights, tri_y).reshape(-1)
        true = params.height_scale * height_np(heights, sample_uv)
        worst_world = max(worst_world, float(np.abs(approx - true).max()))
        xz = (sample_uv - 0.5) * params.size
        pixels = [_to_pixels(np.stack([xz[:, 0], y, xz[:, 1]], 1), view_projection, size) for y in (approx, true)]
        inside = pixels[0][1] & pixels[1][1]
        if inside.any():
            worst_pixels = max(worst_pixels, float(np.linalg.norm(pixels[0][0] - pixels[1][0], axis=1)[inside].max()))
    return {"max_error_world": worst_world, "max_error_pixels": worst_pixels, "triangles": triangles,
            "mean_segments": float(np.ceil(inner).mean()),
            # WebGPU's indirect draw: the 6·n² vertices of each patch (its snapped, zero-area triangles included).
            "vertices_drawn": int((6 * np.ceil(inner) ** 2).sum()),
            # Uniform tessellation's error falls as 1/L and its triangles grow as L², so error · √triangles is
            # about constant along it: a rule that spends its triangles better scores lower.
            "pixels_sqrt_triangles": worst_pixels * float(np.sqrt(triangles))}


def _to_pixels(points: np.ndarray, view_projection: np.ndarray, size: tuple[int, int]):
    clip = np.c_[points, np.ones(len(points))] @ view_projection.T
    w = clip[:, 3]
    ndc = clip[:, :2] / np.where(w > 1e-9, w, 1.0)[:, None]
    inside = (w > 1e-9) & (np.abs(ndc) <= 1.0).all(axis=1)
    return (ndc + 1.0) * 0.5 * np.array(size, dtype=np.float64), inside


def frame_time(backend: str, params, frames: int, repeats: int, budget: float) -> tuple[float, int]:
    """Median seconds per frame over ``repeats`` frames (each waited for with a one-pixel read-back), fewer (at
    least one) when they would take longer than ``budget`` seconds. Returns (median, frames timed)."""
    import importlib

    variant = importlib.import_module(f"{__package__}.{backend}")
    with variant.create_app(headless=True, width=SIZE[0], height=SIZE[1], params=params) as app:
        app.run(frames=frames)  # compile, upload, first passes
        renderer = app.renderer
        renderer.read_pixel(0, 0)
        times: list[float] = []
        while len(times) < repeats and (not times or sum(times) + times[-1] <= budget):
            start = time.perf_counter()
            app.run(frames=1)
            renderer.read_pixel(0, 0)
            times.append(time.perf_counter() - start)
    return statistics.median(times), len(times)


def run(out: Path, backends: list[str], levels: tuple[int, ...], repeats: int, budget: float) -> dict:
    from gandalf_core.math import look_at, perspective

    from . import scene
    from .heightfield import quantize

    heights = quantize(scene.terrain_heights())
    eye = np.asarray(scene.EYE, dtype=np.float64)
    view_projection = perspective(scene.FOV, SIZE[0] / SIZE[1], 0.1, 100.0) @ look_at(eye, scene.TARGET)
    rows = []
    settings = [(f"uniform {level}", replace(scene.PARAMS, min_level=float(level), max_level=float(level)))
                for level in levels]
    settings.append(("LOD 1-16", scene.PARAMS))
    for name, params in settings:
        start = time.perf_counter()
        row = {"levels": name, "min_level": params.min_level, "max_level": params.max_level,
               "lod_scale": params.lod_scale, **geometric_error(heights, params, eye, view_projection, SIZE)}
        print(f"{name:10s}: {row['triangles']} triangles, largest error {row['max_error_world']:.4f} "
              f"world units, {row['max_error_pixels']:.2f} px ({time.perf_counter() - start:.1f} s)", flush=True)
        for backend in backends:
            seconds, timed = frame_time(backend, params, 2, repeats, budget)
            row[f"{backend}_ms"] = 1000.0 * seconds
            row[f"{backend}_frames"] = timed
            print(f"  {backend}: {1000.0 * seconds:.2f} ms per frame (median of {timed})", flush=True)
        rows.append(row)
    result = {"study": "terrain", "size": SIZE, "repeats": repeats, "budget_s": budget, "backends": backends,
              "machine": platform.platform(), "processor": platform.processor() or platform.machine(),
              "reference": "the bilinear 16-bit heightfield (terrain_height) in float64", "rows": rows}
    out.mkdir(parents=True, exist_ok=True)
    (out / "terrain_study.json").write_text(json.dumps(result, indent=2) + "\n")
    (out / "terrain_study.md").write_text(markdown(result))
    plot(result, out / "terrain_study.png")
    plot_levels(out / "terrain_levels.png")
    return result


def markdown(result: dict) -> str:
    backends = result["backends"]
    head = ["levels", "triangles", "WebGPU vertices drawn", "mean segments", "max error (world)", "max error (px)",
            "px · √triangles", *(f"{b} ms/frame" for b in backends)]
    lines = ["| " + " | ".join(head) + " |", "|" + "---:|" * len(head)]
    for r in result["rows"]:
        cells = [r["levels"], str(r["triangles"]), str(r["vertices_drawn"]), f"{r['mean_segments']:.2f}",
                 f"{r['max_error_world']:.4f}", f"{r['max_error_pixels']:.2f}", f"{r['pixels_sqrt_triangles']:.0f}",
                 *(f"{r[f'{b}_ms']:.2f}" for b in backends)]
        lines.append("| " + " | ".join(cells) + " |")
    lod = [r for r in result["rows"] if not r["levels"].startswith("uniform")]
    uniform = sorted((r for r in result["rows"] if r["levels"].startswith("uniform")), key=lambda r: r["triangles"])
    for r in lod:
        same = uniform_error_at(uniform, r["triangles"])
        if same is not None:
            lines.append(f"\n{r['levels']}: {r['max_error_pixels']:.2f} px with {r['triangles']} triangles; uniform "
                         f"tessellation with as many triangles: {same:.2f} px (log-log between its neighbours).")
    return "\n".join(lines) + "\n"


def uniform_error_at(uniform: list[dict], triangles: int) -> float | None:
    """The uniform levels' on-screen error at ``triangles``, interpolated log-log between the two levels around it
    (None outside their range)."""
    for a, b in zip(uniform, uniform[1:]):
        if a["triangles"] <= triangles <= b["triangles"]:
            t = np.log(triangles / a["triangles"]) / np.log(b["triangles"] / a["triangles"])
            return float(a["max_error_pixels"] * (b["max_error_pixels"] / a["max_error_pixels"]) ** t)
    return None


def plot(result: dict, path: Path) -> None:
    fig, (left, right) = figure(1, 2, figsize=(10, 4))
    rows = [r for r in result["rows"] if r["levels"].startswith("uniform")]
    lod = [r for r in result["rows"] if not r["levels"].startswith("uniform")]
    triangles = [r["triangles"] for r in rows]
    left.loglog(triangles, [r["max_error_world"] for r in rows], "o-", label="uniform L: world units")
    left.loglog(triangles, [r["max_error_pixels"] for r in rows], "s-", label="uniform L: pixels (640×480)")
    for r in lod:
        left.loglog([r["triangles"]], [r["max_error_world"]], "o", color="C2", label=f"{r['levels']}: world units")
        left.loglog([r["triangles"]], [r["max_error_pixels"]], "s", color="C3", label=f"{r['levels']}: pixels")
    left.set_xlabel("triangles")
    left.set_ylabel("largest error")
    left.set_title("error against the full heightfield")
    left.legend()
    for backend in result["backends"]:
        right.loglog([r[f"{backend}_ms"] for r in rows], [r["max_error_pixels"] for r in rows], "o-", label=backend)
        for r in rows + lod:
            right.annotate(r["levels"].replace("uniform ", "L="), (r[f"{backend}_ms"], r["max_error_pixels"]),
                           fontsize=7)
        for r in lod:
            right.plot([r[f"{backend}_ms"]], [r["max_error_pixels"]], "*", markersize=10, color="black")
    right.set_xlabel("frame time (ms, median)")
    right.set_ylabel("largest error (pixels)")
    right.set_title("error against run time")
    right.legend()
    save_figure(fig, path, dpi=110)


def plot_levels(path: Path) -> None:
    """The segments per patch side that the scene's LOD gives each patch from the tour's camera (a map seen
    from above, the camera beyond the top edge)."""
    from . import scene
    from .heightfield import quantize
    from .patches import patch_levels

    params = scene.PARAMS
    _outer, inner = patch_levels(quantize(scene.terrain_heights()), params, np.asarray(scene.EYE, dtype=np.float64))
    segments = np.ceil(inner).reshape(params.patches, params.patches)
    fig, ax = figure(figsize=(4.6, 4))
    half = params.size / 2
    image = ax.imshow(segments, origin="lower", extent=(-half, half, -half, half), cmap="viridis")
    for (j, i), n in np.ndenumerate(segments):
        x, z = -half + (i + 0.5) * params.size / params.patches, -half + (j + 0.5) * params.size / params.patches
        ax.text(x, z, str(int(n)), ha="center", va="center", fontsize=6, color="white" if n < 9 else "black")
    ax.plot([scene.EYE[0]], [min(scene.EYE[2], half - 0.3)], "rv", markersize=8)
    ax.set_xlabel("world x")
    ax.set_ylabel("world z (the camera looks towards -z)")
    ax.set_title("segments per patch side (inner level)")
    fig.colorbar(image, ax=ax)
    save_figure(fig, path, dpi=110)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m step07_advanced.terrain.study", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, required=True, help="folder for the JSON, markdown table and plot")
    parser.add_argument("--backends", nargs="+", choices=("opengl", "webgpu"), default=["opengl", "webgpu"])
    parser.add_argument("--quick", action="store_true", help="uniform levels 1, 4, 16 only, and fewer repeats")
    parser.add_argument("--levels", type=int, nargs="+", default=None,
                        help=f"the uniform levels (default {' '.join(map(str, LEVELS))})")
    parser.add_argument("--repeats", type=int, default=None, help="timed frames per setting (default 15, quick 5)")
    parser.add_argument("--budget", type=float, default=60.0,
                        help="seconds of timed frames per setting and API before it stops repeating (default 60)")
    args = parser.parse_args(argv)
    repeats = args.repeats or (5 if args.quick else 15)
    levels = tuple(args.levels) if args.levels else (QUICK_LEVELS if args.quick else LEVELS)
    if any(not 1 <= level <= 64 for level in levels) or repeats < 1:
        parser.error("levels must lie in [1, 64] and repeats be at least 1")
    result = run(args.out, args.backends, levels, repeats, args.budget)
    print(markdown(result), end="")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
