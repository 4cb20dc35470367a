"""The light-count study: ``python -m step06_lighting.lights.study_lights --out DIR [--quick]
[--backends opengl webgpu]``.

The lights block holds up to ``MAX_LIGHTS`` (64) point and directional lights, and every fragment loops over all of
them. What does each light cost, and how much of the picture do the weakest lights carry?

* the scene: a floor (a 12 m plane) with a 5 × 5 grid of Blinn-Phong spheres, seen from above at an angle, at
  ``--size`` (default 320×240), lit by 64 point lights (range 6 m, windowed inverse square) scattered 0.5–2 m
  above the floor with seeded random colours and intensities spread over three orders of magnitude
  (``0.003 · 1000^u``, u uniform), plus a dim ambient light;
* the knob: keep only the ``N`` strongest lights (by intensity), N = 1, 2, 4, 8, 16, 32, 64;
* the reference: the same scene with all 64 lights, rendered by the same API;
* the error: the mean and the 99th percentile of the absolute 8-bit channel difference to the reference, over
  the whole picture;
* the time: the median over ``--repeats`` runs of the mean frame time of ``--frames`` frames, each waited for
  with a one-pixel read-back.

Writes ``step06_study_lights.json``, ``.md`` (the table) and ``.png`` (frame time against light count, and the
error of dropping the weakest lights) to ``--out``. Runs headless and prints progress.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, frame_ms, groups, markdown_table, run_info, write_study

STEM = "step06_study_lights"
COUNTS = (0, 1, 2, 4, 8, 16, 32, 64)
QUICK_COUNTS = (1, 8, 64)
TOTAL = 64
EYE = np.array([0.0, 7.0, 9.0])


def light_set(total: int = TOTAL, seed: int = 11) -> list[dict]:
    """``total`` point lights (position, sRGB colour, intensity), strongest first."""
    rng = np.random.default_rng(seed)
    lights = [{"position": (float(rng.uniform(-5.5, 5.5)), float(rng.uniform(0.5, 2.0)), float(rng.uniform(-5.5, 5.5))),
               "color": tuple(float(c) for c in rng.uniform(0.4, 1.0, 3)),
               "intensity": float(0.003 * 1000.0 ** rng.uniform())} for _ in range(total)]
    return sorted(lights, key=lambda light: -light["intensity"])


def lights_scene(count: int, lights: list[dict]):
    """The floor and spheres lit by the ``count`` strongest of ``lights``."""
    from gandalf_core import ClearColorComponent, Scene, TransformComponent
    from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
    from gandalf_core.math import look_at_rotation
    from gandalf_core.resources import MaterialData, plane, uv_sphere

    scene = Scene(f"{count} lights")
    scene.assets.mesh("floor", plane(12.0, 8))
    scene.assets.mesh("sphere", uv_sphere(0.5, 32, 16))
    scene.assets.material("floor", MaterialData("phong", color=(0.6, 0.6, 0.6), params={"specular": 0.2,
                                                                                      "shininess": 16.0}))
    scene.assets.material("ball", MaterialData("phong", color=(0.8, 0.7, 0.6), params={"specular": 0.5,
                                                                                     "shininess": 48.0}))
    scene.create_entity(TransformComponent(), MeshComponent("floor"), MaterialComponent("floor"))
    for i in range(5):
        for j in range(5):
            scene.create_entity(TransformComponent((2.2 * (i - 2), 0.5, 2.2 * (j - 2))), MeshComponent("sphere"),
                                MaterialComponent("ball"))
    for light in lights[:count]:
        scene.create_entity(TransformComponent(light["position"]),
                            LightComponent("point", light["color"], light["intensity"], 6.0))
    scene.create_entity(TransformComponent(), LightComponent("ambient", (0.03, 0.03, 0.03)))
    scene.create_entity(TransformComponent(EYE, quaternion=look_at_rotation(EYE, (0, 0, 0))),
                        CameraComponent(55.0, 0.1, 50.0))
    scene.create_entity(ClearColorComponent((0.0, 0.0, 0.0, 1.0)))
    return scene


def measure(backend: str, count: int, lights: list[dict], size: tuple[int, int], frames: int,
            repeats: int) -> tuple[np.ndarray, float]:
    """(the picture, median ms per frame) of the scene with the ``count`` strongest lights."""
    from gandalf_core import Application
    from gandalf_core.app.cli import load_impl

    reference_impl = load_impl("step06_lighting")  # the solutions, or your exercises where there are none
    from ..shaders import register_shaders

    with Application(backend, *size, headless=True, fixed_dt=1 / 60) as app:
        register_shaders(app, reference_impl)
        app.add_scene(lights_scene(count, lights))
        app.run(frames=3)
        picture = app.capture()
        return picture, frame_ms(app, frames, repeats)


def picture_error(picture: np.ndarray, reference: np.ndarray) -> tuple[float, float]:
    """(mean, 99th percentile) absolute 8-bit channel difference."""
    diff = np.abs(picture[..., :3].astype(np.float64) - reference[..., :3].astype(np.float64))
    return float(diff.mean()), float(np.percentile(diff, 99))


def run_study(backends, counts, size, frames: int, repeats: int) -> dict:
    lights = light_set()
    rows = []
    for backend in backends:
        reference, _ = measure(backend, TOTAL, lights, size, 1, 1)
        for count in counts:
            picture, ms = measure(backend, count, lights, size, frames, repeats)
            mean, p99 = picture_error(picture, reference)
            kept = sum(light["intensity"] for light in lights[:count]) / sum(light["intensity"] for light in lights)
            rows.append({"backend": backend, "lights": count, "frame_ms": ms, "mean_error_8bit": mean,
                         "p99_error_8bit": p99, "intensity_kept": kept})
            print(f"[{backend}] {count:2d} lights: {ms:7.2f} ms/frame; dropping the other {TOTAL - count}: mean error "
                  f"{mean:.2f}, 99th percentile {p99:.1f} (8-bit), {100 * kept:.0f} % of the intensity kept",
                  flush=True)
    return {"rows": rows, "size": list(size), "total_lights": TOTAL,
            "reference": "the same scene with all 64 lights, same API",
            "time": f"median of {repeats} runs of the mean of {frames} frames (1-pixel read-back per frame)",
            **run_info()}


def markdown(result: dict) -> str:
    return markdown_table(
        ["API", "lights kept", "intensity kept", "frame time (ms)", "mean error (8-bit)", "99th percentile (8-bit)"],
        ([r["backend"], r["lights"], f"{100 * r['intensity_kept']:.0f} %", f"{r['frame_ms']:.2f}",
          f"{r['mean_error_8bit']:.2f}", f"{r['p99_error_8bit']:.1f}"] for r in result["rows"]))


def plot(result: dict, path: Path) -> None:
    fig, axes = figure(1, 2, figsize=(10.0, 4.0))
    for backend, mine in groups(result["rows"], "backend"):
        axes[0].plot([r["lights"] for r in mine], [r["frame_ms"] for r in mine], "o-", ms=4, label=backend)
        partial = [r for r in mine if r["lights"] < result["total_lights"]]  # all of them: no error to plot
        axes[1].semilogy([r["frame_ms"] for r in partial], [max(r["mean_error_8bit"], 1e-3) for r in partial], "o-",
                         ms=4, label=f"{backend} mean")
        axes[1].semilogy([r["frame_ms"] for r in partial], [max(r["p99_error_8bit"], 1e-3) for r in partial], "s--",
                         ms=3, label=f"{backend} 99th pct")
        for r in partial:
            axes[1].annotate(str(r["lights"]), (r["frame_ms"], max(r["mean_error_8bit"], 1e-3)), fontsize=6,
                             xytext=(3, 3), textcoords="offset points")
    label_axes(axes[0], "point lights", "frame time (ms, median)")
    label_axes(axes[1], "frame time (ms, median); labels: lights kept", "error against all 64 lights (8-bit)")
    fig.suptitle(f"Light count ({result['size'][0]}×{result['size'][1]}): cost, and the error of keeping only the "
                 "strongest", fontsize=10)
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    args = StudyParser("step06_lighting.lights.study_lights", __doc__, outputs=f"{STEM}.json/.md/.png",
                       quick=f"light counts {QUICK_COUNTS}, fewer frames", size=((320, 240), (320, 240)),
                       frames=(8, 3), repeats=(5, 2)).parse_args(argv)
    size, frames, repeats = args.size, args.frames, args.repeats
    counts = QUICK_COUNTS if args.quick else COUNTS
    print(f"light-count study: {counts} of {TOTAL} lights, {', '.join(args.backends)}, {size[0]}x{size[1]}",
          flush=True)
    result = run_study(args.backends, counts, size, frames, repeats)
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
