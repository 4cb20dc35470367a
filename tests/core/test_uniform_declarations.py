"""Every uniform block is declared once, in Python (a :class:`~gandalf_core.resources.layout.BlockLayout`), and the
shaders get it as generated text: no shader file of the project lays out a uniform block, or a loose non-opaque
uniform, by hand.

A GLSL ``uniform`` outside a block is allowed only for opaque types (samplers and images: they take a texture
unit or an image unit, not bytes) and for the renderer's per-draw value ``u_first_instance`` (instance.glsl: where
the draw's rows start; WGSL's instance index includes it). ``var<uniform>`` in WGSL and ``uniform Name { ... }``
blocks in GLSL are written by :meth:`BlockLayout.glsl` / :meth:`BlockLayout.wgsl` and reach the shader as a
generated ``#include``.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from gandalf_core.render.opengl.libs import ENGINE_UNIFORMS
from gandalf_core.resources.blocks import ENGINE_SNIPPETS, material_snippets
from gandalf_core.resources.layout import BlockLayout, LayoutError
from step07_advanced.filter.shaders import PARAMS_INCLUDES as FILTER_INCLUDES
from step07_advanced.gpu_motion.motion import PARAMS_INCLUDES as MOTION_INCLUDES
from step07_advanced.pathtracer.shaders import PARAMS_INCLUDES as PATHTRACER_INCLUDES
from step07_advanced.showcase.shaders import SIM_INCLUDES
from step07_advanced.terrain.shaders import TESSELLATE_INCLUDES

REPO_ROOT = Path(__file__).resolve().parents[2]
SUFFIXES = (".frag", ".vert", ".geom", ".tesc", ".tese", ".comp", ".glsl", ".wgsl")
SKIPPED = {".venv", "site", "node_modules", ".git"}

#: A WGSL uniform variable; a GLSL uniform block (``uniform Name {``, with or without a layout qualifier).
WGSL_UNIFORM = re.compile(r"var\s*<\s*uniform\s*>")
GLSL_BLOCK = re.compile(r"\buniform\s+\w+\s*\{")
#: A GLSL uniform outside a block whose type is not opaque (a sampler or an image).
GLSL_LOOSE = re.compile(r"^[^/\n]*\buniform\s+(?!(?:[iu]?sampler|[iu]?image)\w*\b)\w+\s+\w+\s*(?:\[[^\]]*\])?\s*;",
                        re.M)


def _comments_removed(text: str) -> str:
    return re.sub(r"//[^\n]*", "", re.sub(r"/\*.*?\*/", "", text, flags=re.S))


def _shader_files() -> list[Path]:
    found = []
    for path in sorted(REPO_ROOT.rglob("*")):
        rel = path.relative_to(REPO_ROOT)
        if path.suffix in SUFFIXES and not SKIPPED.intersection(rel.parts) and ".snap" not in rel.parts:
            found.append(path)
    return found


def _by_hand(text: str) -> list[str]:
    code = _comments_removed(text)
    found = [m.group(0).strip() for pattern in (WGSL_UNIFORM, GLSL_BLOCK, GLSL_LOOSE) for m in pattern.finditer(code)]
    return [line for line in found if line.split()[-1].rstrip(";") not in ENGINE_UNIFORMS]


def test_the_project_has_shader_files_to_check():
    names = {p.name for p in _shader_files()}
    assert {"pathtrace.comp", "pathtrace.wgsl", "particles.comp", "tessellate.wgsl", "io.glsl"} <= names


def test_no_shader_file_declares_a_uniform_block_by_hand():
    found = {str(p.relative_to(REPO_ROOT)): hits for p in _shader_files() if (hits := _by_hand(p.read_text()))}
    assert not found, ("uniform blocks laid out by hand (declare a BlockLayout and include its generated text, "
                       f"see gandalf_core/resources/blocks.py): {found}")


def test_the_check_sees_what_it_forbids():
    assert _by_hand("struct P { a: f32 };\n@group(0) @binding(0) var<uniform> p: P;")
    assert _by_hand("layout(std140, binding = 4) uniform Params {\n    vec4 u_origin;\n};")
    assert _by_hand("uniform Sim { SimParams u_sim; };")
    assert _by_hand("uniform int u_radius;")
    assert _by_hand("uniform ivec2 u_direction;  // (1, 0)")
    assert not _by_hand("uniform sampler2D u_albedo;\nlayout(binding = 0) uniform sampler2D u_src;")
    assert not _by_hand("layout(rgba8, binding = 0) writeonly uniform image2D u_dst;")
    assert not _by_hand("// a uniform float in [0, 1)\n// var<uniform> in a comment")


def test_the_generated_includes_are_the_blocks_declarations():
    """The text the shaders include is what the layouts write, in both languages."""
    generated = {**ENGINE_SNIPPETS, **material_snippets(BlockLayout("Material", [("color", "vec4")])),
                 **PATHTRACER_INCLUDES, **TESSELLATE_INCLUDES, **SIM_INCLUDES, **FILTER_INCLUDES,
                 **MOTION_INCLUDES}
    for name, text in generated.items():
        assert _by_hand(text), f"{name}: generated text with no uniform block"
        assert name.endswith((".glsl", ".wgsl"))
    glsl = {n for n in generated if n.endswith(".glsl")}
    wgsl = {n for n in generated if n.endswith(".wgsl")}
    # Every generated block exists in both languages, except the terrain's compute pass (WebGPU only: OpenGL
    # tessellates in hardware).
    assert {n[:-5] for n in wgsl} - {n[:-5] for n in glsl} == {"tessellate_params"}


def test_a_block_written_with_a_binding_point_or_as_a_struct():
    layout = BlockLayout("Sim", [("gravity", "vec4"), ("dt", "float"), ("seed", "uint")])
    assert layout.glsl(None, binding=4).startswith("layout(std140, binding = 4) uniform Sim {\n    vec4 gravity;")
    text = layout.glsl("u_sim", binding=4, struct=True)
    assert text.startswith("struct Sim {\n    vec4 gravity;\n    float dt;\n    uint seed;\n};\n")
    assert text.endswith("layout(std140, binding = 4) uniform SimBlock { Sim u_sim; };\n")
    with pytest.raises(LayoutError, match="block 'Sim': a block declared as a struct needs an instance name"):
        layout.glsl(struct=True)
