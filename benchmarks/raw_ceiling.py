"""Raw-API ceiling: the fastest a Python program can animate and draw N rotating cubes with
moderngl or wgpu directly (vectorised numpy model matrices uploaded every frame, ONE instanced draw,
a 1-pixel readback per frame so the GPU really finishes). The framework is measured against this.
usage: python raw_ceiling.py [opengl|webgpu|both] [W H] [frames]
(The same program as the shared bench/raw_ceiling.py, only reformatted.)

``SYNC=inflight`` waits as ``bench_scenes.py --sync inflight`` does: each frame waits for the previous frame's
pixel, not its own (two frames in flight, as a swap chain of two images allows)."""

import json
import os
import sys
import time

import bench_common
import numpy as np

SYNC = os.environ.get("SYNC", "pixel")
if SYNC not in ("pixel", "inflight"):
    sys.exit(f"SYNC must be pixel or inflight, not {SYNC!r}")


def cube():
    f = [
        ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
        ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
        ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
        ((0, 0, -1), (0, 1, 0), (1, 0, 0)),
    ]
    out = []
    for n, u, v in f:
        n, u, v = map(np.array, (n, u, v))
        c = [
            n * 0.5 - u * 0.5 - v * 0.5,
            n * 0.5 + u * 0.5 - v * 0.5,
            n * 0.5 + u * 0.5 + v * 0.5,
            n * 0.5 - u * 0.5 + v * 0.5,
        ]
        for i in (0, 1, 2, 0, 2, 3):
            out.append(np.concatenate([c[i], n]))
    return np.array(out, dtype="f4")


