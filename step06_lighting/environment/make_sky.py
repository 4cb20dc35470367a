"""Writes the environment's sky as six image files, one per cube face (``models/sky/px.png`` ... ``nz.png``).

A sky usually comes as six photographs or renders, one per face of a cube around the viewer, named after the axis
each face looks along: ``px`` (+X), ``nx`` (-X), ``py`` (+Y, up), ``ny``, ``pz``, ``nz``. The step's scene reads
them back with ``CubeTextureData.from_files`` in that order. This script makes them from the engine's procedural
daylight sky (``sky_cube``, 128 texels a face, sRGB), so the files are small and the picture is the same as the
procedural one: ``python -m step06_lighting.environment.make_sky`` writes them again.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from gandalf_core.resources import sky_cube

#: The face files in the order CubeTextureData.from_files takes them: +X, -X, +Y, -Y, +Z, -Z.
FACES = ("px", "nx", "py", "ny", "pz", "nz")
SKY_DIR = Path(__file__).resolve().parents[1] / "models" / "sky"
SKY_FILES = tuple(SKY_DIR / f"{face}.png" for face in FACES)
SIZE = 128


def write_sky(folder: Path = SKY_DIR, size: int = SIZE) -> list[Path]:
    """Write the six faces of ``sky_cube(size)`` into ``folder`` as PNG files; returns their paths."""
    from PIL import Image

    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for face, pixels in zip(FACES, sky_cube(size).faces, strict=True):
        path = folder / f"{face}.png"
        Image.fromarray(pixels).save(path, optimize=True)
        paths.append(path)
    return paths


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m step06_lighting.environment.make_sky",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=SKY_DIR, help=f"the folder to write into (default {SKY_DIR})")
    parser.add_argument("--size", type=int, default=SIZE, help=f"texels along a face's edge (default {SIZE})")
    args = parser.parse_args(argv)
    for path in write_sky(args.out, args.size):
        print(f"wrote {path} ({path.stat().st_size} bytes)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
