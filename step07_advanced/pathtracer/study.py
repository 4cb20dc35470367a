"""The path tracer study: ``python -m step07_advanced.pathtracer.study --out DIR [--backends opengl webgpu]
[--quick]``.

Error against run time for progressive Monte Carlo rendering of the showcase scene (``scene.build_scene``):

* reference: the mean of ``--reference-spp`` samples per pixel (default 4096; ``--quick``: 256) of the same
  scene at ``--size`` (default 64x48; ``--quick``: 32x24), rendered by the first backend with another seed
  (``REFERENCE_SEED``), so its random streams are independent of the measured ones;
* error: the RMSE of the accumulated mean (linear radiance, all pixels and channels) against the reference after
  N = 1, 2, 4, ... ``--max-spp`` samples per pixel (default 256; ``--quick``: 64), seed 1. Monte Carlo error falls
  as 1/sqrt(N): a slope of -0.5 on the log-log plot (the fitted slope is printed; the reference's own noise,
  1/sqrt(4096) of one sample's, flattens the curve slightly at the largest N);
* time: milliseconds to accumulate N samples (N dispatches and a wait for the GPU), the median over
  ``--repeats`` runs (default 3) in this process; the kernels are compiled and the scene uploaded before timing.

Writes ``pathtracer_study.json``, ``pathtracer_study.md`` (the table) and ``pathtracer_study.png`` (RMSE against
samples per pixel and against milliseconds, log-log, with the fitted slopes) to ``--out``. Runs headless; prints
progress.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, save_figure

REFERENCE_SEED = 90210
SEED = 1


def _tracer(backend: str, size: tuple[int, int]):
    """The kernel of ``backend`` on its own headless context/device (the reference solution's shaders), with the
    showcase scene gathered and uploaded and one sample run (everything compiled)."""
    from gandalf_core.app.cli import load_impl

    reference_impl = load_impl("step07_advanced")  # the solutions, or your exercises where there are none

    from .scene import build_scene

    if backend == "opengl":
        from .compute_gl import GLPathTracer

        kernel = GLPathTracer.standalone(reference_impl, *size)
    else:
        from .compute_wgpu import WGPUPathTracer

        kernel = WGPUPathTracer.standalone(reference_impl, *size)
    scene = build_scene(kernel, samples=1, seed=SEED)
    scene.update(1 / 60)  # TransformSystem, then PathTraceSystem: gather, BVH, upload, one sample
    kernel.finish()
    return scene, kernel


def _accumulate(kernel, count: int, seed: int, checkpoints: list[int] | None = None, label: str = "") -> dict:
    """Run ``count`` samples from a cleared accumulation; at each checkpoint wait and note the time (ms) and mean."""
    kernel.clear()
    kernel.finish()
    marks = set(checkpoints or [count])
    out = {}
    elapsed = 0.0
    start = time.perf_counter()
    for i in range(count):
        kernel.dispatch(i, seed)
        if i + 1 in marks:
            kernel.finish()
            elapsed += time.perf_counter() - start
            acc = kernel.read()  # the read-back is not timed
            out[i + 1] = (elapsed * 1e3, acc[..., :3].astype(np.float64) / acc[..., 3:4])
            start = time.perf_counter()
        if label and (i + 1) % 256 == 0:
            print(f"  {label}: {i + 1}/{count} samples", flush=True)
    return out


def fit_slope(x, y) -> tuple[float, float]:
    """Least-squares line through (log x, log y): (slope, intercept)."""
    slope, intercept = np.polyfit(np.log(np.asarray(x, float)), np.log(np.asarray(y, float)), 1)
    return float(slope), float(intercept)


def run(backends: list[str], size: tuple[int, int], reference_spp: int, max_spp: int, repeats: int) -> dict:
    checkpoints = [n for n in (2 ** k for k in range(0, 20)) if n <= max_spp]
    print(f"path tracer study: {size[0]}x{size[1]}, reference {reference_spp} spp ({backends[0]}, seed "
          f"{REFERENCE_SEED}), N = {checkpoints}, {repeats} repeats", flush=True)
    reference = None
    results = []
    devices: dict[str, str] = {}
    for backend in backends:
        scene, kernel = _tracer(backend, size)
        devices[backend] = kernel.device_name
        print(f"{backend}: {devices[backend]}", flush=True)
        try:
            if reference is None:
                print(f"{backend}: reference ...", flush=True)
                t0 = time.perf_counter()
                reference = _accumulate(kernel, reference_spp, REFERENCE_SEED, label="reference")[reference_spp][1]
                print(f"{backend}: reference done in {time.perf_counter() - t0:.1f} s", flush=True)
            times: dict[int, list[float]] = {n: [] for n in checkpoints}
            means = None
            for r in range(repeats):
                marks = _accumulate(kernel, max_spp, SEED, checkpoints)
                for n in checkpoints:
                    times[n].append(marks[n][0])
                means = {n: marks[n][1] for n in checkpoints}
                print(f"{backend}: run {r + 1}/{repeats}: {max_spp} spp in {marks[max_spp][0]:.1f} ms", flush=True)
            for n in checkpoints:
                rmse = float(np.sqrt(np.mean((means[n] - reference) ** 2)))
                ms = statistics.median(times[n])
                results.append({"backend": backend, "spp": n, "rmse": rmse, "ms": ms, "ms_per_spp": ms / n})
                print(f"{backend:<7} N={n:<5} RMSE {rmse:.5f}  {ms:9.2f} ms  ({ms / n:.3f} ms/spp)", flush=True)
        finally:
            scene.teardown()  # releases the kernel (PathTraceSystem.on_destroy_system)
    slopes = {}
    for backend in backends:
        rows = [r for r in results if r["backend"] == backend]
        slopes[backend] = fit_slope([r["spp"] for r in rows], [r["rmse"] for r in rows])[0]
        print(f"{backend}: fitted slope of log RMSE against log N: {slopes[backend]:.3f} (Monte Carlo: -0.5)")
    return {"size": list(size), "reference_spp": reference_spp, "reference_backend": backends[0],
            "reference_seed": REFERENCE_SEED, "seed": SEED, "repeats": repeats, "results": results,
            "slopes": slopes, "devices": devices, "machine": platform.platform(), "python": sys.version.split()[0]}


def markdown(study: dict) -> str:
    w, h = study["size"]
    lines = [f"RMSE of the mean (linear radiance) against a {study['reference_spp']}-spp reference "
             f"({study['reference_backend']}, independent seed), {w}×{h}; time = median of {study['repeats']} runs; "
             + ", ".join(f"{b}: {d}" for b, d in study.get("devices", {}).items()) + ".",
             "", "| API | spp | RMSE | ms | ms / spp |", "|---|---:|---:|---:|---:|"]
    for r in study["results"]:
        lines.append(f"| {r['backend']} | {r['spp']} | {r['rmse']:.5f} | {r['ms']:.1f} | {r['ms_per_spp']:.2f} |")
    lines.append("")
    lines.append("Fitted slope of log RMSE against log spp: " + ", ".join(
        f"{b} {s:.3f}" for b, s in study["slopes"].items()) + " (the 1/√N law: −0.5).")
    return "\n".join(lines) + "\n"


def plot(study: dict, path: Path) -> None:
    fig, (left, right) = figure(1, 2, figsize=(10, 4))
    style = {"opengl": ("o", "C0", "C0"), "webgpu": ("s", "C1", "none")}  # marker, colour, fill
    for backend in study["slopes"]:
        marker, colour, fill = style.get(backend, ("^", "C2", "C2"))
        rows = [r for r in study["results"] if r["backend"] == backend]
        n = np.array([r["spp"] for r in rows], float)
        e = np.array([r["rmse"] for r in rows])
        slope, intercept = fit_slope(n, e)
        left.loglog(n, e, marker, color=colour, markerfacecolor=fill, markersize=8,
                    label=f"{backend} (fit slope {slope:.3f})")
        left.loglog(n, np.exp(intercept) * n ** slope, "-", color=colour, alpha=0.5)
        right.loglog([r["ms"] for r in rows], e, marker + "-", color=colour, markerfacecolor=fill, label=backend)
    n_all = np.array(sorted({r["spp"] for r in study["results"]}), float)
    e0 = max(r["rmse"] for r in study["results"] if r["spp"] == 1)
    left.loglog(n_all, e0 / np.sqrt(n_all), "k:", label="1/√N")
    left.set_xlabel("samples per pixel")
    left.set_ylabel("RMSE against the reference")
    left.legend()
    left.set_title("error against samples")
    right.set_xlabel("milliseconds")
    right.set_ylabel("RMSE against the reference")
    right.legend()
    right.set_title("error against run time")
    save_figure(fig, path, dpi=100)


def _size(text: str) -> tuple[int, int]:
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT, got {text!r}") from None
    if w < 1 or h < 1:
        raise argparse.ArgumentTypeError(f"the size must be positive, got {text!r}")
    return w, h


def _positive(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1 (0 samples per pixel would show nothing), got {value}")
    return value


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for pathtracer_study.json/.md/.png")
    parser.add_argument("--backends", nargs="+", default=["opengl", "webgpu"], choices=["opengl", "webgpu"])
    parser.add_argument("--quick", action="store_true", help="32x24, 256-spp reference, up to 64 spp")
    parser.add_argument("--size", type=_size, default=None, help="WIDTHxHEIGHT (default 64x48)")
    parser.add_argument("--reference-spp", type=_positive, default=None, help="default 4096")
    parser.add_argument("--max-spp", type=_positive, default=None, help="default 256")
    parser.add_argument("--repeats", type=_positive, default=3)
    args = parser.parse_args(argv)
    size = args.size or ((32, 24) if args.quick else (64, 48))
    reference_spp = args.reference_spp or (256 if args.quick else 4096)
    max_spp = args.max_spp or (64 if args.quick else 256)
    if max_spp > reference_spp:
        parser.error(f"--max-spp ({max_spp}) must not exceed --reference-spp ({reference_spp})")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    study = run(args.backends, size, reference_spp, max_spp, args.repeats)
    (out / "pathtracer_study.json").write_text(json.dumps(study, indent=2))
    (out / "pathtracer_study.md").write_text(markdown(study))
    try:
        plot(study, out / "pathtracer_study.png")
    except ImportError as exc:  # a GPU machine without matplotlib: plot the JSON elsewhere with plot()
        print(f"no plot ({exc}); the JSON and the table are written")
    print(f"wrote {out / 'pathtracer_study.json'}, .md and .png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
