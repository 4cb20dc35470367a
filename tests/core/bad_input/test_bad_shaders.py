"""Shaders: GLSL and WGSL syntax, type and link errors point at ``file:line`` (the included file's own line when
the error is in an include); missing files and includes, include cycles, missing or ambiguous entry points and
varyings the other stage never writes are errors naming the shader files. GLSL cases run on the OpenGL app, WGSL
cases on the WebGPU app. Every file is written by this module (its text is below, so each expected line number
can be read off)."""

from __future__ import annotations

from pathlib import Path

import pytest

from gandalf_core.render.errors import ShaderCompileError
from gandalf_core.resources import ResourceError

from .catalogue import error, params_per_backend, result, run, write_files

FILES = {
    "plain.vert": """#version 330 core
layout(location = 0) in vec3 a_position;
void main() { gl_Position = vec4(a_position, 1.0); }
""",
    "ok.frag": """#version 330 core
out vec4 f_color;
void main() { f_color = vec4(1.0); }
""",
    "syntax.frag": """#version 330 core
out vec4 f_color;
void main() {
    f_color = vec4(1.0) +;
}
""",
    "undeclared.vert": """#version 330 core
layout(location = 0) in vec3 a_position;
void main() {
    gl_Position = vec4(a_position, 1.0) * undefined_thing;
}
""",
    "types.frag": """#version 330 core
out vec4 f_color;
void main() {
    f_color = vec4(1.0);
    float x = vec3(1.0);
}
""",
    "helper.glsl": """float helper() {
    return vec3(1.0);
}
""",
    "uses_helper.frag": """#version 330 core
#include "helper.glsl"
out vec4 f_color;
void main() { f_color = vec4(helper()); }
""",
    "lost_include.frag": """#version 330 core
#include "nowhere.glsl"
out vec4 f_color;
void main() { f_color = vec4(1.0); }
""",
    "loop.glsl": """#include "loop.glsl"
""",
    "cycle.frag": """#version 330 core
#include "loop.glsl"
out vec4 f_color;
void main() { f_color = vec4(1.0); }
""",
    "reads_missing.frag": """#version 330 core
in vec2 v_missing;
out vec4 f_color;
void main() { f_color = vec4(v_missing, 0.0, 1.0); }
""",
    "writes_vec3.vert": """#version 330 core
layout(location = 0) in vec3 a_position;
out vec3 v_c;
void main() { v_c = a_position; gl_Position = vec4(a_position, 1.0); }
""",
    "reads_vec2.frag": """#version 330 core
in vec2 v_c;
out vec4 f_color;
void main() { f_color = vec4(v_c, 0.0, 1.0); }
""",
    "no_main.vert": """#version 330 core
layout(location = 0) in vec3 a_position;
void not_main() { gl_Position = vec4(a_position, 1.0); }
""",
    "empty.frag": "",
    "shader.txt": "void main() {}\n",
    # WGSL
    "ok.wgsl": """@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    return vec4<f32>(0.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
""",
    "syntax.wgsl": """@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    return vec4<f32>(0.0)
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
""",
    "undeclared.wgsl": """@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let x = undefined_thing;
    return vec4<f32>(0.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
""",
    "types.wgsl": """@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    return vec4<f32>(0.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> {
    let x: f32 = vec3<f32>(1.0);
    return vec4<f32>(x);
}
""",
    "helper.wgsl": """fn helper() -> f32 {
    return vec3<f32>(1.0);
}
""",
    "uses_helper.wgsl": """#include "helper.wgsl"
@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> { return vec4<f32>(helper()); }
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
""",
    "lost_include.wgsl": """#include "nowhere.wgsl"
@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> { return vec4<f32>(0.0); }
@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
""",
    "no_fragment.wgsl": """@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    return vec4<f32>(0.0);
}
""",
    "two_fragments.wgsl": """@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    return vec4<f32>(0.0);
}
@fragment fn fs_a() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }
@fragment fn fs_b() -> @location(0) vec4<f32> { return vec4<f32>(0.5); }
""",
    "varying.wgsl": """struct VOut { @builtin(position) p: vec4<f32>, @location(0) c: vec3<f32> };
@vertex fn vs_main(@builtin(vertex_index) i: u32) -> VOut {
    var o: VOut; o.p = vec4<f32>(0.0); o.c = vec3<f32>(1.0); return o;
}
@fragment fn fs_main(@location(1) c: vec3<f32>) -> @location(0) vec4<f32> { return vec4<f32>(c, 1.0); }
""",
    "empty.wgsl": "",
}



@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return write_files(tmp_path_factory.mktemp("shaders"), FILES)


_n = [0]


def glsl(vertex: str, fragment: str):
    def action(app, folder):
        _n[0] += 1
        return app.renderer.shaders.build(f"glsl-{_n[0]}", folder / vertex, folder / fragment)
    return action


