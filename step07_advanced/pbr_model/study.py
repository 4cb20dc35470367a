"""The IBL study: ``python -m step07_advanced.pbr_model.study --out DIR [--backends opengl webgpu] [--quick]``.

How many GGX importance samples the prefiltered environment needs, and what they cost:

* prefiltering: the procedural sky (``ibl.sky_radiance``, with its sun of radiance 16) into the five rough
  levels of the 128² cube (64² at roughness 0.2 down to 4² at 1.0), with M = 4 … 512 Hammersley samples per
  texel (``--quick``: 4 … 64), in numpy float64 on the CPU, by two methods: ``plain`` importance sampling
  (every sample reads the sky function) and ``filtered`` importance sampling (every sample reads the mip level
  of a 128² float cube of the sky that matches its share of the lobe; the demo's method);
* error, against the exact prefiltered integral ``Σ L (n·l) D dω / Σ (n·l) D dω`` by deterministic quadrature
  over a 256² cube of the sky (``--quick``: 128²), float64: the RMS error in linear radiance over up to 16²
  texels per face of each of the five levels, relative to the RMS radiance, and the largest error in 8-bit sRGB
  steps after encoding (what the GPU gets; under 1 step is invisible);
* time: the median over ``--repeats`` runs of the prefiltering's wall time;
* per backend: the model rendered at 320×240 with each M's maps, as PSNR against the same frame rendered with
  maps prefiltered by the plain method with 8 × the largest M (4096; ``--quick``: 512), and the frame time
  (median of the mean over 20 frames, each waited for by a read-back).

Writes ``pbr_model_study.json``, ``pbr_model_study.md`` (the table), ``pbr_model_study.png`` (error and time
against M) and ``pbr_model_maps.png`` (the IBL maps the demo uses) to ``--out``. Runs headless; prints progress.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import time
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, save_figure
from gandalf_tools.studies import markdown_table

SAMPLES = (4, 8, 16, 32, 64, 128, 256, 512)
QUICK_SAMPLES = (4, 8, 16, 32, 64)
SIZE = (320, 240)


METHODS = ("plain", "filtered")


def prefilter(samples: int, method: str = "plain") -> list[np.ndarray]:
    """The five rough levels (linear radiance) of the 128² cube with ``samples`` samples per texel (the time of
    a ``filtered`` run includes building its float mip chain of the sky)."""
    from gandalf_core.resources import cube_face_directions

    from .ibl import PREFILTER_LEVELS, PREFILTER_SIZE, RadianceMips, prefilter_directions, sky_radiance

    source = RadianceMips(sky_radiance, PREFILTER_SIZE) if method == "filtered" else None
    out = []
    for k in range(1, PREFILTER_LEVELS):
        s = PREFILTER_SIZE >> k
        d = cube_face_directions(s).reshape(-1, 3)
        roughness = k / (PREFILTER_LEVELS - 1)
        out.append(prefilter_directions(sky_radiance, d, roughness, samples, source).reshape(6, s, s, 3))
    return out


def _subsample(level: np.ndarray) -> np.ndarray:
    """At most 16 x 16 texels per face of a level (every stride-th texel, centred): where the error is measured."""
    stride = max(1, level.shape[1] // 16)
    return level[:, stride // 2 :: stride, stride // 2 :: stride]


def reference(grid: int) -> list[np.ndarray]:
    """The five rough levels on the texels of :func:`_subsample`, by deterministic quadrature over a grid² cube of
    the sky: ``Σ L(l) (n·l) D(h) dω / Σ (n·l) D(h) dω`` — the integral the importance samples estimate (their
    pdf is D(h)/4 with n = v = r, and n·h = sqrt((1 + n·l) / 2))."""
    from gandalf_core.resources import cube_face_directions

    from .ibl import PREFILTER_LEVELS, PREFILTER_SIZE, sky_radiance

    dirs = cube_face_directions(grid).reshape(-1, 3)
    c = (np.arange(grid) + 0.5) / grid * 2.0 - 1.0
    s, t = np.meshgrid(c, c)
    solid = np.tile(((2.0 / grid) ** 2 / (1.0 + s * s + t * t) ** 1.5).ravel(), 6)
    weighted_l = sky_radiance(dirs) * solid[:, None]
    out = []
    for k in range(1, PREFILTER_LEVELS):
        size = PREFILTER_SIZE >> k
        n = _subsample(cube_face_directions(size))
        shape = n.shape
        n = n.reshape(-1, 3)
        a2 = (k / (PREFILTER_LEVELS - 1)) ** 4
        num, den = np.zeros((len(n), 3)), np.zeros(len(n))
        for start in range(0, len(dirs), 16384):
            cos = np.clip(n @ dirs[start : start + 16384].T, 0.0, None)
            nh2 = (1.0 + cos) / 2.0
            w = cos * a2 / (np.pi * (nh2 * (a2 - 1.0) + 1.0) ** 2)
            num += w @ weighted_l[start : start + 16384]
            den += w @ solid[start : start + 16384]
        out.append((num / den[:, None]).reshape(shape))
    return out


def errors(levels: list[np.ndarray], reference: list[np.ndarray]) -> tuple[float, list[float]]:
    """(relative RMS error in linear radiance, largest error in 8-bit sRGB steps per level) over the measured
    texels."""
    from gandalf_core.resources import linear_to_srgb

    levels = [_subsample(a) for a in levels]
    diff = np.concatenate([(a - b).ravel() for a, b in zip(levels, reference)])
    ref = np.concatenate([b.ravel() for b in reference])
    steps = [float(np.abs(np.rint(linear_to_srgb(np.clip(a, 0, 1)) * 255)
                          - np.rint(linear_to_srgb(np.clip(b, 0, 1)) * 255)).max())
             for a, b in zip(levels, reference)]
    return float(np.sqrt(np.mean(diff**2)) / np.sqrt(np.mean(ref**2))), steps


def render(backend: str, maps, frames: int, repeats: int) -> tuple[np.ndarray, float]:
    """(picture, frame time in ms) of the model lit by ``maps`` (an IBLMaps)."""
    import importlib

    from gandalf_core import Application
    from gandalf_core.app.cli import load_impl

    reference_impl = load_impl("step07_advanced")  # the solutions, or your exercises where there are none

    from .scene import build_scene

    with Application(backend, *SIZE, headless=True, fixed_dt=1 / 60) as app:
        importlib.import_module(f"{__package__}.{backend}").register_shaders(app, reference_impl)
        app.add_scene(build_scene(reference_impl, ibl=maps))
        app.run(frames=2)
        picture = app.capture()
        times = []
        for _ in range(repeats):
            start = time.perf_counter()
            for _ in range(frames):
                app.run(frames=1)
                app.capture()  # waits for the GPU
            times.append((time.perf_counter() - start) / frames * 1000.0)
    return picture, statistics.median(times)


def plot(rows: list[dict], path: Path) -> None:
    fig, (ax1, ax2) = figure(1, 2, figsize=(9, 3.6))
    for method, style in zip(METHODS, ("o-", "s-")):
        sel = [r for r in rows if r["method"] == method]
        m = [r["samples"] for r in sel]
        ax1.loglog(m, [r["rms_error"] for r in sel], style, label=method)
        ax2.loglog(m, [r["prefilter_s"] for r in sel], style, label=method)
    plain = [r for r in rows if r["method"] == "plain"]
    if plain:
        m = [r["samples"] for r in plain]
        ax1.loglog(m, [plain[0]["rms_error"] * (m[0] / x) ** 0.5 for x in m], ":", color="grey", label="∝ 1/√M")
    ax1.set_xlabel("GGX samples per texel (M)")
    ax1.set_ylabel("relative RMS error (vs quadrature)")
    ax1.legend()
    ax1.grid(True, which="both", alpha=0.3)
    ax2.set_xlabel("GGX samples per texel (M)")
    ax2.set_ylabel("prefiltering time (s, numpy float64)")
    ax2.legend()
    ax2.grid(True, which="both", alpha=0.3)
    fig.suptitle("Prefiltered environment: error and cost against the sample count")
    save_figure(fig, path, dpi=100)


def plot_maps(maps, path: Path) -> None:
    """The IBL maps of ``maps`` (an IBLMaps) side by side: the +Z face (the sun's side) of every prefiltered
    level, of the irradiance map, and the BRDF table's A and B."""
    chain = maps.prefiltered.mip_chain()
    fig, axes = figure(1, len(chain) + 3, figsize=(2.0 * (len(chain) + 3), 2.4))
    for k, (ax, level) in enumerate(zip(axes, chain)):
        ax.imshow(level[4, ..., :3], interpolation="nearest")
        ax.set_title(f"level {k}: r = {k / (len(chain) - 1):.1f}", fontsize=9)
    axes[len(chain)].imshow(maps.irradiance.faces[4][..., :3], interpolation="nearest")
    axes[len(chain)].set_title("irradiance E/π", fontsize=9)
    lut = maps.brdf_lut.pixels
    for ax, channel, name in ((axes[-2], 0, "A (scale of F0)"), (axes[-1], 1, "B (bias)")):
        ax.imshow(lut[..., channel], cmap="magma", vmin=0, vmax=255, extent=(0, 1, 1, 0))
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("n·v", fontsize=8)
        ax.set_ylabel("roughness", fontsize=8)
    for ax in axes[: len(chain) + 1]:
        ax.set_xticks([])
        ax.set_yticks([])
    save_figure(fig, path, dpi=100)


def table(rows: list[dict], backends: list[str]) -> str:
    header = ["method", "samples M", "prefilter time (s, median)", "relative RMS error",
              "max error (8-bit steps), levels 1/2/3/4/5"]
    for b in backends:
        header += [f"{b} PSNR to reference maps (dB)", f"{b} frame (ms)"]
    cells = []
    for r in rows:
        row = [r["method"], r["samples"], f"{r['prefilter_s']:.3f}", f"{r['rms_error']:.4f}",
               "/".join(f"{x:.0f}" for x in r["max_steps_per_level"])]
        for b in backends:
            row += [f"{r[b]['psnr_db']:.1f}", f"{r[b]['frame_ms']:.2f}"]
        cells.append(row)
    return markdown_table(header, cells)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m step07_advanced.pbr_model.study", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=Path("out"), help="folder for the JSON, table and plot")
    parser.add_argument("--backends", nargs="*", choices=("opengl", "webgpu"), default=["opengl", "webgpu"],
                        help="backends that render the model with each M's maps (none: prefiltering only)")
    parser.add_argument("--quick", action="store_true", help="M up to 64, a coarser reference, one timed run")
    parser.add_argument("--repeats", type=int, default=None, help="timed runs per case (default 3, quick 1)")
    args = parser.parse_args(argv)
    from dataclasses import replace

    from gandalf_core.resources import cube_face_directions
    from gandalf_tools.testing import psnr

    from .ibl import PREFILTER_SIZE, default_ibl, encode_prefiltered, sky_radiance

    samples = QUICK_SAMPLES if args.quick else SAMPLES
    grid = 128 if args.quick else 256
    repeats = args.repeats or (1 if args.quick else 3)
    print(f"pbr_model study: M = {', '.join(map(str, samples))}, methods {', '.join(METHODS)}; reference: "
          f"quadrature over a {grid}² cube; {repeats} timed runs; backends: {', '.join(args.backends) or 'none'}",
          flush=True)
    print("  reference quadrature ...", end="", flush=True)
    start = time.perf_counter()
    exact = reference(grid)
    print(f" {time.perf_counter() - start:.1f} s", flush=True)
    print(f"  reference maps for the pictures: plain, M = {samples[-1] * 8} ...", end="", flush=True)
    start = time.perf_counter()
    reference_levels = prefilter(samples[-1] * 8, "plain")
    print(f" {time.perf_counter() - start:.1f} s", flush=True)
    base = default_ibl()
    level0 = sky_radiance(cube_face_directions(PREFILTER_SIZE))  # roughness 0: the sky itself

    def maps_of(levels):
        return replace(base, prefiltered=encode_prefiltered([level0, *levels]))

    pictures = {b: render(b, maps_of(reference_levels), 20, 1)[0] for b in args.backends}
    rows = []
    for method in METHODS:
        for m in samples:
            print(f"  {method:8s} M = {m:4d} ...", end="", flush=True)
            times, levels = [], None
            for _ in range(repeats):
                start = time.perf_counter()
                levels = prefilter(m, method)
                times.append(time.perf_counter() - start)
            rms, steps = errors(levels, exact)
            row = {"method": method, "samples": m, "prefilter_s": statistics.median(times), "rms_error": rms,
                   "max_steps": max(steps), "max_steps_per_level": steps}
            print(f" {row['prefilter_s']:.3f} s, relative RMS error {rms:.4f}, max steps per level "
                  f"{'/'.join(f'{x:.0f}' for x in steps)}", end="", flush=True)
            for b in args.backends:
                picture, frame_ms = render(b, maps_of(levels), 10 if args.quick else 20, repeats)
                row[b] = {"psnr_db": min(psnr(picture, pictures[b]), 99.0), "frame_ms": frame_ms}
                print(f"; {b} {row[b]['psnr_db']:.1f} dB, {frame_ms:.2f} ms/frame", end="", flush=True)
            print(flush=True)
            rows.append(row)
    args.out.mkdir(parents=True, exist_ok=True)
    text = table(rows, args.backends)
    (args.out / "pbr_model_study.md").write_text(text)
    info = {"machine": platform.platform(), "processor": platform.processor(), "reference_grid": grid,
            "picture_reference": f"plain, M = {samples[-1] * 8}",
            "render_size": SIZE, "repeats": repeats, "rows": rows}
    (args.out / "pbr_model_study.json").write_text(json.dumps(info, indent=2))
    plot(rows, args.out / "pbr_model_study.png")
    plot_maps(base, args.out / "pbr_model_maps.png")
    print(text)
    print(f"wrote {args.out / 'pbr_model_study.json'}, .md and .png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
