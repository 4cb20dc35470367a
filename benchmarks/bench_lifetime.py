"""GPU objects and memory over 1,000 create/destroy cycles of an entity with a new mesh and a new texture.

Each cycle adds a mesh, a texture and a material under new names to the scene's assets, creates an entity that
draws them, runs a frame (which builds the GPU objects), destroys the entity, removes the three assets and runs a
frame (which must release them). Printed at cycles 0, 250, 500, 750 and 1000, per backend, as JSON lines:

* ``engine_objects``: the GPU objects the renderer holds (``renderer.live_objects()``: library entries, vertex
  arrays / pipelines);
* ``api_objects``: the API's own objects alive in Python (WebGPU: ``wgpu.diagnostics.object_counts``' total;
  OpenGL: moderngl objects found by the garbage collector), and WebGPU's ``resource_mem`` in bytes;
* ``rss_mib``: the process's resident memory (``VmRSS``), after a full garbage collection, and
  ``rss_trimmed_mib`` the same after ``malloc_trim(0)`` (what the C allocator keeps free but mapped drops out).

Flat means: the same counts at 250, 500, 750 and 1000 (cycle 0 is before the first cycle built the pipeline a
mesh needs), and RSS no higher than in the control run: the same frames with one entity that stays, nothing created
or destroyed (``"mode": "frames-only"``). On llvmpipe the frames alone take RSS from ~100 to 135-155 MiB over the
first ~500 frames and then wander in that band (the driver threads' heaps; ``malloc_trim`` gives back up to ~17 MiB
of it at times), with or without the cycles.

    python benchmarks/bench_lifetime.py                  # both backends, 1,000 cycles
    python benchmarks/bench_lifetime.py --backends webgpu --cycles 200 --every 50
"""

from __future__ import annotations

import argparse
import gc
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

from gandalf_core import Application, Scene, TransformComponent  # noqa: E402
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent  # noqa: E402
from gandalf_core.resources import MaterialData, TextureData, cube  # noqa: E402

SHADERS = ROOT / "tests" / "core" / "shaders"


def rss_mib() -> float:
    """Resident memory of this process in MiB (Linux /proc; 0 elsewhere)."""
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    except OSError:
        pass
    return 0.0


def rss_after_trim_mib() -> float:
    """RSS after glibc's ``malloc_trim(0)`` hands freed heap pages back to the system: memory that is free but kept
    by the allocator (fragmentation, not a leak) drops out; 0 where there is no glibc."""
    try:
        import ctypes

        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):
        return 0.0
    return rss_mib()


def api_objects(backend: str) -> dict:
    gc.collect()
    if backend == "webgpu":
        import wgpu

        counts = wgpu.diagnostics.object_counts.get_dict()
        return {"api_objects": counts["total"]["count"], "resource_mem": counts["total"].get("resource_mem", 0),
                "by_type": {k: v["count"] for k, v in counts.items() if k != "total" and v["count"]}}
    import moderngl

    kinds = (moderngl.Buffer, moderngl.Texture, moderngl.TextureCube, moderngl.VertexArray, moderngl.Program,
             moderngl.Sampler, moderngl.Framebuffer, moderngl.Renderbuffer)
    by_type: dict[str, int] = {}
    for obj in gc.get_objects():
        if isinstance(obj, kinds):
            by_type[type(obj).__name__] = by_type.get(type(obj).__name__, 0) + 1
    return {"api_objects": sum(by_type.values()), "by_type": by_type}


def make_app(backend: str) -> Application:
    app = Application(backend, 16, 12, headless=True, fixed_dt=1 / 60)
    if backend == "opengl":
        app.renderer.shaders.build("unlit", SHADERS / "unlit.vert", SHADERS / "unlit.frag")
    else:
        app.renderer.shaders.build("unlit", SHADERS / "unlit.wgsl")
    return app


def texture(i: int) -> TextureData:
    return TextureData(np.tile(np.array([i % 255, 40, 200, 255], np.uint8), (4, 4, 1)), mipmaps=False)


def run(backend: str, cycles: int, every: int, control: bool) -> None:
    """``control``: the same frames with one entity that stays (nothing created or destroyed), to tell the memory
    the frames themselves settle at (driver threads' heaps) from what the cycles would leave behind."""
    with make_app(backend) as app:
        scene = Scene("cycles")
        scene.create_entity(TransformComponent((0, 0, 3)), CameraComponent(60.0, 0.1, 10.0))
        if control:
            scene.assets.mesh("mesh", cube(1.0))
            scene.assets.texture("tex", texture(1))
            scene.assets.material("mat", MaterialData("unlit", ["tex"]))
            scene.create_entity(TransformComponent(), MeshComponent("mesh"), MaterialComponent("mat"))
        app.add_scene(scene)
        app.step()
        start = time.perf_counter()
        for i in range(cycles + 1):
            if i % every == 0:
                print(json.dumps({"bench": "lifetime", "backend": backend,
                                  "mode": "frames-only" if control else "cycles", "cycle": i,
                                  "engine_objects": app.renderer.live_objects(), **api_objects(backend),
                                  "rss_mib": round(rss_mib(), 2), "rss_trimmed_mib": round(rss_after_trim_mib(), 2),
                                  "s": round(time.perf_counter() - start, 2)}), flush=True)
            if i == cycles:
                break
            if control:
                app.step()
                app.step()
                continue
            assets = scene.assets
            assets.mesh(f"mesh{i}", cube(1.0 + i * 1e-3))
            assets.texture(f"tex{i}", texture(i))
            assets.material(f"mat{i}", MaterialData("unlit", [f"tex{i}"]))
            entity = scene.create_entity(TransformComponent(), MeshComponent(f"mesh{i}"), MaterialComponent(f"mat{i}"))
            app.step()  # builds the mesh, texture and material (and a vertex array / bind group)
            scene.destroy_entity(entity)
            assets.remove_material(f"mat{i}")
            assets.remove_mesh(f"mesh{i}")
            assets.remove_texture(f"tex{i}")
            app.step()  # the assets are gone: so must their GPU objects be


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--backends", default="opengl,webgpu")
    parser.add_argument("--cycles", type=int, default=1000)
    parser.add_argument("--every", type=int, default=250)
    parser.add_argument("--no-control", action="store_true", help="skip the frames-only control run")
    parser.add_argument("--one", nargs=2, metavar=("BACKEND", "MODE"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one:  # one run in this (fresh) process
        run(args.one[0], args.cycles, args.every, control=args.one[1] == "frames-only")
        return
    # Each run in a fresh interpreter: RSS starts from the same place, and one run's heaps do not hide another's.
    for backend in args.backends.split(","):
        for mode in ("cycles",) + (() if args.no_control else ("frames-only",)):
            subprocess.run([sys.executable, __file__, "--cycles", str(args.cycles), "--every", str(args.every),
                            "--one", backend, mode], check=True)


if __name__ == "__main__":
    main()
