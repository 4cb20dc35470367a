"""How the vertex shader gets each instance's rows: instanced vertex attributes against fetching them by instance
index (a buffer texture or a storage buffer), the same N cubes drawn with one instanced draw in both APIs.

Every variant draws the same picture (checked: identical read-back bytes within an API); only the way the three
affine rows of the model matrix reach the vertex shader changes. Time per frame, in both APIs the same way: the wall
clock of ``--frames`` frames (clear and one draw) issued back to back after ``--warmup`` frames, ended by reading the
picture back, divided by the frames. At 100k cubes and more the GPU is the bottleneck, so this is its throughput.
The engine uses the buffer texture (OpenGL) and the storage buffer (WebGPU): ``instance.glsl``/``instance.wgsl``.

usage: python benchmarks/bench_instance_rows.py [--ns 100000,1000000] [--size 1280x720] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import raw_ceiling  # noqa: E402  (the same cubes, grid and camera as the raw ceiling)

FS_GLSL = """#version 330 core
in vec3 v_normal; out vec4 colour;
void main() { float d = max(dot(normalize(v_normal), normalize(vec3(0.3, 0.5, 1.0))), 0.0);
  colour = vec4(vec3(0.2) + d * vec3(0.8, 0.6, 0.3), 1.0); }"""
VS_GLSL_HEAD = """#version {version} core
in vec3 p; in vec3 nr; uniform mat4 vp; out vec3 v_normal;
void emit(vec4 r0, vec4 r1, vec4 r2) {{
  mat4 m = transpose(mat4(r0, r1, r2, vec4(0.0, 0.0, 0.0, 1.0)));
  v_normal = mat3(m) * nr; gl_Position = vp * m * vec4(p, 1.0); }}
"""
VS_GLSL = {
    "attributes": ("330", "in vec4 r0; in vec4 r1; in vec4 r2; void main() { emit(r0, r1, r2); }"),
    "buffer texture": ("330", "uniform samplerBuffer rows; void main() { int b = gl_InstanceID * 3;"
                              " emit(texelFetch(rows, b), texelFetch(rows, b + 1), texelFetch(rows, b + 2)); }"),
    "storage buffer": ("430", "layout(std430, binding = 0) readonly buffer Rows { vec4 rows[]; };"
                              " void main() { int b = gl_InstanceID * 3; emit(rows[b], rows[b + 1], rows[b + 2]); }"),
}
WGSL_COMMON = """
struct U { vp: mat4x4<f32> };
@group(0) @binding(0) var<uniform> u: U;
struct VOut { @builtin(position) pos: vec4<f32>, @location(0) n: vec3<f32> };
fn emit(r0: vec4<f32>, r1: vec4<f32>, r2: vec4<f32>, p: vec3<f32>, nr: vec3<f32>) -> VOut {
  let m = transpose(mat4x4<f32>(r0, r1, r2, vec4<f32>(0.0, 0.0, 0.0, 1.0)));
  var o: VOut; o.n = (m * vec4<f32>(nr, 0.0)).xyz; o.pos = u.vp * m * vec4<f32>(p, 1.0); return o; }
@fragment fn fs(v: VOut) -> @location(0) vec4<f32> {
  let d = max(dot(normalize(v.n), normalize(vec3<f32>(0.3, 0.5, 1.0))), 0.0);
  return vec4<f32>(vec3<f32>(0.2) + d * vec3<f32>(0.8, 0.6, 0.3), 1.0); }
"""
VS_WGSL = {
    "vertex buffer": """@vertex fn vs(@location(0) p: vec3<f32>, @location(1) nr: vec3<f32>, @location(5) r0: vec4<f32>,
  @location(6) r1: vec4<f32>, @location(7) r2: vec4<f32>) -> VOut { return emit(r0, r1, r2, p, nr); }""",
    "storage buffer": """@group(0) @binding(1) var<storage, read> rows: array<vec4<f32>>;
@vertex fn vs(@location(0) p: vec3<f32>, @location(1) nr: vec3<f32>, @builtin(instance_index) i: u32) -> VOut {
  return emit(rows[3u * i], rows[3u * i + 1u], rows[3u * i + 2u], p, nr); }""",
}


def indexed_cube() -> tuple[np.ndarray, np.ndarray]:
    """The raw ceiling's cube as 24 vertices (position, normal) and 36 indices."""
    flat = raw_ceiling.cube()  # 36 vertices, two triangles (0 1 2, 0 2 3) a face
    faces = flat.reshape(6, 6, 6)
    vertices = faces[:, [0, 1, 2, 5]].reshape(-1, 6)
    indices = (np.arange(6)[:, None] * 4 + np.array([0, 1, 2, 0, 2, 3])).ravel().astype(np.uint32)
    return np.ascontiguousarray(vertices, dtype=np.float32), indices


