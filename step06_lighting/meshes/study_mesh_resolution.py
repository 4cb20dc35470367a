"""The mesh-resolution study: ``python -m step06_lighting.meshes.study_mesh_resolution --out DIR [--quick]
[--backends opengl webgpu]``.

``uv_sphere(radius, segments, rings)`` approximates a sphere with ``2 · segments · (rings - 1)`` triangles. How
many does a sphere need, and what do they cost?

* the picture: the unit sphere at the origin seen from (0, 0, 3.2) with a 45° field of view at ``--size``
  (default 320×240), shaded with the step's Blinn-Phong (reference ``shading``; albedo (0.8, 0.5, 0.3),
  specular 0.5, shininess 32) under one directional light and an ambient light, on a black background;
* the reference: the exact sphere, ray-traced in float64 numpy (one ray per pixel centre) and shaded with the
  same formula, encoded to 8-bit sRGB like the framebuffer;
* the errors: the **silhouette** error, the pixels whose coverage differs from the exact sphere's divided by the
  outline's length (2πr pixels) — the mean distance between the two outlines in pixels (an inscribed polygon
  with ``segments`` sides is up to ``r (1 - cos(π / segments))`` inside); and the **shading** error, the mean
  absolute 8-bit channel difference over the pixels inside both outlines (2 pixels in from the edge);
* the time: the median over ``--repeats`` runs of the mean frame time of ``--frames`` frames of a grid of
  ``--instances`` such spheres (one instanced draw), each frame waited for with a one-pixel read-back.

Writes ``step06_study_mesh_resolution.json``, ``.md`` (the table) and ``.png`` (error against frame time) to
``--out``. Runs headless (llvmpipe/lavapipe here) and prints progress.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, frame_ms, groups, markdown_table, run_info, write_study

STEM = "step06_study_mesh_resolution"
SPHERES = ((6, 3), (8, 4), (12, 6), (16, 8), (24, 12), (32, 16), (64, 32), (128, 64), (256, 128))
QUICK_SPHERES = ((8, 4), (16, 8), (64, 32))
EYE = np.array([0.0, 0.0, 3.2])
FOV = 45.0
ALBEDO = (0.8, 0.5, 0.3)
SPECULAR, SHININESS = 0.5, 32.0
LIGHT_TOWARDS = np.array([1.0, 1.5, 2.0])
AMBIENT = (0.15, 0.15, 0.15)
COVERED = 8  # a channel above this (0..255) is the sphere, not the black background


def _material():
    from gandalf_core.resources import MaterialData

    return MaterialData("phong", color=ALBEDO, params={"specular": SPECULAR, "shininess": SHININESS})


def sphere_scene(mesh, instances: int = 1):
    """``instances`` copies of ``mesh``: one at the origin (the picture), or a grid of them (the timing)."""
    from gandalf_core import ClearColorComponent, Scene, TransformComponent
    from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
    from gandalf_core.math import look_at_rotation
    from gandalf_tools import testing

    scene = Scene("mesh resolution")
    scene.assets.mesh("sphere", mesh)
    scene.assets.material("M", _material())
    side = math.ceil(math.sqrt(instances))
    scale = 1.0 / side
    for k in range(instances):
        x, y = (k % side - (side - 1) / 2) * 2 * scale, (k // side - (side - 1) / 2) * 2 * scale
        scene.create_entity(TransformComponent((x, y, 0.0), scale=scale), MeshComponent("sphere"),
                            MaterialComponent("M"))
    testing.add_lights(scene, [testing.directional_light(LIGHT_TOWARDS), testing.ambient_light(AMBIENT)])
    scene.create_entity(TransformComponent(EYE, quaternion=look_at_rotation(EYE, (0, 0, 0))),
                        CameraComponent(FOV, 0.1, 20.0))
    scene.create_entity(ClearColorComponent((0.0, 0.0, 0.0, 1.0)))
    return scene


def reference(size: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """(8-bit sRGB RGB (H, W, 3) of the exact sphere, its coverage mask (H, W)), float64 throughout."""
    from gandalf_core.resources import linear_to_srgb, srgb_to_linear
    from gandalf_tools.testing import sphere_hits

    hit, p, _ = sphere_hits(EYE, FOV, size)
    n = p / np.linalg.norm(p, axis=-1, keepdims=True)
    v = EYE - p
    v /= np.linalg.norm(v, axis=-1, keepdims=True)
    albedo = srgb_to_linear(np.asarray(ALBEDO, dtype=np.float64))
    to_light = LIGHT_TOWARDS / np.linalg.norm(LIGHT_TOWARDS)
    n_dot_l = np.maximum(n @ to_light, 0.0)[..., None]
    h = (to_light + v) / np.linalg.norm(to_light + v, axis=-1, keepdims=True)
    lobe = np.maximum(np.sum(n * h, axis=-1), 0.0)[..., None] ** SHININESS
    linear = srgb_to_linear(np.asarray(AMBIENT)) * albedo + (albedo + SPECULAR * lobe) * n_dot_l
    return np.round(linear_to_srgb(np.clip(linear, 0.0, 1.0)) * 255.0), hit


def errors(picture: np.ndarray, expected: np.ndarray, hit: np.ndarray) -> dict:
    """Silhouette error (mean outline distance, px) and shading error (mean 8-bit difference inside)."""
    from gandalf_tools.testing import inner

    covered = picture[..., :3].max(axis=2) > COVERED
    radius_px = math.sqrt(hit.sum() / math.pi)
    silhouette = float((covered ^ hit).sum() / (2.0 * math.pi * radius_px))
    inside = inner(covered & hit, 2)
    shading = float(np.abs(picture[..., :3].astype(np.float64) - expected)[inside].mean())
    return {"silhouette_px": silhouette, "shading_8bit": shading, "radius_px": radius_px}


def _app(backend: str, size: tuple[int, int]):
    from gandalf_core import Application
    from gandalf_core.app.cli import load_impl

    reference_impl = load_impl("step06_lighting")  # the solutions, or your exercises where there are none
    from ..shaders import register_shaders

    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    register_shaders(app, reference_impl)
    return app


def render(backend: str, mesh, size: tuple[int, int]) -> np.ndarray:
    with _app(backend, size) as app:
        app.add_scene(sphere_scene(mesh))
        app.run(frames=1)
        return app.capture()


def frame_time(backend: str, mesh, size: tuple[int, int], instances: int, frames: int, repeats: int) -> float:
    """Median over ``repeats`` of the mean milliseconds per frame (each frame waited for)."""
    with _app(backend, size) as app:
        app.add_scene(sphere_scene(mesh, instances))
        app.run(frames=3)
        app.renderer.read_pixel(0, 0)
        return frame_ms(app, frames, repeats)


def run_study(backends, spheres, size, instances: int, frames: int, repeats: int) -> dict:
    from gandalf_core.resources import uv_sphere

    expected, hit = reference(size)
    rows = []
    for backend in backends:
        for segments, rings in spheres:
            mesh = uv_sphere(1.0, segments, rings)
            row = {"backend": backend, "segments": segments, "rings": rings, "triangles": mesh.triangle_count,
                   **errors(render(backend, mesh, size), expected, hit),
                   "polygon_bound_px": math.sqrt(hit.sum() / math.pi) * (1.0 - math.cos(math.pi / segments)),
                   "frame_ms": frame_time(backend, mesh, size, instances, frames, repeats)}
            rows.append(row)
            print(f"[{backend}] {segments:3d}x{rings:<3d} {row['triangles']:6d} triangles: silhouette "
                  f"{row['silhouette_px']:.3f} px, shading {row['shading_8bit']:.2f}, {row['frame_ms']:.2f} ms/frame",
                  flush=True)
    return {"rows": rows, "size": list(size), "instances": instances,
            "reference": "float64 ray-traced exact sphere, same Blinn-Phong, 8-bit sRGB",
            "time": f"median of {repeats} runs of the mean of {frames} frames ({instances} spheres, 1-pixel read-back "
                    "per frame)",
            **run_info()}


def markdown(result: dict) -> str:
    return markdown_table(
        ["API", "segments × rings", "triangles", "silhouette error (px)", "r(1 − cos π/segments) (px)",
         "shading error (8-bit)", "frame time (ms)"],
        ([r["backend"], f"{r['segments']} × {r['rings']}", r["triangles"], f"{r['silhouette_px']:.3f}",
          f"{r['polygon_bound_px']:.3f}", f"{r['shading_8bit']:.2f}", f"{r['frame_ms']:.2f}"] for r in result["rows"]))


def plot(result: dict, path: Path) -> None:
    fig, axes = figure(1, 2, figsize=(10.0, 4.0))
    for backend, mine in groups(result["rows"], "backend"):
        for ax, key in zip(axes, ("silhouette_px", "shading_8bit")):
            ax.loglog([r["frame_ms"] for r in mine], [max(r[key], 1e-3) for r in mine], "o-", ms=4, label=backend)
            for r in mine:
                ax.annotate(str(r["triangles"]), (r["frame_ms"], max(r[key], 1e-3)), fontsize=6, xytext=(3, 3),
                            textcoords="offset points")
    for ax, ylabel in zip(axes, ("silhouette error (mean outline distance, px)",
                                 "shading error (mean 8-bit difference)")):
        label_axes(ax, f"frame time, {result['instances']} spheres (ms, median)", ylabel)
    fig.suptitle(f"uv_sphere resolution against the exact sphere ({result['size'][0]}×{result['size'][1]}; "
                 "labels: triangles)", fontsize=10)
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    parser = StudyParser("step06_lighting.meshes.study_mesh_resolution", __doc__, outputs=f"{STEM}.json/.md/.png",
                         quick="three spheres, fewer frames", size=((320, 240), (320, 240)), frames=(10, 5),
                         repeats=(5, 2))
    parser.add_argument("--instances", type=int, default=16, help="spheres in the timed grid (default 16)")
    args = parser.parse_args(argv)
    if args.instances < 1:
        parser.error("--instances must be at least 1")
    size, frames, repeats = args.size, args.frames, args.repeats
    spheres = QUICK_SPHERES if args.quick else SPHERES
    print(f"mesh-resolution study: {len(spheres)} spheres, {', '.join(args.backends)}, {size[0]}x{size[1]}",
          flush=True)
    result = run_study(args.backends, spheres, size, args.instances, frames, repeats)
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
