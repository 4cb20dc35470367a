"""The shadow-mapping study: ``python -m step07_advanced.showcase.study_shadows --out DIR [--quick]
[--backends opengl webgpu]``.

Shadow mapping has three quality knobs: the shadow map's size, the percentage-closer filter's taps and the depth
bias. This study sets the error of each against a ray-traced shadow, and the frame time, in both APIs.

* the scene: a floor under a sun (``towards`` (1, 2, 0.6), ``shadow_extent`` 16, ``shadow_depth`` 40: a box for
  a larger world than the boxes need, so one texel of a small map is coarse) with three boxes: a cube floating
  between heights 1 and 2, a box standing on the floor (its shadow touches it: too much bias detaches it,
  "peter-panning") and a thin post (0.16 m: a small map loses it); seen straight down through an orthographic
  camera 8 m high, at ``--size`` (default 320×240);
* the surfaces output the lit fraction itself (``shaders/study_shadow.*``: the engine's lookup of ``shadow.*``
  with the filter radius r as a material parameter, (2r + 1)² taps; the engine's own shaders use r = 1);
* the knobs, one at a time around the engine's defaults (2048² map, 3 × 3 taps, ``shadow_bias`` 1): map sizes
  256–4096, filter radius 0–3, ``LightComponent.shadow_bias`` 0–32. The map size is a constant of the engine
  (``SHADOW_MAP_SIZE``): the study sets it for its own renderers only, through :func:`shadow_map_size`;
* the reference: the exact shadow of the boxes, ray-traced in float64 numpy from each floor pixel's centre towards
  the sun (pixels whose view hits a box top are left out);
* the errors, over the floor pixels: the pixels whose lit/shadowed state (lit fraction ≥ 0.5) differs from the
  reference, as a share of the true shadow's area, split into **false shadow** (lit in the reference: acne,
  blurred or blocky edges) and **missing shadow** (shadowed in the reference: peter-panning, lost thin casters);
* the time: the median over ``--repeats`` runs of the mean frame time (shadow pass + main pass) of ``--frames``
  frames, each waited for with a one-pixel read-back.

Writes ``step07_study_shadows.json``, ``.md`` (the table) and ``.png`` (error against frame time for the map size and
the taps, against the bias itself for the bias, which costs nothing) to
``--out``. Runs headless and prints progress.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, save_figure
from gandalf_tools.studies import StudyParser, frame_ms, markdown_table, run_info, write_study

from .shaders import STUDY_SHADOW_MATERIAL

STEM = "step07_study_shadows"
SHADER_DIR = Path(__file__).resolve().parent / "shaders"
TOWARDS = np.array([1.0, 2.0, 0.6])
VIEW_HEIGHT = 8.0
EXTENT, DEPTH = 16.0, 40.0
#: (centre, half sizes) of the boxes that cast shadows.
BOXES = (((-1.6, 1.5, -0.8), (0.5, 0.5, 0.5)),   # floating cube
         ((1.2, 0.6, 0.9), (0.45, 0.6, 0.45)),   # standing on the floor
         ((-0.2, 1.1, 1.6), (0.08, 1.1, 0.08)))  # a thin post
DEFAULTS = {"map_size": 2048, "pcf_radius": 1, "bias": 1.0}
SWEEPS = {"map_size": (256, 512, 1024, 2048, 4096), "pcf_radius": (0, 1, 2, 3),
          "bias": (0.0, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0)}
QUICK_SWEEPS = {"map_size": (256, 2048), "pcf_radius": (0, 1, 3), "bias": (0.0, 1.0, 32.0)}
LIT_THRESHOLD = 188  # sRGB byte of lit fraction 0.5


@contextlib.contextmanager
def shadow_map_size(size: int) -> Iterator[None]:
    """Renderers created inside use ``size``² shadow maps (the engine's constant, set for this study only)."""
    import gandalf_core.render.opengl.renderer as gl_renderer
    import gandalf_core.render.webgpu.renderer as wgpu_renderer
    import gandalf_core.systems.light_system as light_system

    modules = (gl_renderer, wgpu_renderer, light_system)
    saved = [module.SHADOW_MAP_SIZE for module in modules]
    for module in modules:
        module.SHADOW_MAP_SIZE = int(size)
    try:
        yield
    finally:
        for module, value in zip(modules, saved):
            module.SHADOW_MAP_SIZE = value


def shadow_scene(pcf_radius: int, bias: float):
    from gandalf_core import ClearColorComponent, Scene, TransformComponent
    from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
    from gandalf_core.math import look_at_rotation
    from gandalf_core.resources import MaterialData, cube, plane

    scene = Scene("shadow study")
    scene.assets.mesh("floor", plane(12.0, 1))
    scene.assets.mesh("cube", cube(1.0))
    scene.assets.material("white", MaterialData("study_shadow", color=(1.0, 1.0, 1.0),
                                                params={"pcf": float(pcf_radius)}))
    scene.create_entity(ClearColorComponent((0.0, 0.0, 0.0)))
    scene.create_entity(TransformComponent(), MeshComponent("floor"), MaterialComponent("white"))
    for centre, half in BOXES:
        scene.create_entity(TransformComponent(centre, scale=tuple(2.0 * h for h in half)), MeshComponent("cube"),
                            MaterialComponent("white"))
    sun = TOWARDS / np.linalg.norm(TOWARDS) * 10.0
    scene.create_entity(TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", (1, 1, 1), 1.0, cast_shadows=True, shadow_extent=EXTENT,
                                       shadow_depth=DEPTH, shadow_bias=bias))
    scene.create_entity(TransformComponent((0.0, 10.0, 0.0), rotation=(-90, 0, 0)),
                        CameraComponent(near=0.1, far=50.0, projection="orthographic", height=VIEW_HEIGHT))
    return scene


