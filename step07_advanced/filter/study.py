"""The filter study: error against the float64 reference and GPU time, per method, radius, image size and API.

``python -m step07_advanced.filter.study --out DIR [--backends opengl webgpu] [--quick] [--repeats N]``

For each API, image size (square, the procedural landscape) and radius it runs the naive 2-D convolution
(``(2r + 1)²`` taps per pixel), the separable blur (two passes of ``2r + 1`` taps, the solutions' ``blur_pass``)
and the tiled separable blur (the same passes reading a tile + apron from workgroup memory), and measures

* the error of the 8-bit result against the float64 numpy reference (``reference.blur``, clamp-to-edge): the
  largest and the RMS difference in 8-bit steps (0.5 is perfect rounding);
* the GPU time: the median over ``--repeats`` runs of ``--batch`` dispatches of the whole filter (weights + passes)
  followed by one wait (``ctx.finish()`` in OpenGL, a 4-byte read-back in WebGPU), divided by ``--batch``, after
  one warm-up run. With ``--batch 1`` a fast GPU mostly measures the wait (about 0.25 ms for WebGPU's read-back);
  a larger batch measures the throughput.

Runs whose tap count (pixels · taps per pixel) exceeds ``--max-taps`` are skipped (the naive kernel at large radii
takes minutes on a software rasteriser); pass ``--max-taps 0`` for no limit. Writes ``DIR/filter_study.json``,
``DIR/filter_study.md`` (a markdown table) and ``DIR/filter_study.png`` (time against radius per method).
"""

from __future__ import annotations

import statistics
import time
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, save_figure
from gandalf_tools.studies import StudyParser, markdown_table, run_info, write_study

from . import reference
from .kernels import OPERATIONS

METHODS = ("naive", "separable", "tiled")
RADII, QUICK_RADII = (1, 2, 4, 8, 16, 32), (1, 4, 16)
SIZES, QUICK_SIZES = (256, 512, 1024), (128, 256)


def taps(method: str, size: int, radius: int) -> int:
    """Texel reads of one run: (2r + 1)² per pixel for the naive kernel, 2 (2r + 1) for the separable ones."""
    per_pixel = (2 * radius + 1) ** 2 if method == "naive" else 2 * (2 * radius + 1)
    return size * size * per_pixel


def _open(backend: str):
    """The filter of ``backend`` on its own headless context/device, with the reference solution's shaders."""
    from gandalf_core.app.cli import load_impl

    reference_impl = load_impl("step07_advanced")  # the solutions, or your exercises where there are none

    if backend == "opengl":
        from .compute_gl import GLImageFilter

        return GLImageFilter.standalone(reference_impl)
    from .compute_wgpu import WGPUImageFilter

    return WGPUImageFilter.standalone(reference_impl)


def measure(flt, image: np.ndarray, expected255: np.ndarray, method: str, radius: int, repeats: int,
            batch: int = 1) -> dict:
    """Error (8-bit steps) and median time per dispatch (ms) of one method on one image."""
    flt.upload(image)
    flt.dispatch(method, radius)  # warm-up (first use compiles/allocates in some drivers)
    got = flt.read().astype(np.float64)
    error = np.abs(got - expected255)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(batch):
            flt.dispatch(method, radius)
        flt.finish()
        times.append((time.perf_counter() - start) / batch)
    return {"max_error": float(error.max()), "rms_error": float(np.sqrt(np.mean(error**2))),
            "time_ms": 1000.0 * statistics.median(times), "repeats": repeats, "batch": batch}


