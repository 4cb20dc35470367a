"""The BRDF's safety clamps, measured: ``python -m step07_advanced.showcase.study_clamps --out DIR [--quick]``.

The GGX shaders clamp the perceptual roughness to at least 0.045 and the cosines n·v, n·l to at least 1e-4. What
do the clamps cost in accuracy, what do they save, and what would the alternative cost in time?

* the case: a metal sphere (f0 0.9, radius 1) seen orthographically at ``SIZE``² pixels, lit by one directional
  light 30° from the view; its specular light ``ggx_specular · n·l`` per pixel, in float32 arithmetic written as
  the shaders write it (``brdf.glsl``), one sample per pixel at the pixel's centre;
* the reference: the same light integrated over the sphere in float64 (``∫ f n·l n·v dω`` over the visible
  normals, a polar grid around the half vector scaled by the lobe's width), at the material's true roughness and
  with no clamp;
* the error: the relative error of the image's total specular energy (the pixel sum times the pixel area) against
  the reference: a lobe narrower than a pixel is hit or missed by the one sample, and the energy with it;
* the roughness clamp against its alternative: roughness 0.002 to 0.3 drawn with clamps 0 (none) to 0.08 at one
  sample per pixel, and unclamped with N × N samples per pixel (N = 1 to 16); time: the median over ``--repeats``
  runs of the shading in numpy (the relative cost of N² samples, not a GPU figure);
* the cosine clamp: the same sphere with its normals bent by a normal map (seeded, up to 40°, so some face away
  from the viewer), roughness 0.5, cosine clamps 0 to 1e-2: pixels that are not finite or negative, and the
  energy error against the unclamped float64 shading of the same bent normals (n·v ≤ 0 pixels contribute 0).

Writes ``step07_study_clamps.json``, ``.md`` (the tables, the machine named) and ``.png`` to ``--out``. No GPU.
"""

from __future__ import annotations

import os
import platform
import statistics
import time
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, markdown_table, run_info, write_study

STEM = "step07_study_clamps"
SIZE = 128
F0 = 0.9
LIGHT = np.array([np.sin(np.radians(30.0)), 0.0, np.cos(np.radians(30.0))])
VIEW = np.array([0.0, 0.0, 1.0])
ROUGHNESS = (0.002, 0.005, 0.01, 0.02, 0.045, 0.1, 0.3)
CLAMPS = (0.0, 0.01, 0.02, 0.045, 0.08, 0.12)
SAMPLES = (1, 2, 4, 8, 16)
COSINE_CLAMPS = (0.0, 1e-6, 1e-4, 1e-2)
QUICK = {"ROUGHNESS": (0.005, 0.045, 0.3), "CLAMPS": (0.0, 0.045), "SAMPLES": (1, 4)}


def ggx_specular_f32(n: np.ndarray, v: np.ndarray, light: np.ndarray, roughness: float, min_roughness: float,
                     min_cosine: float) -> np.ndarray:
    """``ggx_specular(n, v, l, roughness, f0)`` of ``brdf.glsl`` in float32 (``l`` = ``light``), with the two
    clamps as arguments (0: none). ``n`` is (..., 3); ``v`` and ``light`` are unit vectors."""
    f = np.float32
    n = n.astype(f)
    v, light = v.astype(f), light.astype(f)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        n_dot_v = np.clip(n @ v, f(min_cosine), f(1.0))
        n_dot_l = np.clip(n @ light, f(min_cosine), f(1.0))
        h = (light + v) / np.linalg.norm(light + v)
        r = np.clip(f(roughness), f(min_roughness), f(1.0))
        a2 = r * r * r * r
        c = np.clip(n @ h, f(0.0), f(1.0))
        d = c * c * (a2 - f(1.0)) + f(1.0)
        dist = a2 / (f(np.pi) * d * d)
        k = (r + f(1.0)) ** 2 / f(8.0)
        g = n_dot_v / (n_dot_v * (f(1.0) - k) + k) * (n_dot_l / (n_dot_l * (f(1.0) - k) + k))
        m = f(1.0) - np.clip(v @ h, f(0.0), f(1.0))
        fresnel = f(F0) + (f(1.0) - f(F0)) * m ** 5
        return dist * g * fresnel / (f(4.0) * n_dot_v * n_dot_l)


def _sphere_normals(samples: int, size: int = SIZE) -> tuple[np.ndarray, float]:
    """The visible normals at ``samples`` × ``samples`` points per pixel (stratified centres), and the area one
    point stands for."""
    step = 2.0 / (size * samples)
    centres = -1.0 + step * (np.arange(size * samples) + 0.5)
    x, y = np.meshgrid(centres, centres)
    inside = x * x + y * y < 1.0
    x, y = x[inside], y[inside]
    return np.stack([x, y, np.sqrt(1.0 - x * x - y * y)], axis=1), step * step


