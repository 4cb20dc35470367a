"""Writes ``models/bunny.glb``, the step's small procedural bunny: ``python -m step06_lighting.meshes.make_bunny``.

Five parts (body, head, two ears, tail), each a deformed icosphere stored in its own local frame and placed by
its glTF node transform, so loading the file exercises multi-part scenes and node transforms. No normals or
UVs are needed in the file: :func:`gandalf_core.resources.mesh_loader.load_mesh` computes smooth normals.
The output is deterministic; it is committed, so the step never needs this script at run time.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

#: The step's model, shared by its concepts (and by step 07), in the step's top folder.
MODEL_PATH = Path(__file__).resolve().parents[1] / "models" / "bunny.glb"


def _part(subdivisions: int, radii: tuple[float, float, float], flatten_below: float | None = None):
    """An icosphere scaled to an ellipsoid; optionally squashed flat below a height (a base to sit on)."""
    import trimesh

    mesh = trimesh.creation.icosphere(subdivisions=subdivisions)
    v = np.asarray(mesh.vertices) * radii
    if flatten_below is not None:
        low = v[:, 1] < flatten_below
        v[low, 1] = flatten_below + 0.25 * (v[low, 1] - flatten_below)
    return trimesh.Trimesh(v.astype(np.float32), mesh.faces, process=False)


def _place(translation, rot_x: float = 0.0, rot_z: float = 0.0) -> np.ndarray:
    import trimesh.transformations as tf

    return (
        tf.translation_matrix(translation)
        @ tf.rotation_matrix(np.radians(rot_z), [0, 0, 1])
        @ tf.rotation_matrix(np.radians(rot_x), [1, 0, 0])
    )


def build_bunny():
    """The bunny as a trimesh Scene: it sits on y = 0, about 1.9 units tall, facing +Z."""
    import trimesh

    scene = trimesh.Scene()
    scene.add_geometry(_part(3, (0.62, 0.56, 0.78), flatten_below=-0.42), node_name="body", geom_name="body",
                       transform=_place((0.0, 0.455, -0.1)))
    scene.add_geometry(_part(3, (0.40, 0.36, 0.44)), node_name="head", geom_name="head",
                       transform=_place((0.0, 0.995, 0.5), rot_x=-12.0))
    ear = _part(2, (0.11, 0.40, 0.06))
    for side, name in ((-1.0, "ear_left"), (1.0, "ear_right")):
        scene.add_geometry(ear, node_name=name, geom_name=name,
                           transform=_place((0.15 * side, 1.485, 0.36), rot_x=-18.0, rot_z=-12.0 * side))
    scene.add_geometry(_part(1, (0.16, 0.16, 0.16)), node_name="tail", geom_name="tail",
                       transform=_place((0.0, 0.485, -0.88)))
    return scene


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m step06_lighting.meshes.make_bunny",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=MODEL_PATH, help=f"the GLB file to write (default {MODEL_PATH})")
    args = parser.parse_args(argv)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    build_bunny().export(args.out)
    print(f"wrote {args.out} ({args.out.stat().st_size} bytes)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
