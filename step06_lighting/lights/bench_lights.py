"""Frame time as lights and instanced entities grow, in both APIs: ``python -m step06_lighting.lights.bench_lights``.

Each case renders a grid of small Blinn-Phong spheres (one instanced draw call) lit by N point lights plus an
ambient light, offscreen at 320x240, and prints one JSON object per line: backend, lights, entities and the
mean milliseconds per frame (the last frame is read back, so the GPU work is included).
Options: ``--frames N`` (default 60), ``--backends opengl webgpu``, ``--size WxH``.
"""

from __future__ import annotations

import argparse
import json
import math
import time

from gandalf_core import Application, Scene, TransformComponent
from gandalf_core.app.cli import load_impl
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, uv_sphere

from ..shaders import register_shaders

# The reference solutions' shading, or your exercises' where there are no solutions/.
REFERENCE = load_impl("step06_lighting")

LIGHT_COUNTS = (0, 1, 4, 16, 64)
ENTITY_COUNTS = (1, 100, 1000, 10000)
_SPHERE = uv_sphere(0.4, 12, 6)


def bench_scene(lights: int, entities: int) -> Scene:
    """``entities`` spheres on a square grid in the XY plane, ``lights`` point lights on a ring in front."""
    scene = Scene(f"bench {lights}x{entities}")
    scene.assets.mesh("sphere", _SPHERE)
    scene.assets.material("M", MaterialData("phong", color=(0.7, 0.6, 0.5), params={"specular": 0.4,
                                                                                    "shininess": 32.0}))
    side = math.ceil(math.sqrt(entities))
    spacing = 20.0 / side
    for k in range(entities):
        x, y = (k % side - (side - 1) / 2) * spacing, (k // side - (side - 1) / 2) * spacing
        scene.create_entity(TransformComponent((x, y, 0.0), scale=spacing), MeshComponent("sphere"),
                            MaterialComponent("M"))
    for k in range(lights):
        a = 2.0 * math.pi * k / max(lights, 1)
        scene.create_entity(TransformComponent((8.0 * math.cos(a), 8.0 * math.sin(a), 4.0)),
                            LightComponent("point", (1.0, 0.9, 0.8), 4.0 / max(lights, 1), 30.0))
    scene.create_entity(TransformComponent(), LightComponent("ambient", (0.1, 0.1, 0.1)))
    scene.create_entity(TransformComponent((0.0, 0.0, 24.0)), CameraComponent(50.0, 0.5, 100.0))
    return scene


def measure(backend: str, lights: int, entities: int, frames: int, size: tuple[int, int]) -> float:
    """Mean milliseconds per frame after a few warm-up frames."""
    with Application(backend, *size, headless=True, fixed_dt=1 / 60) as app:
        register_shaders(app, REFERENCE)
        app.add_scene(bench_scene(lights, entities))
        app.run(frames=5)
        app.capture()
        start = time.perf_counter()
        app.run(frames=frames)
        app.capture()
        return (time.perf_counter() - start) * 1000.0 / frames


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--backends", nargs="*", default=["opengl", "webgpu"])
    parser.add_argument("--size", default="320x240")
    args = parser.parse_args(argv)
    size = tuple(int(v) for v in args.size.lower().split("x"))
    cases = [(n, 100) for n in LIGHT_COUNTS] + [(16, n) for n in ENTITY_COUNTS if n != 100]
    for backend in args.backends:
        for lights, entities in cases:
            ms = measure(backend, lights, entities, args.frames, size)
            row = {"backend": backend, "lights": lights, "entities": entities, "ms_per_frame": round(ms, 3)}
            print(json.dumps(row), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
