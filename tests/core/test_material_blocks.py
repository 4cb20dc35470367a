"""A material's values are one ``Material`` block with the same bytes in both APIs (GLSL std140 = WGSL uniform),
and a material is checked against its shader when it is built.

The block is declared once in Python with its shader (``shaders.build(..., material=...)``) and written into
both languages (``#include "material.glsl"`` / ``"material.wgsl"``). Checked here: the bytes of the same material in
OpenGL and WebGPU are identical; the declared layout is the driver's own; no shader in the project declares the
block by hand; and each build
check (unknown parameter, missing field, wrong size, ``u_`` prefix, wrong texture kind, a varying the vertex stage
never writes) is an error naming the material or shader, the shader file and the field. No pictures here.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from core_shaders import build_shaders

from gandalf_core import Application
from gandalf_core.render.errors import ShaderCompileError
from gandalf_core.render.opengl.libs import ENGINE_UNIFORMS
from gandalf_core.render.shader_files import SNIPPETS_DIR
from gandalf_core.resources import MaterialData, ResourceError, ShaderSource, checkerboard, sky_cube
from gandalf_core.resources.blocks import material_layout, material_snippets
from gandalf_tools.tour import REPO_ROOT

GL_VERT = """#version 330 core
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
out vec3 v_world;
void main() {
    vec4 world = instance_model() * vec4(a_position, 1.0);
    v_world = world.xyz;
    gl_Position = u_projection * u_view * world;
}
"""
GL_FRAG = """#version 330 core
in vec3 v_world;
#include "material.glsl"
out vec4 f_color;
void main() { f_color = material.color * vec4(material.tint * material.gain + material.m[1], 1.0)
                        + vec4(material.offset, 0.0, 0.0) + vec4(v_world, 0.0) * 0.0; }
