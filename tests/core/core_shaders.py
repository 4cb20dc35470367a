"""The core tests' own shaders (``tests/core/shaders/``) and one call that builds them for either API."""

from __future__ import annotations

from pathlib import Path
from typing import Any

SHADERS = Path(__file__).resolve().parent / "shaders"
#: name -> (GLSL vertex, GLSL fragment, WGSL) file names in SHADERS.
FILES = {
    "unlit": ("unlit.vert", "unlit.frag", "unlit.wgsl"),
    "lit": ("lit.vert", "lit.frag", "lit.wgsl"),
    "flat": ("unlit.vert", "flat.frag", "flat.wgsl"),
}


def build_shaders(shaders: Any, backend: str, *names: str) -> None:
    """Build each of ``names`` (keys of :data:`FILES`) in a renderer's shader library ``shaders`` for ``backend``:
    GLSL has a file per stage, WGSL one module with both."""
    for name in names:
        vert, frag, wgsl = FILES[name]
        if backend == "opengl":
            shaders.build(name, SHADERS / vert, SHADERS / frag)
        else:
            shaders.build(name, SHADERS / wgsl)