def instance_rows(n: int) -> np.ndarray:
    """(n, 3, 4) float32: each cube turned about y by 0.1 rad per index, on the raw ceiling's grid."""
    pos = raw_ceiling.grid(n)
    a = np.arange(n) * 0.1
    c, s = np.cos(a), np.sin(a)
    rows = np.zeros((n, 3, 4), np.float32)
    rows[:, 0, 0], rows[:, 0, 2], rows[:, 0, 3] = c, s, pos[:, 0]
    rows[:, 1, 1], rows[:, 1, 3] = 1.0, pos[:, 1]
    rows[:, 2, 0], rows[:, 2, 2], rows[:, 2, 3] = -s, c, pos[:, 2]
    return rows


def opengl(ns: list[int], size: tuple[int, int], frames: int, warmup: int) -> list[dict]:
    import moderngl

    from gandalf_core.render.opengl import raw_gl

    ctx = moderngl.create_standalone_context(backend="egl", require=430)
    renderer = ctx.info["GL_RENDERER"]
    vertices, indices = indexed_cube()
    out = []
    for n in ns:
        fbo = ctx.framebuffer([ctx.texture(size, 4)], ctx.depth_texture(size))
        fbo.use()
        ctx.enable_only(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        rows = ctx.buffer(instance_rows(n).tobytes())
        vbo, ibo = ctx.buffer(vertices.tobytes()), ctx.buffer(indices.tobytes())
        texture = raw_gl.BufferTexture()
        texture.attach(rows.glo)
        pictures = {}
        for variant, (version, body) in VS_GLSL.items():
            prog = ctx.program(vertex_shader=VS_GLSL_HEAD.format(version=version) + body, fragment_shader=FS_GLSL)
            content = [(vbo, "3f 3f", "p", "nr")]
            if variant == "attributes":
                content.append((rows, "4f 4f 4f/i", "r0", "r1", "r2"))
            elif variant == "buffer texture":
                texture.use(0)
                raw_gl.set_sampler_unit(prog.glo, prog["rows"].location, 0)
            else:
                rows.bind_to_storage_buffer(0)
            vao = ctx.vertex_array(prog, content, index_buffer=ibo, index_element_size=4)
            prog["vp"].write(np.ascontiguousarray(raw_ceiling.view_proj(*size, n, False).T, dtype="f4").tobytes())
            for _ in range(warmup):
                fbo.clear(0.05, 0.05, 0.1, 1.0, depth=1.0)
                vao.render(instances=n)
            fbo.read(viewport=(0, 0, 1, 1))
            start = time.perf_counter()
            for _ in range(frames):
                fbo.clear(0.05, 0.05, 0.1, 1.0, depth=1.0)
                vao.render(instances=n)
            pictures[variant] = fbo.read(components=4)
            ms = (time.perf_counter() - start) / frames * 1e3
            out.append({"api": "opengl", "renderer": renderer, "variant": variant, "n": n, "size": list(size),
                        "ms": round(ms, 4), "ns_per_instance": round(ms * 1e6 / n, 2)})
            vao.release()
            prog.release()
        _check_same(pictures, "opengl", n)
        texture.release()
        for obj in (rows, vbo, ibo, fbo):
            obj.release()
    return out


def webgpu(ns: list[int], size: tuple[int, int], frames: int, warmup: int) -> list[dict]:
    import wgpu

    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    device = adapter.request_device_sync()
    renderer = f"{adapter.info['device']} via {adapter.info['backend_type']}"
    vertices, indices = indexed_cube()
    usage = wgpu.BufferUsage
    vbo = device.create_buffer_with_data(data=vertices.tobytes(), usage=usage.VERTEX)
    ibo = device.create_buffer_with_data(data=indices.tobytes(), usage=usage.INDEX)
    mesh_layout = {"array_stride": 24, "step_mode": "vertex", "attributes": [
        {"format": "float32x3", "offset": 0, "shader_location": 0},
        {"format": "float32x3", "offset": 12, "shader_location": 1}]}
    row_layout = {"array_stride": 48, "step_mode": "instance", "attributes": [
        {"format": "float32x4", "offset": 16 * k, "shader_location": 5 + k} for k in range(3)]}
    out = []
    for n in ns:
        w, h = size
        color = device.create_texture(size=(w, h, 1), format="rgba8unorm",
                                      usage=wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC)
        depth = device.create_texture(size=(w, h, 1), format="depth32float", usage=wgpu.TextureUsage.RENDER_ATTACHMENT)
        vp = np.ascontiguousarray(raw_ceiling.view_proj(w, h, n, True).T, dtype="f4")
        uniform = device.create_buffer_with_data(data=vp.tobytes(), usage=usage.UNIFORM)
        rows = device.create_buffer_with_data(data=instance_rows(n).tobytes(), usage=usage.VERTEX | usage.STORAGE)
        targets = color, color.create_view(), depth.create_view()  # what the frames draw into
        pictures = {}
        for variant, body in VS_WGSL.items():
            module = device.create_shader_module(code=WGSL_COMMON + body)
            pulled = variant == "storage buffer"
            pipeline = device.create_render_pipeline(
                layout="auto", vertex={"module": module, "entry_point": "vs",
                                       "buffers": [mesh_layout] if pulled else [mesh_layout, row_layout]},
                primitive={"topology": "triangle-list", "cull_mode": "back"},
                depth_stencil={"format": "depth32float", "depth_write_enabled": True, "depth_compare": "less"},
                fragment={"module": module, "entry_point": "fs", "targets": [{"format": "rgba8unorm"}]})
            entries = [{"binding": 0, "resource": {"buffer": uniform}}]
            if pulled:
                entries.append({"binding": 1, "resource": {"buffer": rows}})
            group = device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=entries)

            ms, pictures[variant] = _time_wgpu(device, pipeline, group, (vbo, rows if not pulled else None, ibo), n,
                                               targets, frames, warmup)
            out.append({"api": "webgpu", "renderer": renderer, "variant": variant, "n": n, "size": list(size),
                        "ms": round(ms, 4), "ns_per_instance": round(ms * 1e6 / n, 2)})
        _check_same(pictures, "webgpu", n)
        for obj in (color, depth, uniform, rows):
            obj.destroy()
    return out