def rendered_energy(roughness: float, min_roughness: float, samples: int = 1,
                    min_cosine: float = 1e-4) -> tuple[float, float]:
    """The image's total specular energy, Σ (specular · n·l) × the area each sample stands for, and the largest
    sample."""
    n, area = _sphere_normals(samples)
    value = ggx_specular_f32(n, VIEW, LIGHT, roughness, min_roughness, min_cosine) * np.maximum(n @ LIGHT, 0.0)
    return float(np.sum(value.astype(np.float64)) * area), float(value.max())


def reference_energy(roughness: float) -> float:
    """``∫ f(n) (n·l) (n·v) dω_n`` over the normals facing the viewer and the light, float64, no clamp: a polar
    grid about the half vector whose radial steps follow the lobe (tan θ = α sinh u)."""
    alpha = roughness * roughness
    h = (LIGHT + VIEW) / np.linalg.norm(LIGHT + VIEW)
    e1 = np.cross(h, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(h, e1)
    u_max = np.arcsinh(1e4 / alpha)
    u = np.linspace(0.0, u_max, 6001)
    theta = np.arctan(alpha * np.sinh(u))
    dtheta = np.gradient(theta)
    phi = np.linspace(0.0, 2.0 * np.pi, 721)[:-1]
    a2 = alpha * alpha
    k = (roughness + 1.0) ** 2 / 8.0
    fresnel = F0 + (1 - F0) * (1 - float(VIEW @ h)) ** 5
    ring = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2  # (P, 3)
    total = 0.0
    for start in range(0, len(theta), 256):  # rows of the grid in chunks whose arrays stay near the CPU's caches
        rows = slice(start, start + 256)
        t = theta[rows, None]
        n = np.cos(t)[..., None] * h + np.sin(t)[..., None] * ring  # (T, P, 3)
        n_dot_v, n_dot_l, n_dot_h = n @ VIEW, n @ LIGHT, np.cos(t)
        dist = a2 / (np.pi * (n_dot_h ** 2 * (a2 - 1.0) + 1.0) ** 2)
        visible = (n_dot_v > 0) & (n_dot_l > 0)
        nv, nl = np.where(visible, n_dot_v, 1.0), np.where(visible, n_dot_l, 1.0)
        g = nv / (nv * (1 - k) + k) * nl / (nl * (1 - k) + k)
        integrand = np.where(visible, dist * g * fresnel / 4.0, 0.0)  # f · n·l · n·v = D G F / 4
        d_omega = np.sin(t) * dtheta[rows, None] * (2.0 * np.pi / len(phi))
        total += float(np.sum(integrand * d_omega))
    return total


def _timed(function, repeats: int) -> tuple[float, float]:
    value, runs = function(), []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        runs.append(time.perf_counter() - start)
    return value, 1000.0 * statistics.median(runs)


def roughness_rows(roughness, clamps, samples, repeats: int) -> list[dict]:
    rows = []
    for r in roughness:
        reference = reference_energy(r)
        for c in clamps:
            (energy, peak), ms = _timed(lambda: rendered_energy(r, c), repeats)  # noqa: B023 (called at once)
            rows.append({"roughness": r, "method": f"clamp {c:g}", "clamp": c, "samples": 1, "ms": ms,
                         "error": abs(energy - reference) / reference, "peak": peak})
        for s in samples[1:]:
            (energy, peak), ms = _timed(lambda: rendered_energy(r, 0.0, s), repeats)  # noqa: B023
            rows.append({"roughness": r, "method": f"{s}x{s} samples", "clamp": 0.0, "samples": s, "ms": ms,
                         "error": abs(energy - reference) / reference, "peak": peak})
        print(f"roughness {r:g}: reference energy {reference:.4f}", flush=True)
    return rows


def cosine_rows(clamps, roughness: float = 0.5, seed: int = 3) -> list[dict]:
    """Bent normals (a seeded normal map up to 40°): bad pixels and the energy error for each cosine clamp."""
    n, area = _sphere_normals(1)
    rng = np.random.default_rng(seed)
    tilt = rng.normal(size=n.shape)
    tilt -= (tilt * n).sum(axis=1, keepdims=True) * n
    tilt /= np.linalg.norm(tilt, axis=1, keepdims=True)
    angle = np.radians(40.0) * rng.uniform(0.0, 1.0, len(n))[:, None]
    bent = np.cos(angle) * n + np.sin(angle) * tilt
    facing = (bent @ VIEW > 0) & (bent @ LIGHT > 0)
    exact = np.where(facing, ggx_specular_f32(bent, VIEW, LIGHT, roughness, 0.045, 0.0).astype(np.float64)
                     * np.maximum(bent @ LIGHT, 0.0), 0.0)
    reference = float(exact[np.isfinite(exact)].sum() * area)
    rows = []
    for c in clamps:
        value = ggx_specular_f32(bent, VIEW, LIGHT, roughness, 0.045, c) * np.maximum(bent @ LIGHT, 0.0)
        bad = ~np.isfinite(value) | (value < 0)
        energy = float(np.where(bad, 0.0, value).astype(np.float64).sum() * area)
        rows.append({"cosine_clamp": c, "bad_pixels": int(bad.sum()), "pixels": len(n),
                     "away_from_viewer": int((bent @ VIEW <= 0).sum()), "error": abs(energy - reference) / reference})
    return rows


def d_peak(roughness: float) -> float:
    """GGX's D at n·h = 1: 1 / (π α²) with α = roughness²."""
    return 1.0 / (np.pi * roughness ** 4)


def machine() -> str:
    return f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, numpy {np.__version__}"


def markdown(result: dict) -> str:
    rows = result["roughness_rows"]
    methods = list(dict.fromkeys(r["method"] for r in rows))
    by = {(r["roughness"], r["method"]): r for r in rows}
    table = markdown_table(["roughness", *methods],
                           ([f"{g:g}", *(f"{by[g, m]['error']:.1e}" for m in methods)]
                            for g in dict.fromkeys(r["roughness"] for r in rows)), left=0)
    times = "; ".join(f"{m}: {statistics.median(r['ms'] for r in rows if r['method'] == m):.1f} ms" for m in methods)
    smallest = min(r["roughness"] for r in rows)
    peaks = "; ".join(f"{c:g}: {d_peak(max(c, smallest)):.2g}" for c in dict.fromkeys(r["clamp"] for r in rows
                                                                                   if r["samples"] == 1))
    cos = markdown_table(["cosine clamp", "pixels not finite or negative", "energy error"],
                         ([f"{r['cosine_clamp']:g}", f"{r['bad_pixels']} of {r['pixels']}", f"{r['error']:.1e}"]
                          for r in result["cosine_rows"]), left=0)
    return (table + f"\nRelative error of the specular energy; shading time per image (median): {times}. "
            f"GGX's D at its peak, 1/(π r⁴), for the smallest roughness drawn with each clamp (float16 holds up to "
            f"65504, float32 3.4e38): {peaks}.\n\n"
            + cos + f"\nMeasured on {result['machine']} ({result['host']}), {result['date']}.\n")


def plot(result: dict, path: Path) -> None:
    fig, (left, right) = figure(1, 2, figsize=(10.0, 3.8))
    rows = result["roughness_rows"]
    for method in dict.fromkeys(r["method"] for r in rows):
        mine = [r for r in rows if r["method"] == method]
        left.loglog([r["roughness"] for r in mine], [max(r["error"], 1e-6) for r in mine], "o-", ms=4, label=method)
    label_axes(left, "material roughness", "relative energy error", "Roughness clamp or supersampling", legend=7)
    for r in [r for r in rows if r["roughness"] == min(x["roughness"] for x in rows)]:
        right.loglog([r["ms"]], [max(r["error"], 1e-6)], "o" if r["samples"] == 1 else "s", color="C0"
                     if r["samples"] == 1 else "C1")
        right.annotate(r["method"], (r["ms"], max(r["error"], 1e-6)), fontsize=7, xytext=(3, 3),
                       textcoords="offset points")
    label_axes(right, "shading time per image (ms, median, numpy)", "relative energy error",
               f"Error against time at roughness {min(x['roughness'] for x in rows):g}", legend=None)
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    args = StudyParser("step07_advanced.showcase.study_clamps", __doc__, outputs=f"{STEM}.json/.md/.png",
                       quick="three roughnesses, two clamps, 1 and 4 samples", backends=None,
                       repeats=(5, 2)).parse_args(argv)
    pick = QUICK if args.quick else {"ROUGHNESS": ROUGHNESS, "CLAMPS": CLAMPS, "SAMPLES": SAMPLES}
    result = {"roughness_rows": roughness_rows(pick["ROUGHNESS"], pick["CLAMPS"], pick["SAMPLES"], args.repeats),
              "cosine_rows": cosine_rows(COSINE_CLAMPS), "size": SIZE, "machine": machine(), **run_info()}
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
