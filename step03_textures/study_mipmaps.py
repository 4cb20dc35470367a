"""The mipmap and filtering study: ``python -m step03_textures.study_mipmaps --out DIR [--quick]
[--backends opengl webgpu]``.

``TextureData(filter=..., mipmaps=...)`` picks how a texture is sampled. On a floor seen at a grazing angle one
pixel covers many texels; how wrong is each sampler there, and what does it cost?

* the scene: a checkerboard floor (a 512² sRGB texture of 32-texel checks, black (sRGB 0.1) and white (0.9),
  repeating every 4 m: 0.25 m checks) drawn with the step's ``textured`` shader, seen from 2 m above the floor
  looking 27° down (45° vertical field of view): the floor fills the picture, from 2 m away at the bottom to
  about 28 m at the top, where a pixel covers about ten checks;
* the samplers: ``nearest`` and ``linear`` without mipmaps, ``nearest`` with mipmaps (nearest level, nearest
  texel), ``linear`` with mipmaps (trilinear), and trilinear with anisotropic filtering
  (``TextureData(anisotropy=4 / 16)``: up to that many samples along the direction the floor recedes in);
* the reference: each pixel's exact box-filtered texture, estimated in float64 numpy by ``--ss``² (default 16²)
  rays spread evenly over the pixel, each looking up its texel (the texture is piecewise constant), averaged in
  linear light and encoded to 8-bit sRGB like the framebuffer;
* the error: the mean absolute 8-bit difference over the picture, also for the far half (the top half of the
  picture, where the texture is minified) and the near half on their own;
* the time: the median over ``--repeats`` runs of the mean frame time of ``--frames`` frames, each waited for with a
  one-pixel read-back.

Writes ``step03_study_mipmaps.json``, ``.md`` (the table) and ``.png`` (error against frame time) to ``--out``.
Runs headless and prints progress.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, frame_ms, markdown_table, run_info, write_study

STEM = "step03_study_mipmaps"
SAMPLERS = {"nearest": ("nearest", False, 1), "linear": ("linear", False, 1), "nearest + mipmaps": ("nearest", True, 1),
            "trilinear (linear + mipmaps)": ("linear", True, 1), "anisotropic 4x": ("linear", True, 4),
            "anisotropic 16x": ("linear", True, 16)}
TEXTURE_SIZE, CHECK_TEXELS = 512, 32
DARK, LIGHT = 0.1, 0.9
METRES_PER_REPEAT = 4.0
EYE = np.array([0.0, 2.0, 0.0])
TARGET = np.array([0.0, 0.0, -4.0])
FOV = 45.0
FLOOR = (-80.0, 80.0, -400.0, 10.0)  # x from, x to, z from, z to: the floor fills every pixel
SHADERS = Path(__file__).resolve().parent / "shaders"


def checker_pixels() -> np.ndarray:
    """The (512, 512, 4) uint8 sRGB checkerboard; row 0 is the image's top row (v = 0)."""
    i = np.arange(TEXTURE_SIZE) // CHECK_TEXELS
    odd = (i[:, None] + i[None, :]) % 2 == 1
    value = np.where(odd, round(LIGHT * 255), round(DARK * 255)).astype(np.uint8)
    return np.dstack([value, value, value, np.full_like(value, 255)])


def floor_mesh():
    from gandalf_core.resources import MeshData

    x0, x1, z0, z1 = FLOOR
    p = np.array([[x0, 0.0, z1], [x1, 0.0, z1], [x1, 0.0, z0], [x0, 0.0, z0]])
    uvs = np.c_[p[:, 0], p[:, 2]] / METRES_PER_REPEAT
    return MeshData(p, normals=np.tile([0.0, 1.0, 0.0], (4, 1)), uvs=uvs, indices=[0, 1, 2, 0, 2, 3], name="floor")


def floor_scene(sampler: str):
    from gandalf_core import Scene, TransformComponent
    from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
    from gandalf_core.math import look_at_rotation
    from gandalf_core.resources import MaterialData, TextureData

    from .scene import SHADER

    filter_, mipmaps, anisotropy = SAMPLERS[sampler]
    scene = Scene(f"mipmaps {sampler}")
    scene.assets.mesh("floor", floor_mesh())
    scene.assets.texture("checker", TextureData.from_array(checker_pixels(), filter=filter_, mipmaps=mipmaps,
                                                           anisotropy=anisotropy, wrap="repeat",
                                                           name=f"checker {sampler}"))
    scene.assets.material("floor", MaterialData(SHADER, ["checker"], color=(1.0, 1.0, 1.0)))
    scene.create_entity(TransformComponent(), MeshComponent("floor"), MaterialComponent("floor"))
    scene.create_entity(TransformComponent(EYE, quaternion=look_at_rotation(EYE, TARGET)),
                        CameraComponent(FOV, 0.1, 1000.0))
    return scene


