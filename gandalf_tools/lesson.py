"""The frame the plain-API lesson files (``stepNN_*/*_gl.py`` and ``*_wgpu.py``) share around their API calls.

A lesson file makes every moderngl or wgpu call itself, up to and including the read-back of its frame; this
module only turns the bytes it read into a picture (:func:`image`: OpenGL's rows start at the bottom, WebGPU's at
the top) and gives every lesson the same command line (:func:`main`: ``--out FILE.png --size WIDTHxHEIGHT``).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

import numpy as np


def image(pixels: bytes, width: int, height: int, *, bottom_up: bool) -> np.ndarray:
    """The read-back RGBA8 ``pixels`` as a (height, width, 4) uint8 array, top row first.

    ``bottom_up``: the rows start at the bottom (OpenGL's ``fbo.read``), not at the top (WebGPU's ``read_texture``).
    """
    rows = np.frombuffer(pixels, dtype=np.uint8).reshape(height, width, 4)
    return (rows[::-1] if bottom_up else rows).copy()


def main(render: Callable[[int, int], np.ndarray], doc: str, out: str, size: str = "640x480",
         argv: list[str] | None = None) -> int:
    """A lesson's command line: render ``WIDTHxHEIGHT`` with ``render(width, height)`` and write the PNG ``--out``.

    ``doc`` is the lesson's module docstring (its first line is the help's description).
    """
    from PIL import Image

    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--out", default=out, help=f"PNG file to write (default: {out})")
    parser.add_argument("--size", default=size, help=f"WIDTHxHEIGHT (default: {size})")
    args = parser.parse_args(argv)
    width, height = (int(v) for v in args.size.lower().split("x"))
    Image.fromarray(render(width, height)).save(args.out)
    print(f"wrote {args.out}")
    return 0
