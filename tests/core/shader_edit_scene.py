"""A scene for the shader-editing tests: one cube filling the middle of the frame, drawn with a shader whose colour
comes from an ``#include``d file (``tint.glsl`` / ``tint.wgsl``), written into a folder so that a test can edit it.

The material's colour is white, so the middle pixel shows the tint itself, sRGB-encoded by the target: a tint of
(1, 0.5, 0.25) reads (255, 188, 137), the fixed tint (0.25, 1, 0.5) reads (137, 255, 188). The two differ by at
least 67 levels in every channel that changes; the encoding rounds to within 1 level, the tolerance used.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from gandalf_core import Application, ClearColorComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, cube
from gandalf_core.resources.texture_data import linear_to_srgb

SHADER = "tinted"
MATERIAL = "M_tinted"
#: The tint the files hold at first, and the one a fix writes.
FIRST, FIXED = (1.0, 0.5, 0.25), (0.25, 1.0, 0.5)

GLSL_VERT = """#version 330 core
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
void main() { gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0); }
"""
GLSL_FRAG = """#version 330 core
#include "material.glsl"
#include "tint.glsl"
out vec4 f_color;
void main() { f_color = vec4(tint(material.color.rgb), 1.0); }
"""
WGSL = """#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"
#include "tint.wgsl"
@vertex fn vs_main(@location(0) position: vec3<f32>, inst: Instance) -> @builtin(position) vec4<f32> {
    return frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> {
    return vec4<f32>(tint(material.color.rgb), 1.0);
}
"""


def tint_text(backend: str, rgb: tuple[float, float, float], broken: bool = False) -> str:
    """The included file: ``tint(base)`` is ``base * rgb``; ``broken`` puts an undeclared name on its line 3."""
    values = ", ".join(f"{c:.2f}" for c in rgb)
    tail = " + nope" if broken else ""
    if backend == "opengl":
        return f"// the colour the cube shows\nvec3 tint(vec3 base) {{\n    return base * vec3({values}){tail};\n}}\n"
    return (f"// the colour the cube shows\nfn tint(base: vec3<f32>) -> vec3<f32> {{\n"
            f"    return base * vec3<f32>({values}){tail};\n}}\n")


def write_shader(folder: Path, backend: str) -> dict[str, Path]:
    """The shader's files in ``folder``: its stage files and ``tint`` (the include)."""
    folder.mkdir(parents=True, exist_ok=True)
    if backend == "opengl":
        files = {"vert": folder / "tinted.vert", "frag": folder / "tinted.frag", "tint": folder / "tint.glsl"}
        files["vert"].write_text(GLSL_VERT)
        files["frag"].write_text(GLSL_FRAG)
    else:
        files = {"wgsl": folder / "tinted.wgsl", "tint": folder / "tint.wgsl"}
        files["wgsl"].write_text(WGSL)
    files["tint"].write_text(tint_text(backend, FIRST))
    return files


def build(app: Application, files: dict[str, Path], material=None) -> None:
    """Build the shader from its files in ``app``'s renderer."""
    shaders = app.renderer.shaders
    if app.renderer.backend == "opengl":
        shaders.build(SHADER, files["vert"], files["frag"], material=material)
    else:
        shaders.build(SHADER, files["wgsl"], material=material)


def tinted_app(backend: str, folder: Path, width: int, height: int) -> tuple[Application, dict[str, Path]]:
    """A headless app (60 Hz fixed step) showing the tinted scene, its shader built from files written in ``folder``."""
    app = Application(backend, width, height, headless=True, fixed_dt=1 / 60)
    files = write_shader(folder, backend)
    build(app, files)
    app.add_scene(tinted_scene())
    return app, files


def tinted_scene() -> Scene:
    scene = Scene("tinted")
    scene.assets.mesh("cube", cube())
    scene.assets.material(MATERIAL, MaterialData(SHADER, color=(1.0, 1.0, 1.0)))
    scene.create_entity(ClearColorComponent((0.0, 0.0, 0.0)))
    scene.create_entity(TransformComponent((0, 0, 0), scale=2.0), MeshComponent("cube"), MaterialComponent(MATERIAL))
    scene.create_entity(TransformComponent((0.0, 0.0, 5.0)), CameraComponent(50.0, 0.1, 100.0))
    return scene


def expected(rgb: tuple[float, float, float]) -> np.ndarray:
    """The sRGB bytes the target stores for linear ``rgb``."""
    return np.round(255.0 * linear_to_srgb(np.asarray(rgb, dtype=np.float64))).astype(int)


def middle(pixels: np.ndarray) -> np.ndarray:
    """The middle pixel's RGB of a ``(h, w, 4)`` picture."""
    h, w = pixels.shape[:2]
    return pixels[h // 2, w // 2, :3].astype(int)


def shows(pixels: np.ndarray, rgb: tuple[float, float, float]) -> bool:
    """Whether the middle pixel shows tint ``rgb`` (within the 1 level of rounding)."""
    return bool(np.abs(middle(pixels) - expected(rgb)).max() <= 1)
