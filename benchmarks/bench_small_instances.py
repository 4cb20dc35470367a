"""What limits many small instances once their rows are pulled: the vertex shader's arithmetic, the instance count,
or the triangles? The raw ceiling's cubes (24 vertices, 12 triangles, rows read by index from a buffer texture or
storage buffer, as the engine does) drawn several ways, GPU time of the one draw (OpenGL ``GL_TIME_ELAPSED``; WebGPU
wall time of frames back to back, ended by a read-back):

* instanced, with the engine's normal (the cofactor matrix of ``instance_normal()``) or a plain ``mat3(m) * n``;
* "merged" instancing: K cubes an instance (the index buffer holds K copies; the cube is ``gl_VertexID / 24``),
  which packs the vertex shader's warps fuller when an instance has fewer vertices than a warp;
* not instanced at all: ``n * 36`` vertices, everything pulled by ``gl_VertexID``.

Every way prints a checksum of its picture: they must agree. Run by hand on a GPU, never in CI::

    NS4=100000,1000000 python3 benchmarks/bench_small_instances.py

(``NS4``: the cube counts; ``SIZE4``: the target, default 1280x720; ``REPS4``: frames, the median of all but the
first five is printed.)
"""
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import moderngl  # noqa: E402
import raw_ceiling as rc  # noqa: E402
from bench_instance_rows import indexed_cube, instance_rows  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from gandalf_core.render.opengl import raw_gl  # noqa: E402

ctx = moderngl.create_standalone_context(backend="egl", require=430)
print(ctx.info["GL_RENDERER"], ctx.info["GL_VERSION"], flush=True)
NS = [int(x) for x in os.environ.get("NS4", "100000,1000000").split(",")]
W, H = [int(v) for v in os.environ.get("SIZE4", "1280x720").split("x")]
REPS = int(os.environ.get("REPS4", "30"))

cube36 = rc.cube()
verts, idx = indexed_cube()  # the 24-vertex cube and the rows of bench_instance_rows.py: the same cubes and grid
V = len(verts)


FS = """#version 430 core
in vec3 vn; out vec4 f;
void main(){ float d = max(dot(normalize(vn), normalize(vec3(0.3,0.5,1.0))), 0.0);
  f = vec4(vec3(0.2) + d*vec3(0.8,0.6,0.3), 1.0); }"""
HEAD = """#version 430 core
uniform samplerBuffer rowtex; uniform mat4 vp; uniform int first; uniform int merge; uniform int nverts;
uniform int count; out vec3 vn;
"""
COFACTOR = """
vec3 nrm(mat4 mm, vec3 n) { mat3 m = mat3(mm);
    vec3 a = max(max(abs(m[0]), abs(m[1])), abs(m[2])); float s = max(max(a.x, a.y), a.z);
    if (s > 0.0) { m /= s; } vec3 c0 = m[0], c1 = m[1], c2 = m[2];
    mat3 cof = mat3(cross(c1, c2), cross(c2, c0), cross(c0, c1));
    float h = dot(c0, cross(c1, c2)) < 0.0 ? -1.0 : 1.0; vec3 r = cof * n * h; float len = length(r);
    return len > 1e-30 ? r / len : vec3(0.0, 1.0, 0.0); }
"""
SIMPLE = "vec3 nrm(mat4 m, vec3 n) { return mat3(m) * n; }\n"
BODY = """
void main(){ int inst = %s; int b = inst * 3;
 mat4 m = transpose(mat4(texelFetch(rowtex, b), texelFetch(rowtex, b+1), texelFetch(rowtex, b+2), vec4(0,0,0,1)));
 vn = nrm(m, nr); gl_Position = vp * m * vec4(p, 1.0); %s }"""
INST = "first + gl_InstanceID"
MERGED = "first + gl_InstanceID * merge + gl_VertexID / nverts"
CLIP = "if (inst >= count) gl_Position = vec4(2.0, 2.0, 2.0, 1.0);"
ATTRS = "in vec3 p; in vec3 nr;\n"
PULLED = """const vec3 P[36] = vec3[36]({}); const vec3 N[36] = vec3[36]({});
""".format(", ".join("vec3({!r}, {!r}, {!r})".format(*tuple(map(float, v[:3]))) for v in cube36),
       ", ".join("vec3({!r}, {!r}, {!r})".format(*tuple(map(float, v[3:6]))) for v in cube36))
PULLBODY = """
void main(){ int inst = gl_VertexID / 36; int b = inst * 3;
 vec3 p = P[gl_VertexID %% 36]; vec3 nr = N[gl_VertexID %% 36];
 mat4 m = transpose(mat4(texelFetch(rowtex, b), texelFetch(rowtex, b+1), texelFetch(rowtex, b+2), vec4(0,0,0,1)));
 vn = nrm(m, nr); gl_Position = vp * m * vec4(p, 1.0); %s }"""

