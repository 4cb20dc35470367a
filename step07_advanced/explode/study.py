"""The explode study: ``python -m step07_advanced.explode.study --out DIR [--backends opengl webgpu] [--quick]``.

What one exploded frame costs on each route, against the triangle count, and how exact each route is:

* routes: ``gl-geometry`` (OpenGL, the geometry shader), ``gl-pulling`` (OpenGL, vertex pulling from storage
  buffers — the WebGPU way in GLSL 4.30) and ``wgpu-pulling`` (WebGPU, vertex pulling);
* meshes: UV spheres of about 1k, 4k, 16k, 65k and 200k triangles (``--quick``: the first three), one sphere
  filling most of the view, exploding at time 1.5 s (85 % out) and moving every frame;
* time: the median over ``--repeats`` runs of the mean frame time of ``--frames`` frames, each frame waited
  for with a one-pixel read-back (so the GPU's work is inside the measurement); the first frames (compile,
  upload) are not timed;
* error, against the float64 numpy exploded triangles (``scene.exploded_triangles_np``): the largest distance in
  pixels between the rendered silhouette's bounding box and the box of the numpy triangles projected with the
  same camera (rasterisation alone gives up to ~0.5 px), and the PSNR of each route's picture to
  ``gl-geometry``'s (identical triangles give identical pictures up to rounding).

Writes ``explode_study.json``, ``explode_study.md`` (the table) and ``explode_study.png`` (frame time against
triangles, log-log) to ``--out``. Runs headless; prints progress.
"""

from __future__ import annotations

import platform
import statistics
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, frame_runs_ms, groups, markdown_table, write_study

#: (segments, rings) of the UV spheres: 960, 3968, 16128, 65024 and 199808 triangles.
SPHERES = ((32, 16), (64, 32), (128, 64), (256, 128), (448, 224))
ROUTES = {"gl-geometry": "opengl", "gl-pulling": "opengl", "wgpu-pulling": "webgpu"}
STUDY_TIME = 1.5
EYE = (0.0, 0.0, 5.0)
BACKGROUND_TOLERANCE = 3.0


def _scene(route_name: str, app, mesh, time_s: float, speed: float):
    """One exploding sphere at the origin, the demo's lights, the camera on +z."""
    from gandalf_core import Scene, TransformComponent

    from . import scene as explode

    route = (explode.GeometryShaderRoute() if route_name == "gl-geometry"
             else explode.PullingRoute(app.renderer, "explode_pulled"))
    scene = Scene(f"explode study {route_name}")
    explode.add_exploding_mesh(scene, route, "sphere", mesh, time=time_s, speed=speed,
                               transform=TransformComponent())
    explode.add_view(scene, eye=EYE, target=(0.0, 0.0, 0.0))
    scene.add_system(explode.ExplodeSystem(route))
    return scene


def _app(route_name: str, impl, size: tuple[int, int]):
    import importlib

    from gandalf_core import Application

    backend = ROUTES[route_name]
    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    variant = importlib.import_module(f"{__package__}.{backend}")
    variant.register_shaders(app, impl, pulling=True)
    return app


def measure(route_name: str, impl, mesh, size: tuple[int, int], frames: int, repeats: int) -> dict:
    """Frame time (median over repeats of the mean per frame) and the picture at STUDY_TIME."""
    from gandalf_core.render.render_system import RenderSystem

    from .scene import ExplodeSystem

    with _app(route_name, impl, size) as app:
        scene = _scene(route_name, app, mesh, STUDY_TIME, 0.0)
        app.add_scene(scene)
        app.run(frames=1)
        picture = app.capture()
        render = next(s for s in scene.systems if isinstance(s, RenderSystem))
        view, projection, _eye, _ = render.camera()
        # Animate from here on: every timed frame writes a new explode_time.
        for system in scene.systems:
            if isinstance(system, ExplodeSystem):
                for explode_component, _mesh, _material in system.components:
                    explode_component.speed = 1.0
        app.run(frames=3)  # warm-up
        app.renderer.read_pixel(0, 0)
        runs = frame_runs_ms(app, frames, repeats)
        return {"frame_ms": statistics.median(runs), "runs_ms": runs,
                "picture": picture, "view_projection": projection @ view}


