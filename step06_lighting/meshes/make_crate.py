"""Writes the step's textured model: a wooden crate as a Wavefront OBJ file and its texture as a PNG.

``models/crate.obj`` is the engine's cube of edge 0.7 standing on y = 0: 24 vertices (four per face, so each face
has its own normal and its own texture coordinates from 0 to 1), 12 triangles, readable in any text editor.
``models/crate.png`` (128² texels, sRGB) is the wood every face shows: planks, a darker frame and a diagonal brace.
The scene loads both as a model artist would hand them over (``load_mesh``, ``TextureData``) and draws them with the
textured Blinn-Phong shader. ``python -m step06_lighting.meshes.make_crate`` writes them again.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from gandalf_core.resources import cube

MODELS = Path(__file__).resolve().parents[1] / "models"
CRATE_OBJ = MODELS / "crate.obj"
CRATE_PNG = MODELS / "crate.png"
EDGE = 0.7
TEXELS = 128

def crate_obj(edge: float = EDGE) -> str:
    """The crate's OBJ text: the engine's ``cube(edge)`` (four vertices a face, each face the whole texture) lifted
    to stand on y = 0, as positions (``v``), texture coordinates (``vt``: v up, as OBJ has them; the engine's are
    top-row-first), normals (``vn``) and counter-clockwise triangles (``f v/vt/vn``, counted from 1)."""
    mesh = cube(edge)
    lines = [f"# A wooden crate: a cube of edge {edge:g} standing on y = 0 (make_crate.py)", "mtllib crate.mtl"]
    lines += ["v " + " ".join(f"{c:.4f}" for c in (x, y + edge / 2, z)) for x, y, z in mesh.positions]
    lines += [f"vt {u:g} {1.0 - v:g}" for u, v in mesh.uvs]
    lines += ["vn " + " ".join(f"{c:g}" for c in n) for n in mesh.normals]
    lines.append("usemtl crate")
    for a, b, c in np.asarray(mesh.indices).reshape(-1, 3) + 1:
        lines.append(f"f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}")
    return "\n".join(lines) + "\n"


def crate_texels(size: int = TEXELS) -> np.ndarray:
    """The wood, (size, size, 4) uint8 sRGB, top row first: planks with a grain, a frame and a diagonal brace."""
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size
    plank = np.floor(y * 4)
    grain = 0.06 * np.sin(2 * np.pi * (x * 3.0 + 0.7 * plank) + 4.0 * np.sin(7.0 * y)) + 0.05 * (plank % 2)
    gap = np.abs(y * 4 - np.round(y * 4)) < 0.035  # the dark seams between planks
    shade = 0.78 + grain - 0.35 * gap
    frame = (np.minimum.reduce([x, y, 1 - x, 1 - y]) < 0.11) | (np.abs(x - y) < 0.075)
    shade = np.where(frame, 0.58 + 0.5 * grain, shade)
    edge = (np.minimum.reduce([x, y, 1 - x, 1 - y]) < 0.015)
    shade = np.where(edge, 0.3, shade)
    wood = np.array([0.80, 0.56, 0.32])
    rgb = np.clip(shade[..., None] * wood, 0.0, 1.0)
    return np.dstack([np.round(rgb * 255), np.full((size, size), 255)]).astype(np.uint8)


def write_crate(obj_path: Path = CRATE_OBJ, png_path: Path = CRATE_PNG) -> tuple[Path, Path, Path]:
    """Write the OBJ, its one-line material library (naming the texture) and the PNG; returns their paths."""
    from PIL import Image

    obj_path.parent.mkdir(parents=True, exist_ok=True)
    obj_path.write_text(crate_obj())
    mtl_path = obj_path.with_name("crate.mtl")
    mtl_path.write_text(f"newmtl crate\nKd 1 1 1\nmap_Kd {png_path.name}\n")
    Image.fromarray(crate_texels()).save(png_path, optimize=True)
    return obj_path, mtl_path, png_path


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m step06_lighting.meshes.make_crate",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=MODELS, help=f"the folder to write into (default {MODELS})")
    args = parser.parse_args(argv)
    for path in write_crate(args.out / CRATE_OBJ.name, args.out / CRATE_PNG.name):
        print(f"wrote {path} ({path.stat().st_size} bytes)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