def wgsl(source: str, **entries):
    def action(app, folder):
        _n[0] += 1
        return app.renderer.shaders.build(f"wgsl-{_n[0]}", folder / source, **entries)
    return action


GLSL = [
    error("glsl-syntax-error", glsl("plain.vert", "syntax.frag"), ShaderCompileError, "syntax.frag:4:", "syntax error"),
    error("glsl-undeclared-name", glsl("undeclared.vert", "ok.frag"), ShaderCompileError, "undeclared.vert:4:",
          "undefined_thing"),
    error("glsl-type-error", glsl("plain.vert", "types.frag"), ShaderCompileError, "types.frag:5:"),
    error("glsl-error-in-include", glsl("plain.vert", "uses_helper.frag"), ShaderCompileError, "helper.glsl:2:",
          "return"),
    error("glsl-missing-include", glsl("plain.vert", "lost_include.frag"), ResourceError, "lost_include.frag:2",
          '"nowhere.glsl" not found'),
    error("glsl-include-cycle", glsl("plain.vert", "cycle.frag"), ResourceError, "cycle.frag", "include cycle",
          "loop.glsl"),
    error("glsl-missing-file", glsl("plain.vert", "gone.frag"), ResourceError, "gone.frag", "file not found"),
    error("glsl-unknown-extension", glsl("plain.vert", "shader.txt"), ResourceError, "shader.txt",
          "unknown shader extension '.txt'"),
    error("glsl-empty-file", glsl("plain.vert", "empty.frag"), ShaderCompileError, "empty.frag:1:"),
    error("glsl-varying-never-written", glsl("plain.vert", "reads_missing.frag"), ShaderCompileError,
          "reads_missing.frag", "varying 'v_missing'", "plain.vert", "never declares"),
    error("glsl-varying-type-mismatch", glsl("writes_vec3.vert", "reads_vec2.frag"), ShaderCompileError,
          "reads_vec2.frag", "varying 'v_c' is vec2", "vec3 in the vertex stage"),
    error("glsl-link-error-no-main", glsl("no_main.vert", "ok.frag"), ShaderCompileError, "no_main.vert", "main"),
    error("glsl-given-a-wgsl-file", glsl("plain.vert", "ok.wgsl"), ResourceError, "ok.wgsl",
          "is WGSL", "OpenGL renderer compiles GLSL"),
    result("glsl-good-pair-builds", glsl("plain.vert", "ok.frag"), lambda shader: shader is not None),
]

WGSL = [
    error("wgsl-syntax-error", wgsl("syntax.wgsl"), ShaderCompileError, "syntax.wgsl:3:", "expected `;`"),
    error("wgsl-undeclared-name", wgsl("undeclared.wgsl"), ShaderCompileError, "undeclared.wgsl:2:",
          "undefined_thing"),
    error("wgsl-type-error", wgsl("types.wgsl"), ShaderCompileError, "types.wgsl:5:"),
    error("wgsl-error-in-include", wgsl("uses_helper.wgsl"), ShaderCompileError, "helper.wgsl:"),
    error("wgsl-missing-include", wgsl("lost_include.wgsl"), ResourceError, "lost_include.wgsl:1",
          '"nowhere.wgsl" not found'),
    error("wgsl-missing-file", wgsl("gone.wgsl"), ResourceError, "gone.wgsl", "file not found"),
    error("wgsl-empty-file", wgsl("empty.wgsl"), ShaderCompileError, "empty.wgsl", "@vertex entry point"),
    error("wgsl-no-fragment-entry", wgsl("no_fragment.wgsl"), ShaderCompileError, "no_fragment.wgsl",
          "@fragment entry point, found 0"),
    error("wgsl-two-fragment-entries", wgsl("two_fragments.wgsl"), ShaderCompileError, "two_fragments.wgsl",
          "found 2", "fs_a", "fs_b", "name one"),
    error("wgsl-named-entry-missing", wgsl("ok.wgsl", vertex_entry="main"), ShaderCompileError, "ok.wgsl",
          "no @vertex entry point named 'main'", "vs_main"),
    error("wgsl-varying-never-written", wgsl("varying.wgsl"), ShaderCompileError, "varying.wgsl",
          "reads @location(1)", "never returns"),
    error("wgsl-given-a-glsl-file", wgsl("ok.frag"), ResourceError, "ok.frag", "is GLSL",
          "WebGPU renderer compiles WGSL"),
    result("wgsl-named-entry-of-two", wgsl("two_fragments.wgsl", fragment_entry="fs_b"),
           lambda shader: shader is not None),
]


@pytest.mark.parametrize(("case", "backend"), params_per_backend(GLSL, ("opengl",)))
def test_glsl(case, backend, apps, folder):
    run(case, apps[backend], folder)


@pytest.mark.parametrize(("case", "backend"), params_per_backend(WGSL, ("webgpu",)))
def test_wgsl(case, backend, apps, folder):
    run(case, apps[backend], folder)