def reference(size: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """(shadowed (H, W), floor (H, W)): the ray-traced shadow at each pixel centre's floor point, and which pixels
    see the floor (not a box top, one pixel of margin)."""
    w, h = size
    scale = h / VIEW_HEIGHT
    x = (np.arange(w) + 0.5 - w / 2) / scale
    z = (np.arange(h) + 0.5 - h / 2) / scale
    px, pz = np.meshgrid(x, z)
    to_sun = TOWARDS / np.linalg.norm(TOWARDS)
    shadowed = np.zeros((h, w), dtype=bool)
    floor = np.ones((h, w), dtype=bool)
    margin = 1.0 / scale
    with np.errstate(divide="ignore", invalid="ignore"):
        for centre, half in BOXES:
            c, e = np.asarray(centre), np.asarray(half)
            floor &= ~((np.abs(px - c[0]) < e[0] + margin) & (np.abs(pz - c[2]) < e[2] + margin))
            # Slab test of the ray p + t·l (t > 0) from the floor point p = (x, 0, z) against the box.
            t_near, t_far = np.full(px.shape, -np.inf), np.full(px.shape, np.inf)
            for origin, axis in ((px, 0), (np.zeros_like(px), 1), (pz, 2)):
                t1 = (c[axis] - e[axis] - origin) / to_sun[axis]
                t2 = (c[axis] + e[axis] - origin) / to_sun[axis]
                t_near = np.maximum(t_near, np.minimum(t1, t2))
                t_far = np.minimum(t_far, np.maximum(t1, t2))
            shadowed |= (t_near <= t_far) & (t_far > 0.0)
    return shadowed, floor


def errors(picture: np.ndarray, shadowed: np.ndarray, floor: np.ndarray) -> dict:
    rendered_shadow = picture[..., 0] < LIT_THRESHOLD
    n = (shadowed & floor).sum()  # shares of the true shadow's area
    false_shadow = float((rendered_shadow & ~shadowed & floor).sum() / n)
    missing = float((~rendered_shadow & shadowed & floor).sum() / n)
    return {"wrong_share": false_shadow + missing, "false_shadow_share": false_shadow, "missing_shadow_share": missing}


def _app(backend: str, size: tuple[int, int]):
    from gandalf_core import Application

    app = Application(backend, *size, headless=True, fixed_dt=1 / 60)
    if backend == "opengl":
        app.renderer.shaders.build("study_shadow", SHADER_DIR / "study_shadow.vert", SHADER_DIR / "study_shadow.frag",
                                   material=STUDY_SHADOW_MATERIAL)
    else:
        app.renderer.shaders.build("study_shadow", SHADER_DIR / "study_shadow.wgsl", material=STUDY_SHADOW_MATERIAL)
    return app


def measure(backend: str, case: dict, size: tuple[int, int], frames: int, repeats: int) -> tuple[np.ndarray, float]:
    """(the picture, median ms per frame) of one setting of the knobs."""
    with shadow_map_size(case["map_size"]), _app(backend, size) as app:
        app.add_scene(shadow_scene(case["pcf_radius"], case["bias"]))
        app.run(frames=2)
        picture = app.capture()
        return picture, frame_ms(app, frames, repeats)


def cases(sweeps: dict) -> list[dict]:
    """The defaults with one knob changed at a time (the defaults themselves once, under every knob's sweep)."""
    out = []
    for knob, values in sweeps.items():
        for value in values:
            out.append({"knob": knob, **DEFAULTS, knob: value})
    return out


def run_study(backends, sweeps, size, frames: int, repeats: int) -> dict:
    shadowed, floor = reference(size)
    rows = []
    for backend in backends:
        done: dict[tuple, tuple] = {}
        for case in cases(sweeps):
            key = (case["map_size"], case["pcf_radius"], case["bias"])
            if key not in done:
                done[key] = measure(backend, case, size, frames, repeats)
            picture, ms = done[key]
            row = {"backend": backend, **case, "taps": (2 * case["pcf_radius"] + 1) ** 2,
                   **errors(picture, shadowed, floor), "frame_ms": ms}
            rows.append(row)
            print(f"[{backend}] map {case['map_size']:4d}², {row['taps']:2d} taps, bias {case['bias']:4.2f}: wrong "
                  f"{100 * row['wrong_share']:5.2f} % (false shadow {100 * row['false_shadow_share']:5.2f} %, missing "
                  f"{100 * row['missing_shadow_share']:5.2f} %), {ms:.2f} ms/frame", flush=True)
    return {"rows": rows, "size": list(size), "floor_pixels": int(floor.sum()),
            "reference_shadowed_share": float(shadowed[floor].mean()), "defaults": DEFAULTS,
            "reference": "float64 numpy ray-traced shadow of the boxes at each floor pixel centre",
            "time": f"median of {repeats} runs of the mean of {frames} frames (1-pixel read-back per frame)",
            **run_info()}


def markdown(result: dict) -> str:
    return markdown_table(
        ["API", "knob", "map size", "taps", "bias", "wrong (% of the shadow)", "false shadow (%)", "missing shadow (%)",
         "frame time (ms)"],
        ([r["backend"], r["knob"], r["map_size"], r["taps"], f"{r['bias']:g}", f"{100 * r['wrong_share']:.2f}",
          f"{100 * r['false_shadow_share']:.2f}", f"{100 * r['missing_shadow_share']:.2f}", f"{r['frame_ms']:.2f}"]
         for r in result["rows"]), left=2)


def plot(result: dict, path: Path) -> None:
    knobs = list(dict.fromkeys(r["knob"] for r in result["rows"]))
    fig, axes = figure(1, len(knobs), figsize=(4.2 * len(knobs), 3.8), squeeze=False)
    label = {"map_size": lambda r: f"{r['map_size']}", "pcf_radius": lambda r: f"{r['taps']}",
             "bias": lambda r: f"{r['bias']:g}"}
    titles = {"map_size": "shadow map size (labels: texels a side)", "pcf_radius": "PCF taps (labels: taps)",
              "bias": "depth bias (labels: shadow_bias)"}
    for ax, knob in zip(axes[0], knobs):
        # The bias costs nothing (one subtraction): its panel is drawn against the bias itself, not the time.
        x_of = (lambda r: r["bias"]) if knob == "bias" else (lambda r: r["frame_ms"])
        for backend in dict.fromkeys(r["backend"] for r in result["rows"]):
            mine = [r for r in result["rows"] if r["backend"] == backend and r["knob"] == knob]
            ax.semilogy([x_of(r) for r in mine], [max(100 * r["wrong_share"], 1e-2) for r in mine], "o-",
                        ms=4, label=f"{backend}: wrong")
            ax.semilogy([x_of(r) for r in mine], [max(100 * r["missing_shadow_share"], 1e-2) for r in mine],
                        "x:", ms=4, label=f"{backend}: missing shadow")
            for r in mine:
                ax.annotate(label[knob](r), (x_of(r), max(100 * r["wrong_share"], 1e-2)), fontsize=6,
                            xytext=(3, 3), textcoords="offset points")
        ax.set_title(titles[knob], fontsize=9)
        if knob == "bias":
            ax.set_xscale("symlog", linthresh=0.25)
            ax.set_xlabel("LightComponent.shadow_bias (no effect on time)")
        else:
            ax.set_xlabel("frame time (ms, median)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("pixels in the wrong state (% of the shadow's area)")
    axes[0][-1].legend(fontsize=7)
    fig.suptitle(f"Shadow mapping against a ray-traced shadow ({result['size'][0]}×{result['size'][1]})",
                 fontsize=10)
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    parser = StudyParser("step07_advanced.showcase.study_shadows", __doc__, outputs=f"{STEM}.json/.md/.png",
                         quick="fewer settings per knob, fewer frames", size=((320, 240), (320, 240)),
                         frames=(10, 3), repeats=(5, 2))
    args = parser.parse_args(argv)
    if min(args.size) < 8:
        parser.error("--size must be at least 8 8")
    size, frames, repeats = args.size, args.frames, args.repeats
    sweeps = QUICK_SWEEPS if args.quick else SWEEPS
    print(f"shadow study: {len(cases(sweeps))} settings, {', '.join(args.backends)}, {size[0]}x{size[1]}", flush=True)
    result = run_study(args.backends, sweeps, size, frames, repeats)
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