def _time_wgpu(device, pipeline, group, buffers, n, targets, frames, warmup) -> tuple[float, bytes]:
    """ms a frame of ``frames`` frames submitted back to back (after ``warmup``), and the picture drawn."""
    vbo, rows, ibo = buffers
    color, color_view, depth_view = targets
    w, h = color.size[:2]

    def frame() -> None:
        encoder = device.create_command_encoder()
        rpass = encoder.begin_render_pass(
            color_attachments=[{"view": color_view, "load_op": "clear", "store_op": "store",
                                "clear_value": (0.05, 0.05, 0.1, 1.0)}],
            depth_stencil_attachment={"view": depth_view, "depth_load_op": "clear", "depth_store_op": "store",
                                      "depth_clear_value": 1.0})
        rpass.set_pipeline(pipeline)
        rpass.set_bind_group(0, group)
        rpass.set_vertex_buffer(0, vbo)
        if rows is not None:  # the rows as an instance-step vertex buffer
            rpass.set_vertex_buffer(1, rows)
        rpass.set_index_buffer(ibo, "uint32")
        rpass.draw_indexed(36, n)
        rpass.end()
        device.queue.submit([encoder.finish()])

    def read_back() -> bytes:
        return bytes(device.queue.read_texture({"texture": color, "origin": (0, 0, 0)},
                                               {"bytes_per_row": 4 * w, "rows_per_image": h}, (w, h, 1)))

    for _ in range(warmup):
        frame()
    read_back()
    start = time.perf_counter()
    for _ in range(frames):
        frame()
    picture = read_back()
    return (time.perf_counter() - start) / frames * 1e3, picture


def _check_same(pictures: dict[str, bytes], api: str, n: int) -> None:
    first, *rest = pictures.items()
    for variant, picture in rest:
        if picture != first[1]:
            raise AssertionError(f"{api}, {n} cubes: '{variant}' draws another picture than '{first[0]}'")


def main() -> None:
    parser = argparse.ArgumentParser(prog="python benchmarks/bench_instance_rows.py",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("--ns", default="100000,1000000", help="instance counts, comma-separated")
    parser.add_argument("--size", default="1280x720", help="framebuffer WxH")
    parser.add_argument("--frames", type=int, default=25)
    parser.add_argument("--warmup", type=int, default=5)
    parser.add_argument("--backends", default="opengl,webgpu")
    parser.add_argument("--json", type=Path, help="write the rows as JSON here")
    args = parser.parse_args()
    ns = [int(x) for x in args.ns.split(",")]
    size = tuple(int(x) for x in args.size.split("x"))
    rows: list[dict] = []
    for api in args.backends.split(","):
        rows += (opengl if api == "opengl" else webgpu)(ns, size, args.frames, args.warmup)
    print("| API | renderer | instance rows from | N | ms a frame | ns an instance |")
    print("|---|---|---|---:|---:|---:|")
    for r in rows:
        print(f"| {r['api']} | {r['renderer']} | {r['variant']} | {r['n']} | {r['ms']:.3f} | "
              f"{r['ns_per_instance']:.1f} |")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
