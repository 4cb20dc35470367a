"""The core tests' own shaders (``tests/core/shaders/``), one call that builds them for either API, and a scene's
picture drawn with them."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from gandalf_core import Application, Scene

SHADERS = Path(__file__).resolve().parent / "shaders"
#: name -> (GLSL vertex, GLSL fragment, WGSL) file names in SHADERS.
FILES = {
    "unlit": ("unlit.vert", "unlit.frag", "unlit.wgsl"),
    "lit": ("lit.vert", "lit.frag", "lit.wgsl"),
    "flat": ("unlit.vert", "flat.frag", "flat.wgsl"),
}

#: A probe shader per API with a colour, a vec4 'tint' and a mat4 'm' (the same values in GLSL uniforms and WGSL):
#: it draws color.rgb * tint.rgb + (0, 0, m[1][0]) at the material's alpha. Its Material block, declared once:
FLAT_MATERIAL = [("color", "vec4"), ("tint", "vec4"), ("m", "mat4")]
FLAT_WGSL = """
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"
@vertex fn vs_main(@location(0) position: vec3<f32>, inst: Instance) -> @builtin(position) vec4<f32> {
    return frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> {
    return vec4<f32>(material.color.rgb * material.tint.rgb + vec3<f32>(0.0, 0.0, material.m[1].x),
                     material.color.a);
}
"""
FLAT_VERT = """#version 330 core
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
void main() { gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0); }
"""
FLAT_FRAG = """#version 330 core
#include "material.glsl"
out vec4 f_color;
void main() {
    f_color = vec4(material.color.rgb * material.tint.rgb + vec3(0.0, 0.0, material.m[1].x), material.color.a);
}
"""


def build_shaders(shaders: Any, backend: str, *names: str) -> None:
    """Build each of ``names`` (keys of :data:`FILES`) in a renderer's shader library ``shaders`` for ``backend``:
    GLSL has a file per stage, WGSL one module with both."""
    for name in names:
        vert, frag, wgsl = FILES[name]
        if backend == "opengl":
            shaders.build(name, SHADERS / vert, SHADERS / frag)
        else:
            shaders.build(name, SHADERS / wgsl)


def render_scene(backend: str, scene: Scene, size: tuple[int, int] = (96, 72),
                 shaders: tuple[str, ...] = ("unlit", "lit"),
                 frames: int = 2) -> np.ndarray:
    """``scene``'s picture after ``frames`` frames of a headless ``backend`` app of ``size`` with ``shaders`` built."""
    with Application(backend, *size, headless=True, fixed_dt=1 / 60) as app:
        build_shaders(app.renderer.shaders, backend, *shaders)
        app.add_scene(scene)
        app.run(frames=frames)
        return app.capture()
