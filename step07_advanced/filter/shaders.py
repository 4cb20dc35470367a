"""Where the filter's shader files live, and where the student's (or the reference) shader functions are.

The kernels include ``blur_kernel.*`` (exercise 1: the Gaussian weights) and ``convolve.*`` (exercise 2: one blur
pass) from the implementation package's folder, so ``--student`` runs the exercises and the default the solutions.
A kernel's output format is the token ``OUT_FORMAT`` in its text, replaced when it is built (WGSL and GLSL need
the storage format in the declaration): ``rgba32f`` / ``rgba32float`` for the intermediate image of the separable
and tiled passes, ``rgba8`` / ``rgba8unorm`` for the 8-bit result.
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path
from types import ModuleType

from gandalf_core.render.shader_files import load_shader
from gandalf_core.resources import ShaderSource
from gandalf_core.resources.layout import BlockLayout

SHADER_DIR = Path(__file__).resolve().parent / "shaders"
#: The display material's shader: the core's ready unlit material (colour times one texture), in both APIs.
DISPLAY_SHADER = "gandalf.unlit"
#: Output formats per API: the float intermediate and the 8-bit result.
FORMATS = {
    "opengl": {"float": "rgba32f", "unorm8": "rgba8"},
    "webgpu": {"float": "rgba32float", "unorm8": "rgba8unorm"},
}
#: Compiled program -> (kernel, output kind). Each is built on first use, so a compile error in one exercise file
#: does not stop the kernels that do not include it (the weight table alone, or the blur with given weights).
PROGRAMS = {
    "weights": ("weights", None),
    **{f"{kernel}_{kind}": (kernel, kind) for kernel in ("pass", "tiled") for kind in ("float", "unorm8")},
    "naive": ("naive", "unorm8"),
    "sobel": ("sobel", "unorm8"),
}
#: Kernel name -> file stem (``.comp`` in GLSL, ``.wgsl`` in WGSL).
KERNELS = {"weights": "weights", "pass": "blur_pass", "naive": "blur_2d", "tiled": "blur_tiled", "sobel": "sobel"}

# --8<-- [start:params]
#: A pass's parameters, declared once: both APIs pack them (:func:`pass_params`), and the kernels
#: ``#include "filter_params.glsl"`` / ``"filter_params.wgsl"``, written from this layout (GLSL names the members
#: ``u_direction`` and ``u_radius``).
PARAMS_LAYOUT = BlockLayout("Params", [
    ("direction", "ivec2"),  # (1, 0): horizontal pass, (0, 1): vertical pass
    ("radius", "int"),  # 0..MAX_RADIUS
    ("_pad", "int", 0),
])
#: GL binding point of the block (0 and 1 are the engine's Frame and Lights); WGSL: @group(0) @binding(0).
PARAMS_BINDING = 4
PARAMS_INCLUDES = {
    "filter_params.glsl": PARAMS_LAYOUT.glsl(None, {"direction": "u_direction", "radius": "u_radius",
                                                    "_pad": "u_pad"}, binding=PARAMS_BINDING),
    "filter_params.wgsl": PARAMS_LAYOUT.wgsl("params", 0, 0),
}
# --8<-- [end:params]


def pass_params(direction: tuple[int, int], radius: int) -> bytes:
    """The Params block of one pass."""
    return PARAMS_LAYOUT.pack({"direction": direction, "radius": radius})


#: Line numbers in compiler logs: GLSL drivers ("0:12(5): error ..."), naga ("wgsl:12:5").
_LINE = {
    "glsl": re.compile(r"^\s*(?:ERROR:\s*)?\d+[:(](\d+)\)?"),
    "wgsl": re.compile(r"(?:wgsl|<[^>]*>|\S+\.wgsl):(\d+):\d+"),
}


def impl_shader_dir(impl: ModuleType) -> Path:
    """The folder holding ``impl``'s ``blur_kernel`` and ``convolve`` shader files."""
    return Path(impl.__file__).resolve().parent


def kernel_source(backend: str, kernel: str, impl: ModuleType, out_format: str | None = None) -> ShaderSource:
    """A kernel's expanded source with the student's includes; ``OUT_FORMAT`` replaced by ``out_format``."""
    stem = KERNELS[kernel]
    if backend == "opengl":
        src = load_shader(SHADER_DIR / f"{stem}.comp", "compute", "glsl", [impl_shader_dir(impl)], PARAMS_INCLUDES)
    else:
        src = load_shader(SHADER_DIR / f"{stem}.wgsl", None, "wgsl", [impl_shader_dir(impl)], PARAMS_INCLUDES)
    if out_format is not None:
        # Same number of lines, so the line map (file:line in errors) still holds.
        src = dataclasses.replace(src, text=src.text.replace("OUT_FORMAT", out_format))
    return src


def explain_error(src: ShaderSource, message: str) -> str:
    """A compiler log as ``file:line: message`` lines of the original files (the includes resolved)."""
    pattern = _LINE[src.lang]
    out = [src.format_error(int(m.group(1)), text.strip()) for text in message.splitlines()
           if (m := pattern.search(text))]
    return "\n".join(out) if out else f"{src.filename}: {message.strip()}"