def reference(size: tuple[int, int], ss: int = 16) -> np.ndarray:
    """The (H, W) 8-bit sRGB value of each pixel's box-filtered floor, from ``ss``² rays per pixel (float64)."""
    from gandalf_core.resources import linear_to_srgb, srgb_to_linear

    w, h = size
    forward = (TARGET - EYE) / np.linalg.norm(TARGET - EYE)
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    tan = np.tan(np.radians(FOV) / 2)
    texels = srgb_to_linear(checker_pixels()[..., 0].astype(np.float64) / 255.0)
    sub = (np.arange(ss) + 0.5) / ss
    out = np.empty((h, w))
    xs = ((np.arange(w)[:, None] + sub[None, :]).ravel() / w * 2.0 - 1.0) * tan * w / h  # (w·ss,)
    for row in range(h):
        ys = (1.0 - (row + sub) / h * 2.0) * tan  # (ss,)
        d = forward + xs[None, :, None] * right + ys[:, None, None] * up  # (ss, w·ss, 3)
        t = -EYE[1] / d[..., 1]
        hit = EYE + t[..., None] * d
        u = hit[..., 0] / METRES_PER_REPEAT
        v = hit[..., 2] / METRES_PER_REPEAT
        col = np.floor(u * TEXTURE_SIZE).astype(np.int64) % TEXTURE_SIZE
        tex_row = np.floor(v * TEXTURE_SIZE).astype(np.int64) % TEXTURE_SIZE
        values = texels[tex_row, col].reshape(ss, w, ss)
        out[row] = values.mean(axis=(0, 2))
    return np.round(linear_to_srgb(out) * 255.0)


def _app(backend: str, size: tuple[int, int]):
    from gandalf_core import Application

    from .scene import SHADER

    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    if backend == "opengl":
        app.renderer.shaders.build(SHADER, SHADERS / "textured.vert", SHADERS / "textured.frag")
    else:
        app.renderer.shaders.build(SHADER, SHADERS / "textured.wgsl")
    return app


def measure(backend: str, sampler: str, size: tuple[int, int], frames: int, repeats: int) -> tuple[np.ndarray, float]:
    """(the picture, median ms per frame)."""
    with _app(backend, size) as app:
        app.add_scene(floor_scene(sampler))
        app.run(frames=2)
        picture = app.capture()
        return picture, frame_ms(app, frames, repeats)


def errors(picture: np.ndarray, expected: np.ndarray) -> dict:
    """Mean absolute 8-bit error (red channel: the picture is grey) over all, the far (top) and near halves."""
    diff = np.abs(picture[..., 0].astype(np.float64) - expected)
    half = diff.shape[0] // 2
    return {"mean_error": float(diff.mean()), "far_error": float(diff[:half].mean()),
            "near_error": float(diff[half:].mean())}


def run_study(backends, size, ss: int, frames: int, repeats: int) -> dict:
    print(f"reference: {ss}x{ss} rays per pixel at {size[0]}x{size[1]} ...", flush=True)
    expected = reference(size, ss)
    rows = []
    for backend in backends:
        for sampler in SAMPLERS:
            picture, ms = measure(backend, sampler, size, frames, repeats)
            row = {"backend": backend, "sampler": sampler, **errors(picture, expected), "frame_ms": ms}
            rows.append(row)
            print(f"[{backend}] {sampler:28s} error {row['mean_error']:6.2f} (far {row['far_error']:6.2f}, near "
                  f"{row['near_error']:5.2f}) 8-bit, {ms:.2f} ms/frame", flush=True)
    return {"rows": rows, "size": list(size), "supersampling": ss,
            "reference": f"float64 numpy, {ss}x{ss} rays per pixel box-filtering the texels in linear light",
            "time": f"median of {repeats} runs of the mean of {frames} frames (1-pixel read-back per frame)",
            "anisotropic": "not offered by TextureData: not measured",
            **run_info()}


def markdown(result: dict) -> str:
    return markdown_table(
        ["API", "sampler", "mean error (8-bit)", "far half", "near half", "frame time (ms)"],
        ([r["backend"], r["sampler"], f"{r['mean_error']:.2f}", f"{r['far_error']:.2f}", f"{r['near_error']:.2f}",
          f"{r['frame_ms']:.2f}"] for r in result["rows"]), left=2)


def plot(result: dict, path: Path) -> None:
    fig, ax = figure(figsize=(8.4, 4.2))
    markers = {"opengl": "o", "webgpu": "s"}
    colours = dict(zip(SAMPLERS, ("tab:red", "tab:orange", "tab:blue", "tab:green", "tab:purple", "tab:brown")))
    for r in result["rows"]:
        ax.scatter(r["frame_ms"], r["mean_error"], marker=markers[r["backend"]], color=colours[r["sampler"]],
                   label=f"{r['backend']}: {r['sampler']}")
    ax.set_yscale("log")
    label_axes(ax, "frame time (ms, median)", "mean error against the box-filtered reference (8-bit)",
               f"Checkerboard floor at a grazing angle, {result['size'][0]}×{result['size'][1]}", legend=None)
    ax.legend(fontsize=7, bbox_to_anchor=(1.02, 1.0), loc="upper left")
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    parser = StudyParser("step03_textures.study_mipmaps", __doc__, outputs=f"{STEM}.json/.md/.png",
                         quick="96x72 pixels, 8x8 reference rays, fewer frames", size=((320, 240), (96, 72)),
                         frames=(20, 3), repeats=(5, 2))
    parser.add_argument("--ss", type=int, default=None, help="reference rays per pixel side (default 16, quick 8)")
    args = parser.parse_args(argv)
    ss = args.ss or (8 if args.quick else 16)
    if ss < 1:
        parser.error("--ss must be at least 1")
    print(f"mipmap study: {len(SAMPLERS)} samplers, {', '.join(args.backends)}, {args.size[0]}x{args.size[1]}",
          flush=True)
    result = run_study(args.backends, args.size, ss, args.frames, args.repeats)
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