def grid(n):
    g = int(np.ceil(np.cbrt(n)))
    i = np.arange(n)
    return np.stack([(i % g) - (g - 1) / 2, (i // g % g) - (g - 1) / 2, -(i // (g * g)) - 2.0], 1) * 1.8


def view_proj(w, h, n, zero_to_one):
    g = int(np.ceil(np.cbrt(n)))
    fov, near, far = np.radians(60), 0.1, 10.0 * g + 100
    f = 1 / np.tan(fov / 2)
    a = w / h
    if zero_to_one:
        P = np.array(
            [[f / a, 0, 0, 0], [0, f, 0, 0], [0, 0, far / (near - far), far * near / (near - far)], [0, 0, -1, 0]]
        )
    else:
        P = np.array(
            [
                [f / a, 0, 0, 0],
                [0, f, 0, 0],
                [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
                [0, 0, -1, 0],
            ]
        )
    V = np.eye(4)
    V[2, 3] = -(1.6 * g + 2.0)
    return P @ V


class Models:
    """Per-frame vectorised model matrices (rotation about y, per-instance phase), column-major f32."""

    def __init__(self, n):
        self.pos = grid(n)
        self.phase = np.arange(n) * 0.1
        self.out = np.zeros((n, 4, 4), "f4")
        self.out[:, 3, 3] = 1
        self.out[:, 3, :3] = self.pos

    def at(self, t):
        a = self.phase + t
        c, s = np.cos(a), np.sin(a)
        o = self.out  # column-major: out[i, col, row]
        o[:, 0, 0] = c
        o[:, 0, 2] = -s
        o[:, 1, 1] = 1
        o[:, 2, 0] = s
        o[:, 2, 2] = c
        return o


def run_gl(n, W, H, frames):
    import moderngl

    ctx = moderngl.create_standalone_context(backend="egl", require=330)
    fbo = ctx.framebuffer(color_attachments=[ctx.texture((W, H), 4)], depth_attachment=ctx.depth_texture((W, H)))
    fbo.use()
    ctx.enable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
    prog = ctx.program(
        vertex_shader="""#version 330 core
in vec3 p; in vec3 nr; in mat4 m; uniform mat4 vp; out vec3 vn;
void main(){ vn = mat3(m)*nr; gl_Position = vp * m * vec4(p, 1.0); }""",
        fragment_shader="""#version 330 core
in vec3 vn; out vec4 f;
void main(){ float d = max(dot(normalize(vn), normalize(vec3(0.3,0.5,1.0))), 0.0);
  f = vec4(vec3(0.2) + d*vec3(0.8,0.6,0.3), 1.0); }""",
    )
    prog["vp"].write(np.ascontiguousarray(view_proj(W, H, n, False).T, dtype="f4").tobytes())
    pacer = bench_common.GLFramesInFlight(ctx, fbo, W // 2, H // 2) if SYNC == "inflight" else None
    models = Models(n)
    vbo = ctx.buffer(cube().tobytes())
    ibo = ctx.buffer(reserve=n * 64, dynamic=True)
    vao = ctx.vertex_array(prog, [(vbo, "3f 3f", "p", "nr"), (ibo, "16f/i", "m")])

    def frame(i):
        ibo.write(models.at(i * 0.01).tobytes())
        fbo.clear(0.05, 0.05, 0.1, 1.0, depth=1.0)
        vao.render(instances=n)
        if pacer is None:
            fbo.read(viewport=(W // 2, H // 2, 1, 1), components=4)
        else:
            pacer()

    info = ctx.info["GL_RENDERER"]
    frame.drain = getattr(pacer, "drain", lambda: None)
    return frame, info, lambda: np.frombuffer(fbo.read(components=4), np.uint8).reshape(H, W, 4)[::-1]


def run_wgpu(n, W, H, frames):
    import wgpu

    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    device = adapter.request_device_sync()
    sh = device.create_shader_module(
        code="""
struct U { vp: mat4x4<f32> };
@group(0) @binding(0) var<uniform> u: U;
@group(0) @binding(1) var<storage, read> models: array<mat4x4<f32>>;
struct VOut { @builtin(position) pos: vec4<f32>, @location(0) n: vec3<f32> };
@vertex fn vs(@location(0) p: vec3<f32>, @location(1) nr: vec3<f32>, @builtin(instance_index) i: u32) -> VOut {
  let m = models[i]; var o: VOut; o.n = (m * vec4<f32>(nr, 0.0)).xyz; o.pos = u.vp * m * vec4<f32>(p, 1.0); return o; }
@fragment fn fs(v: VOut) -> @location(0) vec4<f32> {
  let d = max(dot(normalize(v.n), normalize(vec3<f32>(0.3,0.5,1.0))), 0.0);
  return vec4<f32>(vec3<f32>(0.2) + d*vec3<f32>(0.8,0.6,0.3), 1.0); }"""
    )
    pipe = device.create_render_pipeline(
        layout="auto",
        vertex={
            "module": sh,
            "entry_point": "vs",
            "buffers": [
                {
                    "array_stride": 24,
                    "step_mode": "vertex",
                    "attributes": [
                        {"format": "float32x3", "offset": 0, "shader_location": 0},
                        {"format": "float32x3", "offset": 12, "shader_location": 1},
                    ],
                }
            ],
        },
        primitive={"topology": "triangle-list", "cull_mode": "back", "front_face": "ccw"},
        depth_stencil={"format": "depth24plus", "depth_write_enabled": True, "depth_compare": "less"},
        fragment={"module": sh, "entry_point": "fs", "targets": [{"format": "rgba8unorm"}]},
    )
    models = Models(n)
    vbo = device.create_buffer_with_data(data=cube(), usage="VERTEX")
    sbo = device.create_buffer(size=max(64, n * 64), usage="STORAGE|COPY_DST")
    ubo = device.create_buffer_with_data(
        data=np.ascontiguousarray(view_proj(W, H, n, True).T, dtype="f4"), usage="UNIFORM"
    )
    bg = device.create_bind_group(
        layout=pipe.get_bind_group_layout(0),
        entries=[{"binding": 0, "resource": {"buffer": ubo}}, {"binding": 1, "resource": {"buffer": sbo}}],
    )
    color = device.create_texture(size=(W, H, 1), format="rgba8unorm", usage="RENDER_ATTACHMENT|COPY_SRC")
    depth = device.create_texture(size=(W, H, 1), format="depth24plus", usage="RENDER_ATTACHMENT")
    cv, dv = color.create_view(), depth.create_view()
    pacer = bench_common.WgpuFramesInFlight(device, lambda: color, W // 2, H // 2) if SYNC == "inflight" else None

    def frame(i):
        device.queue.write_buffer(sbo, 0, models.at(i * 0.01))
        enc = device.create_command_encoder()
        rp = enc.begin_render_pass(
            color_attachments=[
                {"view": cv, "clear_value": (0.05, 0.05, 0.1, 1), "load_op": "clear", "store_op": "store"}
            ],
            depth_stencil_attachment={
                "view": dv,
                "depth_clear_value": 1.0,
                "depth_load_op": "clear",
                "depth_store_op": "store",
            },
        )
        rp.set_pipeline(pipe)
        rp.set_bind_group(0, bg)
        rp.set_vertex_buffer(0, vbo)
        rp.draw(36, n)
        rp.end()
        device.queue.submit([enc.finish()])
        if pacer is None:
            device.queue.read_texture({"texture": color, "origin": (W // 2, H // 2, 0)}, {"bytes_per_row": 256},
                                      (1, 1, 1))
        else:
            pacer()

    info = adapter.summary
    frame.drain = getattr(pacer, "drain", lambda: None)
    return (
        frame,
        info,
        lambda: np.frombuffer(
            device.queue.read_texture({"texture": color}, {"bytes_per_row": W * 4}, (W, H, 1)), np.uint8
        ).reshape(H, W, 4),
    )


def main():
    which = sys.argv[1] if len(sys.argv) > 1 else "both"
    W, H = (int(sys.argv[2]), int(sys.argv[3])) if len(sys.argv) > 3 else (1280, 720)
    frames = int(sys.argv[4]) if len(sys.argv) > 4 else 200
    ns = [int(x) for x in os.environ.get("NS", "1,100,1000,10000,100000").split(",")]
    outdir = os.environ.get("OUTDIR")
    for backend in ["opengl", "webgpu"] if which == "both" else [which]:
        for n in ns:
            frame, info, grab = (run_gl if backend == "opengl" else run_wgpu)(n, W, H, frames)
            for i in range(10):
                frame(i)
            ts = []
            t0 = time.perf_counter()
            for i in range(frames):
                a = time.perf_counter()
                frame(i)
                ts.append(time.perf_counter() - a)
            frame.drain()
            wall = time.perf_counter() - t0
            ts = np.array(ts) * 1e3
            print(
                json.dumps(
                    {
                        "backend": backend,
                        "n": n,
                        "size": [W, H],
                        "sync": SYNC,
                        "fps": round(frames / wall, 1),
                        "p50_ms": round(float(np.median(ts)), 3),
                        "p95_ms": round(float(np.percentile(ts, 95)), 3),
                        "renderer": info,
                    }
                ),
                flush=True,
            )
            if outdir and n == ns[-1]:
                from PIL import Image

                Image.fromarray(grab()).save(os.path.join(outdir, f"ceiling-{backend}-{n}.png"))


if __name__ == "__main__":
    main()
