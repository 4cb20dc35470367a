"""Run one shader expression per element on the GPU, in GLSL and in WGSL, and read the results back.

The step 07 graders use it to test a student's shader *functions* on edge inputs in both languages: the
student's file is ``#include``d in ``prelude``, ``expression`` calls it, and every element of the ``inputs``
arrays gives one invocation: of a GLSL 3.30 vertex shader captured by transform feedback (so it runs on OpenGL 3.3
and macOS's 4.1, which have no compute shaders), and of a WGSL compute shader. A shared headless context (OpenGL)
and device (WebGPU) serve all tests, so a call costs a compile and one small draw or dispatch.

    eval_glsl('#include "terrain.glsl"', "tess_level(a, b, c.x)",
              {"a": ("vec4", A), "b": ("vec4", B), "c": ("f32", C)}, "f32", include_dirs=[impl_dir])

Types: ``"f32"``, ``"vec2"``, ``"vec4"``, ``"u32"``, ``"i32"`` (no vec3: its array stride differs between
std430 and WGSL's storage layout, so pad to vec4). Inside ``expression`` each input is a local of its type for
the current element.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from gandalf_core.render.errors import ShaderCompileError
from gandalf_core.render.shader_files import load_shader
from gandalf_tools.grading.shader_box import on_shader_box

WORKGROUP = 64
#: type name -> (GLSL type, WGSL type, numpy dtype, components)
TYPES = {
    "f32": ("float", "f32", np.float32, 1),
    "vec2": ("vec2", "vec2<f32>", np.float32, 2),
    "vec4": ("vec4", "vec4<f32>", np.float32, 4),
    "u32": ("uint", "u32", np.uint32, 1),
    "i32": ("int", "i32", np.int32, 1),
}

Inputs = Mapping[str, tuple[str, np.ndarray]]


def _check(inputs: Inputs, output: str) -> tuple[int, list[tuple[str, str, np.ndarray]]]:
    if output not in TYPES:
        raise ValueError(f"output type {output!r} is not one of {sorted(TYPES)}")
    count = None
    arrays = []
    for name, (kind, values) in inputs.items():
        if kind not in TYPES:
            raise ValueError(f"input {name!r}: type {kind!r} is not one of {sorted(TYPES)}")
        _, _, dtype, components = TYPES[kind]
        a = np.ascontiguousarray(values, dtype=dtype)
        if a.ndim == 1 and components == 1:
            pass
        elif a.ndim == 2 and a.shape[1] == components:
            pass
        else:
            raise ValueError(f"input {name!r}: expected shape (n,) or (n, {components}) for {kind}, got {a.shape}")
        if count is None:
            count = a.shape[0]
        elif a.shape[0] != count:
            raise ValueError(f"input {name!r} has {a.shape[0]} elements, the others {count}")
        arrays.append((name, kind, a))
    if not count:
        raise ValueError("no input elements")
    return count, arrays


def _result(data: bytes, output: str, count: int) -> np.ndarray:
    _, _, dtype, components = TYPES[output]
    a = np.frombuffer(data, dtype=dtype)[: count * components].copy()
    return a if components == 1 else a.reshape(count, components)


# --- OpenGL ----------------------------------------------------------------------------------------
#: type name -> moderngl's vertex attribute format (one attribute per input array).
GL_FORMATS = {"f32": "f", "vec2": "2f", "vec4": "4f", "u32": "u", "i32": "i"}


@functools.cache
def gl_context():
    """The shared headless OpenGL context of the harness (3.3 core is enough: it uses transform feedback)."""
    from gandalf_core.render.opengl.renderer import _standalone_context

    return _standalone_context()


@functools.cache
def gl_target():
    """A 1 x 1 framebuffer: a surfaceless EGL context has no default one, and a draw needs a complete framebuffer
    even when transform feedback turns the rasteriser off."""
    return gl_context().simple_framebuffer((1, 1))


def renderers() -> tuple[str, str]:
    """The OpenGL renderer and the WebGPU adapter this process draws with (the grader asks its shader process)."""
    from gandalf_core.render.webgpu.device import request_device

    info = request_device()[0].info
    return gl_context().info["GL_RENDERER"], f"{info.get('device', '')} ({info.get('backend_type', '')})"


def glsl_source(prelude: str, expression: str, arrays: list[tuple[str, str, np.ndarray]], output: str) -> str:
    """A GLSL 3.30 vertex shader: each vertex is one element, its inputs are vertex attributes, and the result is
    captured by transform feedback (OpenGL 3.0), so the same test runs on every OpenGL of the course (3.3 core up,
    macOS's 4.1 included)."""
    inputs = "".join(f"in {TYPES[kind][0]} in_{name};\n" for name, kind, _ in arrays)
    reads = "".join(f"    {TYPES[kind][0]} {name} = in_{name};\n" for name, kind, _ in arrays)
    return f"""#version 330 core
{inputs}flat out {TYPES[output][0]} result;
{prelude}
void main() {{
{reads}    result = {expression};
}}
"""


def eval_glsl(prelude: str, expression: str, inputs: Inputs, output: str,
              include_dirs: Sequence[str | Path] = ()) -> np.ndarray:
    """``expression`` evaluated per element in a GLSL vertex shader; returns the ``output`` values."""
    count, arrays = _check(inputs, output)
    ctx = gl_context()
    with ctx:  # another context (an app's, or wgpu's GL backend) may be current on this thread
        return _run_glsl(ctx, count, arrays, prelude, expression, output, include_dirs)


def _run_glsl(ctx, count, arrays, prelude, expression, output, include_dirs) -> np.ndarray:
    import moderngl

    source = load_shader(glsl_source(prelude, expression, arrays, output), "vertex", "glsl", include_dirs)
    try:
        program = ctx.program(vertex_shader=source.text, varyings=["result"])
    except moderngl.Error as exc:
        from gandalf_core.render.opengl.libs import _explain_gl_error

        raise ShaderCompileError(_explain_gl_error("harness", str(exc), {"vertex_shader": source})) from None
    buffers = [ctx.buffer(a.tobytes()) for _, _, a in arrays]
    out = ctx.buffer(reserve=count * TYPES[output][3] * 4)
    # An input the expression does not read is optimised away: skip_errors leaves it out instead of failing.
    vao = ctx.vertex_array(program, [(buf, GL_FORMATS[kind], f"in_{name}")
                                     for buf, (name, kind, _) in zip(buffers, arrays)], skip_errors=True)
    try:
        gl_target().use()
        vao.transform(out, mode=moderngl.POINTS, vertices=count)
        return _result(out.read(), output, count)
    finally:
        for obj in (vao, *buffers, out, program):
            obj.release()


# --- WebGPU ----------------------------------------------------------------------------------------
@functools.cache
def wgpu_device():
    """The shared headless WebGPU device of the harness."""
    from gandalf_core.render.webgpu.device import request_device

    return request_device()[1]


def warm_up(api: str) -> None:
    """Start this process's OpenGL context (``api`` "glsl" or "opengl") or WebGPU device ("wgsl", "webgpu"): the
    grader's shader process does it before a student's first shader, outside that shader's time budget."""
    (gl_context if api in ("glsl", "opengl") else wgpu_device)()


def wgsl_source(prelude: str, expression: str, arrays: list[tuple[str, str, np.ndarray]], output: str) -> str:
    inputs = "".join(f"@group(0) @binding({binding}) var<storage, read> in_{name}: array<{TYPES[kind][1]}>;\n"
                     for binding, (name, kind, _) in enumerate(arrays))
    reads = "".join(f"    let {name} = in_{name}[i];\n" for name, _, _ in arrays)
    return f"""{prelude}
{inputs}@group(0) @binding({len(arrays)}) var<storage, read_write> result: array<{TYPES[output][1]}>;
@compute @workgroup_size({WORKGROUP})
fn harness_main(@builtin(global_invocation_id) gid: vec3<u32>) {{
    let i = gid.x;
    if (i >= arrayLength(&result)) {{ return; }}
{reads}    result[i] = {expression};
}}
"""


def eval_wgsl(prelude: str, expression: str, inputs: Inputs, output: str,
              include_dirs: Sequence[str | Path] = ()) -> np.ndarray:
    """``expression`` evaluated per element in a WGSL compute shader; returns the ``output`` values."""
    import wgpu

    count, arrays = _check(inputs, output)
    device = wgpu_device()
    source = load_shader(wgsl_source(prelude, expression, arrays, output), None, "wgsl", include_dirs)
    try:
        module = device.create_shader_module(code=source.text, label=source.filename)
        pipeline = device.create_compute_pipeline(layout="auto",
                                                  compute={"module": module, "entry_point": "harness_main"})
    except wgpu.GPUError as exc:
        from gandalf_core.render.webgpu.validation import compile_error

        raise ShaderCompileError(compile_error(source, str(exc))) from None
    usage = wgpu.BufferUsage
    buffers = [device.create_buffer_with_data(data=a.tobytes(), usage=usage.STORAGE) for _, _, a in arrays]
    size = count * TYPES[output][3] * 4
    out = device.create_buffer(size=size, usage=usage.STORAGE | usage.COPY_SRC)
    try:
        entries = [{"binding": i, "resource": {"buffer": b}} for i, b in enumerate([*buffers, out])]
        group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=entries)
        encoder = device.create_command_encoder()
        cpass = encoder.begin_compute_pass()
        cpass.set_pipeline(pipeline)
        cpass.set_bind_group(0, group)
        cpass.dispatch_workgroups((count + WORKGROUP - 1) // WORKGROUP)
        cpass.end()
        device.queue.submit([encoder.finish()])
        return _result(device.queue.read_buffer(out), output, count)
    finally:
        for buf in (*buffers, out):
            buf.destroy()


@on_shader_box  # a student's shader files: compiled and run in the grader's shader process, not in this one
def evaluate(language: str, prelude: str, expression: str, inputs: Inputs, output: str,
             include_dirs: Sequence[str | Path] = ()) -> np.ndarray:
    """:func:`eval_glsl` for ``language == "glsl"``, :func:`eval_wgsl` for ``"wgsl"``."""
    run = {"glsl": eval_glsl, "wgsl": eval_wgsl}[language]
    return run(prelude, expression, inputs, output, include_dirs)
