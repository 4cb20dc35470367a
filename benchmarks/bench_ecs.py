"""The engine's Python costs without a GPU: the teaching form of a system, creating entities, importing.

Prints one JSON line per measurement (medians of repeats in this run; CPU time next to wall time, since a shared
machine's wall time includes other jobs):

* ``teaching``: a per-entity rotate system in the teaching form (``on_update_entity`` with
  ``quat_from_axis_angle``, ``quat_mul`` and ``quat_normalize``), microseconds per entity per frame
  (target: <= 10);
* ``spawn-loop`` / ``spawn-bulk``: creating N entities with a Transform, a Mesh and a Material in a scene that
  already has a transform system and a render-like system, one ``create_entity`` call each or one
  ``Scene.create_entities`` call (target for 100k: <= 0.5 s);
* ``import``: ``import gandalf_core`` in a fresh interpreter (target: <= 150 ms), next to ``import numpy``
  alone (which it needs).

    python benchmarks/bench_ecs.py                 # 2,000 entities for the teaching form, 100k spawned
    python benchmarks/bench_ecs.py --quick         # small sizes, a few seconds
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


def teaching(n: int, frames: int) -> dict:
    from bench_rotate import RotateComponent, RotateEntitySystem

    from gandalf_core import Scene, TransformComponent

    scene = Scene("teaching")
    for i in range(n):
        scene.create_entity(TransformComponent((float(i), 0.0, 0.0)), RotateComponent((0.0, 1.0, 0.0), 30.0 + i % 7))
    scene.add_system(RotateEntitySystem(normalize=True))
    wall, cpu = [], []
    for _ in range(frames):
        a, c = time.perf_counter(), time.process_time()
        scene.update(1 / 60)
        wall.append(time.perf_counter() - a)
        cpu.append(time.process_time() - c)
    return {"bench": "ecs", "what": "teaching", "entities": n, "frames": frames,
            "us_per_entity_wall": round(statistics.median(wall) * 1e6 / n, 2),
            "us_per_entity_cpu": round(statistics.median(cpu) * 1e6 / n, 2)}


def spawn(n: int, bulk: bool) -> dict:
    import numpy as np

    from gandalf_core import Scene, System, TransformComponent, TransformSystem
    from gandalf_core.components import MaterialComponent, MeshComponent

    xyz = np.random.default_rng(0).normal(size=(n, 3))
    scene = Scene("spawn")
    scene.add_system(TransformSystem())
    scene.add_system(System([TransformComponent, MeshComponent, MaterialComponent]))
    a, c = time.perf_counter(), time.process_time()
    if bulk:
        scene.create_entities(n, TransformComponent.batch(translations=xyz), MeshComponent("model"),
                              MaterialComponent("lit"))
    else:
        for i in range(n):
            scene.create_entity(TransformComponent(xyz[i]), MeshComponent("model"), MaterialComponent("lit"))
    wall, cpu = time.perf_counter() - a, time.process_time() - c
    assert len(scene) == n
    return {"bench": "ecs", "what": "spawn-bulk" if bulk else "spawn-loop", "entities": n,
            "s_wall": round(wall, 3), "s_cpu": round(cpu, 3)}


def import_time(module: str, repeats: int) -> dict:
    code = (f"import time; w = time.perf_counter(); c = time.process_time(); import {module}; "
            "print(time.perf_counter() - w, time.process_time() - c)")
    wall, cpu = [], []
    for _ in range(repeats):
        out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True)
        w, c = (float(v) for v in out.stdout.split())
        wall.append(w)
        cpu.append(c)
    return {"bench": "ecs", "what": "import", "module": module, "repeats": repeats,
            "ms_wall_median": round(statistics.median(wall) * 1e3, 1), "ms_wall_min": round(min(wall) * 1e3, 1),
            "ms_cpu_median": round(statistics.median(cpu) * 1e3, 1), "ms_cpu_min": round(min(cpu) * 1e3, 1)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--teaching-entities", type=int, default=None, help="entities for the teaching form")
    parser.add_argument("--spawn", type=int, default=None, help="entities to create (default 100000)")
    parser.add_argument("--repeats", type=int, default=None, help="fresh interpreters per import (default 15)")
    parser.add_argument("--quick", action="store_true", help="small sizes: a few seconds")
    args = parser.parse_args(argv)
    n_teach = args.teaching_entities or (200 if args.quick else 2000)
    n_spawn = args.spawn or (10_000 if args.quick else 100_000)
    repeats = args.repeats or (3 if args.quick else 15)
    steps = [("teaching form", lambda: teaching(n_teach, 5 if args.quick else 9)),
             ("spawn, one by one", lambda: spawn(n_spawn, bulk=False)),
             ("spawn, bulk", lambda: spawn(n_spawn, bulk=True)),
             ("import numpy", lambda: import_time("numpy", repeats)),
             ("import gandalf_core", lambda: import_time("gandalf_core", repeats))]
    for k, (label, step) in enumerate(steps, 1):
        print(f"# [{k}/{len(steps)}] {label}", file=sys.stderr, flush=True)
        print(json.dumps(step()), flush=True)
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    raise SystemExit(main())