def box_error(picture: np.ndarray, mesh, view_projection: np.ndarray) -> float:
    """Largest pixel distance between the rendered silhouette's box and the numpy exploded triangles' box."""
    from .scene import BACKGROUND, exploded_triangles_np

    background = np.round(np.asarray(BACKGROUND) * 255.0)
    mask = np.abs(picture[..., :3].astype(np.float64) - background).max(axis=2) > BACKGROUND_TOLERANCE
    ys, xs = np.nonzero(mask)
    got = np.array([xs.min(), ys.min(), xs.max() + 1.0, ys.max() + 1.0])
    corners = exploded_triangles_np(mesh, np.eye(4), STUDY_TIME).reshape(-1, 3)
    clip = np.c_[corners, np.ones(len(corners))] @ view_projection.T
    ndc = clip[:, :2] / clip[:, 3:4]
    height, width = picture.shape[:2]
    x = (ndc[:, 0] * 0.5 + 0.5) * width
    y = (0.5 - ndc[:, 1] * 0.5) * height
    expected = np.array([x.min(), y.min(), x.max(), y.max()])
    return float(np.abs(got - expected).max())


def run_study(routes: list[str], spheres, size: tuple[int, int], frames: int, repeats: int) -> list[dict]:
    from gandalf_core.app.cli import load_impl
    from gandalf_core.resources import uv_sphere
    from gandalf_tools.testing import psnr

    reference_impl = load_impl("step07_advanced")  # the solutions, or your exercises where there are none

    rows = []
    for segments, rings in spheres:
        mesh = uv_sphere(1.0, segments, rings)
        pictures = {}
        for route in routes:
            print(f"  {route:13s} {mesh.triangle_count:7d} triangles ...", end="", flush=True)
            result = measure(route, reference_impl, mesh, size, frames, repeats)
            pictures[route] = result["picture"]
            row = {"route": route, "triangles": mesh.triangle_count, "frame_ms": result["frame_ms"],
                   "runs_ms": result["runs_ms"], "box_error_px": box_error(result["picture"], mesh,
                                                                           result["view_projection"])}
            reference = pictures.get("gl-geometry")
            row["psnr_to_gl_geometry_db"] = (None if reference is None or route == "gl-geometry"
                                             else _finite(psnr(result["picture"], reference)))
            rows.append(row)
            print(f" {row['frame_ms']:8.2f} ms/frame, box error {row['box_error_px']:.2f} px", flush=True)
    return rows


def _finite(value: float) -> float | str:
    return value if np.isfinite(value) else "inf"


def format_table(rows: list[dict]) -> str:
    def psnr(p: float | str | None) -> str:
        return "—" if p is None else (p if isinstance(p, str) else f"{p:.1f}")

    return markdown_table(
        ["route", "triangles", "frame time (ms, median)", "silhouette box error (px)", "PSNR to gl-geometry (dB)"],
        ([r["route"], r["triangles"], f"{r['frame_ms']:.2f}", f"{r['box_error_px']:.2f}",
          psnr(r["psnr_to_gl_geometry_db"])] for r in rows))


def plot(rows: list[dict], path: Path, title: str) -> Path:
    fig, ax = figure(figsize=(6.4, 4.2))
    for route, mine in groups(rows, "route"):
        ax.loglog([r["triangles"] for r in mine], [r["frame_ms"] for r in mine], "o-", label=route)
    label_axes(ax, "triangles", "frame time (ms, median)", title, legend=None)
    ax.legend()
    return save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    args = StudyParser("step07_advanced.explode.study", __doc__, outputs="the JSON, table and plot",
                       quick="three sphere sizes, fewer frames", size=((640, 480), (640, 480)), frames=(20, 8),
                       repeats=(5, 5)).parse_args(argv)
    frames, size = args.frames, args.size
    routes = [r for r, backend in ROUTES.items() if backend in args.backends]
    spheres = SPHERES[:3] if args.quick else SPHERES
    print(f"explode study: routes {', '.join(routes)}; {frames} frames x {args.repeats} runs at {size[0]}x{size[1]}",
          flush=True)
    rows = run_study(routes, spheres, size, frames, args.repeats)
    meta = {"machine": platform.node(), "python": platform.python_version(), "size": list(size), "frames": frames,
            "repeats": args.repeats, "study_time_s": STUDY_TIME}
    write_study(args.out, "explode_study", {"meta": meta, "rows": rows}, format_table(rows),
                lambda result, path: plot(result["rows"], path, f"Exploding spheres, {size[0]}x{size[1]}"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