_keep = []


def rowtex(n):
    """The rows in a buffer texture at unit 3, as the engine binds them (``raw_gl.BufferTexture``)."""
    buf = ctx.buffer(instance_rows(n).tobytes())
    texture = raw_gl.BufferTexture()
    texture.attach(buf.glo)
    texture.use(3)
    _keep.append((buf, texture))


def setu(p, name, v):
    if name in p:
        p[name] = v


def variant(kind, normal, k=1):
    def make(n):
        nf = COFACTOR if normal == "cofactor" else SIMPLE
        if kind == "pulled":
            vs = HEAD + PULLED + nf + PULLBODY % ""
        else:
            vs = HEAD + ATTRS + nf + BODY % ((INST, "") if k == 1 else (MERGED, CLIP))
        p = ctx.program(vertex_shader=vs, fragment_shader=FS)
        p["vp"].write(np.ascontiguousarray(rc.view_proj(W, H, n, False).T, dtype="f4").tobytes())
        rowtex(n)
        raw_gl.set_sampler_unit(p.glo, p["rowtex"].location, 3)
        for nm, v in (("first", 0), ("merge", k), ("nverts", V), ("count", n)):
            setu(p, nm, v)
        if kind == "pulled":
            vao = ctx.vertex_array(p, [])
            return p, (lambda: vao.render(moderngl.TRIANGLES, vertices=36 * n))
        vb = np.concatenate([verts] * k)
        ib = np.concatenate([idx + V * j for j in range(k)]).astype("i4")
        vao = ctx.vertex_array(p, [(ctx.buffer(vb.tobytes()), "3f 3f", "p", "nr")],
                               index_buffer=ctx.buffer(ib.tobytes()), index_element_size=4)
        inst = -(-n // k)
        return p, (lambda: vao.render(instances=inst))
    return make


def run(label, n, make):
    fbo = ctx.framebuffer([ctx.texture((W, H), 4)], ctx.depth_texture((W, H)))
    fbo.use()
    ctx.enable_only(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
    p, draw = make(n)
    q = ctx.query(time=True)
    times = []
    for _ in range(REPS):
        fbo.clear(0.05, 0.05, 0.1, 1.0, depth=1.0)
        with q:
            draw()
        ctx.finish()
        times.append(q.elapsed / 1e6)
    t = float(np.median(times[5:]))
    img = np.frombuffer(fbo.read(components=4), "u1").reshape(H, W, 4).astype(np.int64)
    print(f"GL  {label:40s} n={n:>8d} {t:8.3f} ms {t * 1e6 / n:7.2f} ns/cube  checksum {int(img.sum())}",
          flush=True)
    fbo.release()


for n in NS:
    run("instanced, cofactor normal (engine)", n, variant("inst", "cofactor"))
    run("instanced, mat3 normal", n, variant("inst", "simple"))
    for k in (4, 16, 64):
        run(f"merged x{k}, cofactor", n, variant("inst", "cofactor", k))
    run("merged x16, mat3 normal", n, variant("inst", "simple", 16))
    run("not instanced, pulled 36, cofactor", n, variant("pulled", "cofactor"))
    for buf, texture in _keep:
        texture.release()
        buf.release()
    _keep.clear()

# ---------------- WebGPU --------------------------------------------------------------------------
import wgpu  # noqa: E402

adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
dev = adapter.request_device_sync()
print("WGPU", adapter.info["device"], adapter.info["backend_type"], flush=True)
WCOMMON = """
struct U { vp: mat4x4<f32>, merge: u32, nverts: u32, count: u32, pad: u32 };
@group(0) @binding(0) var<uniform> u: U;
@group(0) @binding(1) var<storage, read> rows: array<vec4<f32>>;
struct VOut { @builtin(position) pos: vec4<f32>, @location(0) n: vec3<f32> };
fn nrm(m: mat4x4<f32>, n: vec3<f32>) -> vec3<f32> {
    let a = max(max(abs(m[0].xyz), abs(m[1].xyz)), abs(m[2].xyz));
    let largest = max(max(a.x, a.y), a.z);
    let s = select(1.0, 1.0 / largest, largest > 0.0);
    let c0 = m[0].xyz * s; let c1 = m[1].xyz * s; let c2 = m[2].xyz * s;
    let cof = mat3x3<f32>(cross(c1, c2), cross(c2, c0), cross(c0, c1));
    let h = select(1.0, -1.0, dot(c0, cross(c1, c2)) < 0.0);
    let r = cof * n * h; let len = length(r);
    return select(vec3<f32>(0.0, 1.0, 0.0), r / len, len > 1e-30); }
@fragment fn fs(v: VOut) -> @location(0) vec4<f32> {
  let d = max(dot(normalize(v.n), normalize(vec3<f32>(0.3,0.5,1.0))), 0.0);
  return vec4<f32>(vec3<f32>(0.2) + d*vec3<f32>(0.8,0.6,0.3), 1.0); }
@vertex fn vs(@location(0) p: vec3<f32>, @location(1) nr: vec3<f32>, @builtin(instance_index) ii: u32,
              @builtin(vertex_index) vi: u32) -> VOut {
  let i = ii * u.merge + vi / u.nverts;
  let m = transpose(mat4x4<f32>(rows[3u*i], rows[3u*i+1u], rows[3u*i+2u], vec4<f32>(0.0, 0.0, 0.0, 1.0)));
  var o: VOut; o.n = nrm(m, nr); o.pos = u.vp * m * vec4<f32>(p, 1.0);
  if (i >= u.count) { o.pos = vec4<f32>(2.0, 2.0, 2.0, 1.0); }
  return o; }
"""


def wrun(label, n, k, reps=30):
    sm = dev.create_shader_module(code=WCOMMON)
    vb = [{"array_stride": 24, "step_mode": "vertex", "attributes": [
        {"format": "float32x3", "offset": 0, "shader_location": 0},
        {"format": "float32x3", "offset": 12, "shader_location": 1}]}]
    pipe = dev.create_render_pipeline(
        layout="auto", vertex={"module": sm, "entry_point": "vs", "buffers": vb},
        primitive={"topology": "triangle-list", "cull_mode": "back"},
        depth_stencil={"format": "depth32float", "depth_write_enabled": True, "depth_compare": "less"},
        fragment={"module": sm, "entry_point": "fs", "targets": [{"format": "rgba8unorm"}]})
    color = dev.create_texture(size=(W, H, 1), format="rgba8unorm",
                               usage=wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC)
    depth = dev.create_texture(size=(W, H, 1), format="depth32float", usage=wgpu.TextureUsage.RENDER_ATTACHMENT)
    ud = np.ascontiguousarray(rc.view_proj(W, H, n, True).T, dtype="f4").tobytes() + np.array(
        [k, V, n, 0], "u4").tobytes()
    ub = dev.create_buffer_with_data(data=ud, usage=wgpu.BufferUsage.UNIFORM)
    sb = dev.create_buffer_with_data(data=instance_rows(n).tobytes(), usage=wgpu.BufferUsage.STORAGE)
    bg = dev.create_bind_group(layout=pipe.get_bind_group_layout(0), entries=[
        {"binding": 0, "resource": {"buffer": ub}}, {"binding": 1, "resource": {"buffer": sb}}])
    vbd = np.concatenate([verts] * k)
    ibd = np.concatenate([idx + V * j for j in range(k)]).astype(np.uint32)
    vbuf = dev.create_buffer_with_data(data=vbd.tobytes(), usage=wgpu.BufferUsage.VERTEX)
    ibuf = dev.create_buffer_with_data(data=ibd.tobytes(), usage=wgpu.BufferUsage.INDEX)
    cv, dv = color.create_view(), depth.create_view()
    inst = -(-n // k)

    def frame():
        enc = dev.create_command_encoder()
        rp = enc.begin_render_pass(
            color_attachments=[{"view": cv, "load_op": "clear", "store_op": "store", "clear_value": (0, 0, 0, 1)}],
            depth_stencil_attachment={"view": dv, "depth_load_op": "clear", "depth_store_op": "store",
                                      "depth_clear_value": 1.0})
        rp.set_pipeline(pipe)
        rp.set_bind_group(0, bg)
        rp.set_vertex_buffer(0, vbuf)
        rp.set_index_buffer(ibuf, "uint32")
        rp.draw_indexed(len(ibd), inst)
        rp.end()
        dev.queue.submit([enc.finish()])

    def sync():
        dev.queue.read_texture({"texture": color, "origin": (W // 2, H // 2, 0)}, {"bytes_per_row": 256}, (1, 1, 1))

    for _ in range(5):
        frame()
    sync()
    t0 = time.perf_counter()
    for _ in range(reps):
        frame()
    sync()
    t = (time.perf_counter() - t0) / reps * 1e3
    print(f"WGPU {label:39s} n={n:>8d} {t:8.3f} ms {t * 1e6 / n:7.2f} ns/cube (wall, pipelined)", flush=True)


for n in NS:
    for k in (1, 16, 64):
        wrun(f"storage, merged x{k}", n, k)
