"""A skybox from six large images: peak memory (RSS) and time to the first frame, per API.

Each configuration runs in a fresh Python process (so ``ru_maxrss`` is its own): it writes (once, cached in
``--cache``) six ``SIZE``² PNG faces, then loads them with ``CubeTextureData.from_files``, builds a headless
``Application`` with a camera and one cube, and renders the first frame with a one-pixel read-back. It prints
one JSON line per API: ``load_s`` (decode the PNGs), ``first_frame_s`` (upload, mip levels, first draw),
``peak_rss_mb``, ``rss_before_mb`` (after start-up, before the images) and ``rss_loaded_mb`` (peak once
the images are decoded).

    python benchmarks/bench_skybox.py                     # both APIs, 2048² faces, 1280x720
    python benchmarks/bench_skybox.py --size 512 --backends opengl
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

import bench_common
from bench_common import HERE, ROOT, rss_mb, run_child, sky_files


def child(cfg: dict[str, Any]) -> dict[str, Any]:
    import numpy as np

    from gandalf_core import Application, Scene, TransformComponent
    from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent, SkyboxComponent
    from gandalf_core.resources import CubeTextureData, MaterialData, primitives

    paths = [Path(p) for p in cfg["faces"]]
    app = Application(cfg["backend"], *cfg["window"], headless=True, fixed_dt=1 / 60)
    if cfg["backend"] == "opengl":
        app.renderer.shaders.build("lit", HERE / "shaders" / "lit.vert", HERE / "shaders" / "lit.frag")
    else:
        app.renderer.shaders.build("lit", HERE / "shaders" / "lit.wgsl")
    cube, lit = primitives.cube(), MaterialData("lit", color=(0.8, 0.5, 0.3))
    warm = Scene("warm-up")  # the renderer's own start-up (pipelines, targets), before the sky
    warm.assets.mesh("cube", cube)
    warm.assets.material("lit", lit)
    warm.create_entity(TransformComponent((0, 0, 3)), CameraComponent(60.0, 0.1, 100.0))
    warm.create_entity(TransformComponent((0, 0, 0)), MeshComponent("cube"), MaterialComponent("lit"))
    app.add_scene(warm)
    app.step()
    app.renderer.read_pixel(0, 0)
    before = rss_mb()
    t0 = time.perf_counter()
    sky = CubeTextureData.from_files(paths, name="sky")
    t1 = time.perf_counter()
    loaded = rss_mb()
    scene = Scene("sky")
    scene.assets.texture("sky", sky)
    del sky
    scene.assets.mesh("cube", cube)
    scene.assets.material("lit", lit)
    scene.create_entity(TransformComponent((0, 0, 3)), CameraComponent(60.0, 0.1, 100.0))
    scene.create_entity(SkyboxComponent("sky"))
    scene.create_entity(TransformComponent((0, 0, 0)), MeshComponent("cube"), MaterialComponent("lit"))
    app.add_scene(scene)
    app.switch_scene(scene)
    t2 = time.perf_counter()
    app.step()
    pixel = app.renderer.read_pixel(app.renderer.width // 2, 5)
    t3 = time.perf_counter()
    frames = []
    for _ in range(cfg["frames"]):
        a = time.perf_counter()
        app.step()
        app.renderer.read_pixel(app.renderer.width // 2, 5)
        frames.append(time.perf_counter() - a)
    record = {
        "bench": "gandalf-skybox", "backend": cfg["backend"], "face_size": cfg["size"],
        "window": cfg["window"], "load_s": round(t1 - t0, 3), "first_frame_s": round(t3 - t2, 3),
        "frame_ms_median": round(float(np.median(frames)) * 1e3, 2) if frames else None,
        "rss_before_mb": before, "rss_loaded_mb": loaded, "peak_rss_mb": rss_mb(),
        "sky_pixel": [int(v) for v in np.ravel(pixel)[:3]],
    }
    app.close()
    return record


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--backends", default="opengl,webgpu", help="comma list of opengl, webgpu")
    parser.add_argument("--size", type=int, default=2048, help="face edge in texels (default 2048)")
    parser.add_argument("--window", default="1280x720", help="WIDTHxHEIGHT of the frame (default 1280x720)")
    parser.add_argument("--frames", type=int, default=10, help="frames timed after the first (default 10)")
    parser.add_argument("--cache", default="/tmp/gandalf_bench_sky", help="folder for the generated PNG faces")
    args = bench_common.parse_or_answer(parser, argv, child)
    if args is None:  # a child: it printed its record
        return 0
    width, height = (int(v) for v in args.window.lower().split("x"))
    print(f"# writing/reading six {args.size}² faces in {args.cache}", file=sys.stderr, flush=True)
    faces = [str(p) for p in sky_files(Path(args.cache), args.size)]
    failures = 0
    for backend in [b.strip() for b in args.backends.split(",") if b.strip()]:
        print(f"# {backend} ...", file=sys.stderr, flush=True)
        cfg = {"backend": backend, "faces": faces, "size": args.size, "window": [width, height],
               "frames": args.frames}
        if run_child(__file__, cfg, {"bench": "gandalf-skybox", "backend": backend}) is None:
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    raise SystemExit(main())