def run_study(backends: list[str], sizes: tuple[int, ...], radii: tuple[int, ...], repeats: int,
              max_taps: float, batch: int = 1) -> dict:
    rows = []
    devices = {}
    expected: dict[tuple[int, int], np.ndarray] = {}
    for backend in backends:
        flt = _open(backend)
        devices[backend] = flt.device_name
        print(f"[{backend}] {devices[backend]}", flush=True)
        try:
            for size in sizes:
                image = reference.source_image(size, size)
                for radius in radii:
                    if (size, radius) not in expected:
                        expected[(size, radius)] = reference.blur(reference.to_float(image), radius) * 255.0
                    for method in METHODS:
                        row = {"backend": backend, "method": method, "size": size, "radius": radius,
                               "taps": taps(method, size, radius)}
                        if max_taps and row["taps"] > max_taps:
                            row.update(max_error=None, rms_error=None, time_ms=None, repeats=0, skipped=True)
                            print(f"[{backend}] {size}² r={radius:<2} {method:<9} skipped ({row['taps']:.2g} taps)",
                                  flush=True)
                        else:
                            row.update(measure(flt, image, expected[(size, radius)], method, radius, repeats, batch))
                            print(f"[{backend}] {size}² r={radius:<2} {method:<9} {row['time_ms']:9.3f} ms  "
                                  f"max {row['max_error']:.3f}  rms {row['rms_error']:.3f}", flush=True)
                        rows.append(row)
        finally:
            flt.release()
    return {"rows": rows, "devices": devices, "methods": list(METHODS),
            "reference": "float64 numpy separable Gaussian (sigma = radius / 2), clamp-to-edge; errors in 8-bit steps",
            "time": f"median of the repeats of {batch} dispatch(es) of the whole filter + one wait (GL finish / "
                    f"WebGPU 4-byte read-back), per dispatch",
            **run_info()}


def markdown(result: dict) -> str:
    """One row per API, size and radius: time (ms) and max / RMS error (8-bit steps) of each method."""
    header = ["API", "size", "radius", *(cell for m in METHODS for cell in (f"{m} ms", f"{m} max / rms"))]
    table: dict[tuple, dict] = {}
    for row in result["rows"]:
        table.setdefault((row["backend"], row["size"], row["radius"]), {})[row["method"]] = row
    lines = []
    for (backend, size, radius), by_method in table.items():
        cells = [backend, f"{size}²", radius]
        for m in METHODS:
            row = by_method.get(m)
            if row is None or row.get("skipped"):
                cells += ["—", "—"]
            else:
                cells += [f"{row['time_ms']:.2f}", f"{row['max_error']:.2f} / {row['rms_error']:.2f}"]
        lines.append(cells)
    return markdown_table(header, lines, left=len(header))


def plot(result: dict, path: Path) -> None:
    backends = list(dict.fromkeys(r["backend"] for r in result["rows"]))
    sizes = sorted({r["size"] for r in result["rows"]})
    fig, axes = figure(1, len(backends), figsize=(6.2 * len(backends), 4.4), squeeze=False, sharey=True)
    colours = {"naive": "tab:red", "separable": "tab:blue", "tiled": "tab:green"}
    styles = ["-", "--", ":", "-."]
    for ax, backend in zip(axes[0], backends):
        for method in METHODS:
            for k, size in enumerate(sizes):
                pts = [(r["radius"], r["time_ms"]) for r in result["rows"] if r["backend"] == backend
                       and r["method"] == method and r["size"] == size and r["time_ms"] is not None]
                if pts:
                    x, y = zip(*pts)
                    ax.plot(x, y, styles[k % len(styles)], marker="o", ms=3, color=colours[method],
                            label=f"{method} {size}²")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel("kernel radius (pixels)")
        ax.set_title(f"{backend}: {result['devices'].get(backend, '')}"[:60], fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("GPU time per blur (ms, median)")
    axes[0][-1].legend(fontsize=7, ncol=len(METHODS))
    save_figure(fig, path, dpi=110)


def main(argv: list[str] | None = None) -> int:
    parser = StudyParser("step07_advanced.filter.study", __doc__, outputs="filter_study.json/.md/.png (default: out)",
                         quick=f"sizes {QUICK_SIZES} and radii {QUICK_RADII} only", repeats=(5, 3))
    parser.add_argument("--batch", type=int, default=1,
                        help="dispatches per wait; the time is per dispatch (default 1: includes the wait)")
    parser.add_argument("--max-taps", type=float, default=3e8,
                        help="skip cases with more texel reads than this (default 3e8; 0 = no limit)")
    args = parser.parse_args(argv)
    assert set(METHODS) <= set(OPERATIONS)
    sizes, radii = (QUICK_SIZES, QUICK_RADII) if args.quick else (SIZES, RADII)
    if args.batch < 1:
        parser.error("--batch must be >= 1")
    result = run_study(args.backends, sizes, radii, args.repeats, args.max_taps, args.batch)
    write_study(args.out, "filter_study", result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
