"""Writes the step's textured model: a wooden crate as a Wavefront OBJ file and its texture as a PNG.

``models/crate.obj`` is a cube of edge 0.7 standing on y = 0: 24 vertices (four per face, so each face has its own
normal and its own texture coordinates from 0 to 1), 12 triangles, readable in any text editor. ``models/crate.png``
(128² texels, sRGB) is the wood every face shows: planks, a darker frame and a diagonal brace. The scene loads both
as a model artist would hand them over (``load_mesh``, ``TextureData``) and draws them with the textured Blinn-Phong
shader. ``python -m step06_lighting.meshes.make_crate`` writes them again.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

MODELS = Path(__file__).resolve().parents[1] / "models"
CRATE_OBJ = MODELS / "crate.obj"
CRATE_PNG = MODELS / "crate.png"
EDGE = 0.7
TEXELS = 128

# Each face: its outward normal and the two axes its texture's u (left to right) and v (bottom to top) run along.
_FACES = (
    ((1, 0, 0), (0, 0, -1), (0, 1, 0)),
    ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    ((0, 1, 0), (1, 0, 0), (0, 0, -1)),
    ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
    ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
)


def crate_obj(edge: float = EDGE) -> str:
    """The crate's OBJ text: positions (``v``), texture coordinates (``vt``, v up as OBJ has it), normals (``vn``)
    and two counter-clockwise triangles per face (``f v/vt/vn``)."""
    h = edge / 2
    lines = [f"# A wooden crate: a cube of edge {edge:g} standing on y = 0 (make_crate.py)", "mtllib crate.mtl"]
    faces = []
    for k, (n, u, v) in enumerate(_FACES):
        n, u, v = (np.asarray(a, dtype=float) for a in (n, u, v))
        for du, dv in ((0, 0), (1, 0), (1, 1), (0, 1)):
            p = h * n + h * (2 * du - 1) * u + h * (2 * dv - 1) * v + (0.0, h, 0.0)
            lines.append("v " + " ".join(f"{c:.4f}" for c in p))
            lines.append(f"vt {du} {dv}")
        lines.append("vn " + " ".join(f"{c:g}" for c in n))
        a = 4 * k + 1
        faces += [f"f {a}/{a}/{k + 1} {a + 1}/{a + 1}/{k + 1} {a + 2}/{a + 2}/{k + 1}",
                  f"f {a}/{a}/{k + 1} {a + 2}/{a + 2}/{k + 1} {a + 3}/{a + 3}/{k + 1}"]
    return "\n".join(lines + ["usemtl crate"] + faces) + "\n"


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