"""
WGSL = """#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"
struct VOut { @builtin(position) position: vec4<f32>, @location(0) world: vec3<f32> };
@vertex fn vs_main(@location(0) position: vec3<f32>, inst: Instance) -> VOut {
    let world = instance_model(inst) * vec4<f32>(position, 1.0);
    return VOut(frame.projection * frame.view * world, world.xyz);
}
@fragment fn fs_main(in: VOut) -> @location(0) vec4<f32> {
    return material.color * vec4<f32>(material.tint * material.gain + material.m[1], 1.0)
        + vec4<f32>(material.offset, 0.0, 0.0);
}
"""
MATERIAL = [("color", "vec4"), ("tint", "vec3"), ("gain", "float"), ("m", "mat3"), ("offset", "vec2"),
            ("_pad", "float", 0.0)]
PARAMS = {"tint": (0.25, 0.5, 0.75), "gain": 2.0, "m": np.arange(9.0), "offset": (0.125, -0.5)}


def build_shader(app: Application, name: str = "probe", frag: str = GL_FRAG, vert: str = GL_VERT,
                 wgsl: str = WGSL, material=MATERIAL):
    r, inc = app.renderer, [SNIPPETS_DIR]
    block = material_snippets(material_layout(material))
    if app.backend == "opengl":
        return r.shaders.build(name, ShaderSource.from_text(vert, "glsl", "vertex", filename="probe.vert",
                                                            include_dirs=inc, generated=block),
                               ShaderSource.from_text(frag, "glsl", "fragment", filename="probe.frag",
                                                      include_dirs=inc, generated=block), material=material)
    return r.shaders.build(name, ShaderSource.from_text(wgsl, "wgsl", filename="probe.wgsl", include_dirs=inc,
                                                        generated=block), material=material)


def check_refused(backend: str, match: str, **sources: str) -> None:
    """Building the probe shader from ``sources`` in ``backend`` raises a ShaderCompileError matching ``match``."""
    with Application(backend, 16, 12, headless=True) as app:
        with pytest.raises(ShaderCompileError, match=match):
            build_shader(app, **sources)


def test_the_same_material_is_the_same_bytes_in_both_apis():
    data = MaterialData("probe", color=(1.0, 0.5, 0.25, 0.75), params=PARAMS)
    got = {}
    for backend in ("opengl", "webgpu"):
        with Application(backend, 16, 12, headless=True) as app:
            build_shader(app)
            got[backend] = app.renderer.materials.build("M", data).block_bytes
    assert got["opengl"] == got["webgpu"], "the Material block's bytes differ between the APIs"
    floats = np.frombuffer(got["opengl"], np.float32)
    np.testing.assert_allclose(floats[4:8], (0.25, 0.5, 0.75, 2.0))  # vec3 then a float in its last 4 bytes
    np.testing.assert_allclose(floats[8:20].reshape(3, 4)[:, :3], np.arange(9.0).reshape(3, 3).T)  # columns
    np.testing.assert_allclose(floats[20:23], (0.125, -0.5, 0.0))


def test_the_declared_block_is_the_drivers_layout():
    from gandalf_core.render.opengl.libs import make_current
    from gandalf_core.render.opengl.raw_gl import block_members

    with Application("opengl", 16, 12, headless=True) as app:
        shader = build_shader(app)
        make_current(app.renderer.ctx)
        driver = block_members(shader.program.glo)["Material"]
        layout = shader.material_block
        declared = {path: offset for path, offset, _t in layout.leaves()}
        assert {name.split(".", 1)[1]: off for name, (off, _s) in driver.items()} == declared
        assert shader.program["Material"].size == layout.size


def _shader_files() -> list[Path]:
    roots = [REPO_ROOT / "gandalf_core", *sorted(REPO_ROOT.glob("step*")), REPO_ROOT / "tests" / "core" / "shaders",
             REPO_ROOT / "benchmarks", REPO_ROOT / "notebooks"]
    suffixes = (".frag", ".vert", ".geom", ".tesc", ".tese", ".glsl", ".wgsl")
    return [p for root in roots for p in sorted(root.rglob("*")) if p.suffix in suffixes and ".snap" not in p.parts]


def test_no_shader_declares_the_material_block_by_hand():
    """The Material block is declared in Python with the shader and written by the engine: no shader file holds a
    ``uniform Material`` block or a ``struct Material`` of its own."""
    by_hand = re.compile(r"\buniform\s+Material\b|\bstruct\s+Material\b")
    found = [str(p.relative_to(REPO_ROOT)) for p in _shader_files() if by_hand.search(p.read_text())]
    assert not found, f"Material blocks declared by hand (use #include \"material.glsl\" / \"material.wgsl\"): {found}"


def test_no_loose_material_uniforms_are_left_in_the_project_shaders():
    # The renderer's own per-draw uniforms (ENGINE_UNIFORMS: u_first_instance) are no material values.
    loose = re.compile(r"^\s*uniform\s+(?!sampler|isampler|usampler)\w+\s+(u_\w+)", re.M)
    roots = [REPO_ROOT / "gandalf_core", *sorted(REPO_ROOT.glob("step*"))]
    found = [str(p.relative_to(REPO_ROOT)) for root in roots for p in sorted(root.rglob("*"))
             if p.suffix in (".frag", ".vert", ".geom", ".tesc", ".tese", ".glsl", ".comp")
             and ".snap" not in p.parts
             and any(m.group(1) not in ENGINE_UNIFORMS for m in loose.finditer(p.read_text()))]
    assert not found, f"loose u_ material uniforms (use the Material block): {found}"


# --- the checks when a material is built --------------------------------------------------------------------
@pytest.mark.parametrize(("params", "needle"), [
    ({**PARAMS, "gian": 1.0}, r"material 'M': params\['gian'\]: shader 'probe' \(probe\.\w+.*\) has no value 'gian'"
                              r".*did you mean 'gain'"),
    ({k: v for k, v in PARAMS.items() if k != "gain"},
     r"material 'M': params: shader 'probe' \(probe\.\w+.*\) reads 'gain', which the material never sets"),
    ({**PARAMS, "tint": (1.0, 2.0)},
     r"material 'M': params: shader 'probe' \(probe\.\w+.*\): block 'Material' field 'tint': expected 3 value"),
    ({**PARAMS, "m": np.zeros(16)}, r"material 'M': params: .*block 'Material' field 'm': expected 9 value"),
])
def test_a_material_that_does_not_fit_its_block_names_material_shader_file_and_field(backend, params, needle):
    with Application(backend, 16, 12, headless=True) as app:
        build_shader(app)
        with pytest.raises(ResourceError, match=needle):
            app.renderer.materials.build("M", MaterialData("probe", params=params))
        assert "M" not in app.renderer.materials


def test_a_u_prefixed_parameter_says_to_leave_the_prefix_out():
    with Application("opengl", 16, 12, headless=True) as app:
        build_shader(app)
        params = {**{k: v for k, v in PARAMS.items() if k != "gain"}, "u_gain": 1.0}
        with pytest.raises(ResourceError, match=r"material 'M': params\['u_gain'\]: give it without the 'u_' "
                                                r"prefix: 'gain'"):
            app.renderer.materials.build("M", MaterialData("probe", params=params))


def test_padding_fields_have_a_default_and_the_colour_is_optional(backend):
    frag = GL_FRAG.replace("material.color * ", "")
    wgsl = WGSL.replace("material.color * ", "")
    with Application(backend, 16, 12, headless=True) as app:
        build_shader(app, frag=frag, wgsl=wgsl, material=MATERIAL[1:])
        material = app.renderer.materials.build("M", MaterialData("probe", color=(1, 0, 0), params=PARAMS))
        assert len(material.block_bytes) == 80  # tint, gain, m (48), offset, _pad


def test_a_cube_map_in_a_2d_slot_of_a_block_material_names_the_slot(backend):
    with Application(backend, 16, 12, headless=True) as app:
        r = app.renderer
        build_shaders(r.shaders, backend, "unlit")
        r.textures.build("sky", sky_cube(8))
        r.textures.build("flat", checkerboard(8, 2))
        r.materials.build("ok", MaterialData("unlit", ["flat"]))
        with pytest.raises(ResourceError, match=r"material 'M': textures: texture 'sky' is a cube map, but shader "
                                                r"'unlit' samples a 2-D texture in slot"):
            r.materials.build("M", MaterialData("unlit", ["sky"]))


#: Stage interfaces that do not match, each refused naming the shader, its file and the variable: the API, the
#: source edited (``frag``, ``vert`` or ``wgsl``), its ``(old, new)`` edits and the expected message (a pattern).
MISMATCHED_INTERFACES = {
    "glsl-varying-never-declared": ("opengl", "frag", [
        ("in vec3 v_world;", "in vec3 v_world;\nin vec2 v_uv;"),
        ("vec4(v_world, 0.0) * 0.0", "vec4(v_world + vec3(v_uv, 0.0), 0.0) * 0.0"),
    ], r"shader 'probe' \(probe\.frag\): the fragment stage reads varying 'v_uv' \(vec2\), which the vertex stage "
       r"\(probe\.vert\) never declares as 'out' \(its outputs: v_world\)"),
    "glsl-varying-never-written": ("opengl", "vert", [("    v_world = world.xyz;\n", "")],
                                   r"shader 'probe' \(probe\.frag\): the fragment stage reads varying 'v_world', "
                                   r"which the vertex stage \(probe\.vert\) declares but never writes"),
    "glsl-varying-of-another-type": ("opengl", "frag", [
        ("in vec3 v_world;", "in vec4 v_world;"), ("vec4(v_world, 0.0)", "v_world"),
    ], r"varying 'v_world' is vec4 here but vec3 in the vertex stage"),
    "wgsl-input-never-returned": ("webgpu", "wgsl", [
        ("@fragment fn fs_main(in: VOut)", "@fragment fn fs_main(in: VOut, @location(3) uv: vec2<f32>)"),
    ], r"shader 'probe': probe\.wgsl:\d+: fragment entry point 'fs_main' reads @location\(3\) \(Float32x2\), "
       r"which vertex entry point 'vs_main' never returns"),
    "wgsl-input-of-another-type": ("webgpu", "wgsl", [
        ("@fragment fn fs_main(in: VOut)", "@fragment fn fs_main(@location(0) world: vec4<f32>)"),
    ], r"probe\.wgsl:\d+: fragment entry point 'fs_main' reads @location\(0\) \(Float32x4\), which vertex entry "
       r"point 'vs_main' never returns \(.*fewer components or another type"),
}


@pytest.mark.parametrize("case", MISMATCHED_INTERFACES)
def test_a_stage_interface_mismatch_names_shader_file_and_variable(case):
    api, stage, edits, pattern = MISMATCHED_INTERFACES[case]
    source = {"frag": GL_FRAG, "vert": GL_VERT, "wgsl": WGSL}[stage]
    for old, new in edits:
        assert old in source, f"{case}: the probe shader no longer has {old!r}"
        source = source.replace(old, new)
    check_refused(api, pattern, **{stage: source})


def test_a_declared_block_no_stage_includes_names_the_shader_and_files(backend):
    frag = GL_FRAG.replace('#include "material.glsl"\n', "").replace(
        "f_color = material.color * vec4(material.tint * material.gain + material.m[1], 1.0)\n"
        "                        + vec4(material.offset, 0.0, 0.0) + ", "f_color = vec4(1.0) + ")
    wgsl = WGSL.replace('#include "material.wgsl"\n', "").replace(
        "return material.color * vec4<f32>(material.tint * material.gain + material.m[1], 1.0)\n"
        "        + vec4<f32>(material.offset, 0.0, 0.0);", "return vec4<f32>(1.0);")
    with Application(backend, 16, 12, headless=True) as app:
        with pytest.raises(ShaderCompileError, match=r"shader 'probe' \(probe\.\w+.*\): material= declares a Material "
                                                     r"block, but no stage includes it"):
            build_shader(app, frag=frag, wgsl=wgsl)


def test_a_block_that_wgsl_could_not_share_is_refused_naming_shader_and_field(backend):
    with Application(backend, 16, 12, headless=True) as app:
        with pytest.raises(ShaderCompileError, match=r"shader 'probe': material=: block 'Material' field 'm': std140 "
                                                     r"puts it at offset 16"):
            shaders, material = app.renderer.shaders, [("a", "float"), ("m", "mat2")]
            if backend == "opengl":
                shaders.build("probe", GL_VERT, GL_FRAG, material=material)
            else:
                shaders.build("probe", WGSL, material=material)


def test_changing_values_rewrites_the_block_without_a_new_buffer(backend):
    with Application(backend, 16, 12, headless=True) as app:
        build_shader(app)
        material = app.renderer.materials.build("M", MaterialData("probe", params=PARAMS))
        buffer = material.block_buffer if backend == "opengl" else material.uniform_buffer
        material.set_values({"color": (1, 1, 1, 1), **PARAMS, "gain": 3.0})
        assert np.frombuffer(material.block_bytes, np.float32)[7] == 3.0
        assert (material.block_buffer if backend == "opengl" else material.uniform_buffer) is buffer


def test_the_builtin_materials_are_the_same_bytes_in_both_apis_and_match_the_driver():
    from gandalf_core.render.opengl.libs import make_current
    from gandalf_core.render.opengl.raw_gl import block_members
    from gandalf_core.resources import checkerboard

    materials = {"plain": MaterialData("gandalf.blinn_phong", color=(0.2, 0.4, 0.6), params={"shininess": 8}),
                 "textured": MaterialData("gandalf.blinn_phong", ["t"], params={"specular": 0.5}),
                 "unlit": MaterialData("gandalf.unlit", color=(1, 0, 0, 0.5)),
                 "unlit_textured": MaterialData("gandalf.unlit", ["t"])}
    got: dict[str, dict[str, bytes]] = {}
    for backend in ("opengl", "webgpu"):
        with Application(backend, 16, 12, headless=True) as app:
            app.renderer.textures.build("t", checkerboard(8, 2))
            for name, data in materials.items():
                material = app.renderer.materials.build(name, data)
                got.setdefault(name, {})[backend] = material.block_bytes
                if backend == "opengl":
                    make_current(app.renderer.ctx)
                    driver = block_members(material.shader.program.glo)["Material"]
                    declared = {p: o for p, o, _t in material.shader.material_block.leaves()}
                    assert {k.split(".", 1)[1]: o for k, (o, _s) in driver.items()} == declared, name
    for name, pair in got.items():
        assert pair["opengl"] == pair["webgpu"], f"{name}: the Material bytes differ between the APIs"


def test_loose_material_uniforms_are_refused_naming_shader_files_and_uniforms():
    """A material's values go in its Material block: a program declaring loose ``u_<name>`` uniforms (the older
    way, which read 0 when a material forgot them) is refused when it is built, naming its files and uniforms."""
    frag = ("#version 330 core\nin vec3 v_world;\nuniform vec4 u_color;\nuniform vec3 u_tint;\nout vec4 f_color;\n"
            "void main() { f_color = u_color * vec4(u_tint, 1.0) + vec4(v_world, 0.0) * 0.0; }\n")
    needle = r"shader 'probe' \(probe\.vert, probe\.frag\): declares loose material uniforms \(u_color, u_tint\)"
    with Application("opengl", 16, 12, headless=True) as app, pytest.raises(ShaderCompileError, match=needle):
        build_shader(app, frag=frag, material=None)
