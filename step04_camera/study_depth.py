"""The depth-precision study: ``python -m step04_camera.study_depth --out DIR [--quick] [--backends opengl webgpu]``.

Two parallel planes lean back 40° in front of the camera: a red one at distance ``d`` and the same plane in green
``s`` further away along the view axis. The red one is
drawn first, so only the depth test keeps it in front: when both round to the same stored depth the green plane
(drawn second, ``less-equal``) shows through — z-fighting. What is the smallest separation ``s`` that renders
cleanly, against ``d``, for each depth mapping?

* the mappings: standard depth and reverse-Z (near → 1, far → 0), with several near/far planes (reverse-Z also
  with an infinite far plane); both APIs use a 32-bit float depth buffer (OpenGL: ``depth32f`` and clip control
  for reverse-Z, WebGPU: ``depth32float``);
* the measurement: for each ``d`` a bisection over ``log2(s / d)`` (to ``--resolution`` octaves) for the smallest
  ``s`` at which no pixel of the red plane's middle shows green with the red plane at d, 1.0013 d and 1.0029 d
  (one distance alone can round luckily), rendered by the engine at 64×48;
* the bound: one step of the float32 depth buffer at ``d`` turned into distance,
  ``ulp(z(d)) / |dz/dd|`` with ``z`` the window depth in [0, 1], and one float32 step of the position ``d``
  itself (``ulp(d)``, the vertex data's own precision): the larger of the two. Standard depth crowds its float
  values near 1 and loses precision as ``d² / near``; reverse-Z pairs the float's dense values near 0 with the
  far distances, so its step grows only as ``d`` (relative precision about 1e-7, whatever near is). Where the
  depth passes through OpenGL's clip range [-1, 1] on its way to the buffer (wgpu's OpenGL backend writes 2z - 1
  and the viewport halves it back), the stored value keeps only the precision of 2z - 1, a number near 1 in
  size: there one step is ``max(ulp(2z - 1) / 2, ulp(z))`` and reverse-Z gains nothing;
* the time: a depth mapping costs nothing per pixel — the study reports the median frame time of the two planes
  per mapping for completeness.

Writes ``step04_study_depth.json``, ``.md`` (the table) and ``.png`` (smallest separation against distance, with
the bounds) to ``--out``. Runs headless and prints progress.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from gandalf_tools.plots import figure, label_axes, save_figure
from gandalf_tools.studies import StudyParser, frame_ms, groups, markdown_table, run_info, write_study

STEM = "step04_study_depth"
#: (label, near, far, reverse_z)
MAPPINGS = (("standard, near 0.1, far 1e4", 0.1, 1e4, False),
            ("standard, near 1, far 1e4", 1.0, 1e4, False),
            ("reverse-Z, near 0.1, far 1e4", 0.1, 1e4, True),
            ("reverse-Z, near 0.1, far inf", 0.1, math.inf, True))
QUICK_MAPPINGS = (MAPPINGS[0], MAPPINGS[2])
SIZE = (64, 48)
#: Both planes lean back by this angle: their depth then spans many depth-buffer steps across the picture, so a
#: separation passes only when it is clean everywhere, not because two flat planes happen to round apart.
TILT_DEGREES = 40.0
#: The front plane is tried at d times each of these: where depths round is a matter of luck at one distance.
JITTERS = (1.0, 1.0013, 1.0029)
SHADER_DIR = Path(__file__).resolve().parent / "shaders"


def distances(near: float, far: float, per_decade: int) -> np.ndarray:
    """Plane distances from 10 · near up to a quarter of far (or 1e5), ``per_decade`` a decade."""
    top = min(far / 4.0, 1e5)
    lo, hi = math.log10(10.0 * near), math.log10(top)
    return np.logspace(lo, hi, max(2, round((hi - lo) * per_decade) + 1))


def window_depth(d: np.ndarray, near: float, far: float, reverse_z: bool) -> np.ndarray:
    """The [0, 1] window depth of eye distance ``d`` (float64)."""
    r = near / far
    z = (1.0 - near / d) / (1.0 - r)  # standard: 0 at near, 1 at far
    return 1.0 - z if reverse_z else z


def bound(d: np.ndarray, near: float, far: float, reverse_z: bool, through_gl_range: bool = False) -> np.ndarray:
    """The analytic smallest separation: max(one float32 depth step as distance, one float32 step of d).
    ``through_gl_range``: the depth is stored as (2z - 1 + 1) / 2, each part rounded to float32."""
    z = window_depth(d, near, far, reverse_z)
    slope = near / (d * d) / (1.0 - near / far)  # |dz/dd|, the same for both mappings
    step = np.spacing(np.abs(z).astype(np.float32)).astype(np.float64)
    if through_gl_range:
        step = np.maximum(step, np.spacing(np.abs(2.0 * z - 1.0).astype(np.float32)).astype(np.float64) / 2.0)
    depth_step = step / slope
    return np.maximum(depth_step, np.spacing(d.astype(np.float32)).astype(np.float64))


def _scene(near: float, far: float, reverse_z: bool):
    from gandalf_core import ClearColorComponent, Scene, TransformComponent
    from gandalf_core.components import CameraComponent, MaterialComponent, MeshComponent
    from gandalf_core.resources import MaterialData, MeshData, TextureData

    scene = Scene("depth")
    p = np.array([[-0.5, -0.5, 0.0], [0.5, -0.5, 0.0], [0.5, 0.5, 0.0], [-0.5, 0.5, 0.0]])
    uvs = np.array([[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]])
    scene.assets.mesh("quad", MeshData(p, normals=np.tile([0.0, 0.0, 1.0], (4, 1)), uvs=uvs,
                                       indices=[0, 1, 2, 0, 2, 3]))
    white = np.full((1, 1, 4), 255, dtype=np.uint8)
    scene.assets.texture("white", TextureData.from_array(white, filter="nearest", mipmaps=False))
    # Batches draw in material-name order: the red (near) plane first, so only the depth test keeps it in front.
    scene.assets.material("a_red", MaterialData("unlit", ["white"], color=(1.0, 0.0, 0.0)))
    scene.assets.material("b_green", MaterialData("unlit", ["white"], color=(0.0, 1.0, 0.0)))
    front = scene.create_entity(TransformComponent(), MeshComponent("quad"), MaterialComponent("a_red"))
    back = scene.create_entity(TransformComponent(), MeshComponent("quad"), MaterialComponent("b_green"))
    scene.create_entity(TransformComponent(), CameraComponent(60.0, near, far, reverse_z=reverse_z))
    scene.create_entity(ClearColorComponent((0.0, 0.0, 0.0, 1.0)))
    return scene, front, back


class DepthRig:
    """One app and scene of a mapping; :meth:`fights` places the planes and says whether green shows."""

    def __init__(self, backend: str, near: float, far: float, reverse_z: bool) -> None:
        from gandalf_core import Application, TransformComponent
        from gandalf_core.math import quat_from_axis_angle

        self.app = Application(backend, *SIZE, headless=True, fixed_dt=1 / 60)
        #: Whether this implementation stores depth through OpenGL's clip range (see :func:`bound`).
        self.through_gl_range = False
        if backend == "opengl":
            self.app.renderer.shaders.build("unlit", SHADER_DIR / "unlit.vert", SHADER_DIR / "unlit.frag")
        else:
            from gandalf_core.render.webgpu.device import depth_through_gl_range

            self.through_gl_range = depth_through_gl_range(self.app.renderer.adapter)
            self.app.renderer.shaders.build("unlit", SHADER_DIR / "unlit.wgsl")
        scene, front, back = _scene(near, far, reverse_z)
        self.app.add_scene(scene)
        self.front = scene.get_component(front, TransformComponent)
        self.back = scene.get_component(back, TransformComponent)
        tilt = quat_from_axis_angle((1.0, 0.0, 0.0), math.radians(TILT_DEGREES))
        self.front.quaternion = tilt
        self.back.quaternion = tilt

    def place(self, d: float, s: float) -> None:
        self.front.translation = (0.0, 0.0, -d)
        self.front.scale = (0.6 * d, 0.6 * d, 1.0)
        self.back.translation = (0.0, 0.0, -(d + s))
        self.back.scale = (0.6 * d, 0.6 * d, 1.0)  # the same triangles, moved: at s = 0 the depths tie exactly

    def fights(self, d: float, s: float) -> bool:
        """True when, at any of three nearby distances, a pixel of the red plane's middle shows the green plane
        (or no red is drawn at all): a separation counts as clean only when it does not depend on luck."""
        for jitter in JITTERS:
            self.place(d * jitter, s)
            self.app.run(frames=1)
            image = self.app.capture()
            h, w = image.shape[:2]
            middle = image[int(h * 0.35):int(h * 0.65), int(w * 0.35):int(w * 0.65)]
            if (middle[..., 1] > 128).any() or not (middle[..., 0] > 128).all():
                return True
        return False

    def frame_ms(self, frames: int, repeats: int) -> float:
        return frame_ms(self.app, frames, repeats)

    def close(self) -> None:
        self.app.close()


def smallest_separation(rig: DepthRig, d: float, far: float, resolution: float) -> float | None:
    """The smallest clean ``s`` (bisection over log2(s / d) in [-40, log2 of the room before far]), or None."""
    hi = math.log2(min(1.0, 0.9 * (far - d) / d)) if math.isfinite(far) else 0.0
    if rig.fights(d, d * 2.0**hi):
        return None
    lo = -40.0
    while hi - lo > resolution:
        mid = 0.5 * (lo + hi)
        if rig.fights(d, d * 2.0**mid):
            lo = mid
        else:
            hi = mid
    return d * 2.0**hi


def run_study(backends, mappings, per_decade: int, resolution: float, frames: int, repeats: int) -> dict:
    rows, timing = [], []
    for backend in backends:
        for label, near, far, reverse_z in mappings:
            rig = DepthRig(backend, near, far, reverse_z)
            try:
                for d in distances(near, far, per_decade):
                    s = smallest_separation(rig, float(d), far, resolution)
                    b = float(bound(np.array([d]), near, far, reverse_z, rig.through_gl_range)[0])
                    rows.append({"backend": backend, "mapping": label, "near": near,
                                 "far": far if math.isfinite(far) else "inf", "reverse_z": reverse_z,
                                 "distance": float(d), "min_separation": s, "bound": b})
                    shown = "none works" if s is None else f"{s:.3e}"
                    print(f"[{backend}] {label:30s} d = {d:9.3g}: smallest clean separation {shown} "
                          f"(float32 bound {b:.3e})", flush=True)
                rig.place(10.0 * near, 1.0 * near)
                ms = rig.frame_ms(frames, repeats)
                timing.append({"backend": backend, "mapping": label, "frame_ms": ms})
                print(f"[{backend}] {label:30s} {ms:.2f} ms/frame", flush=True)
            finally:
                rig.close()
    return {"rows": rows, "timing": timing, "size": list(SIZE), "resolution_octaves": resolution,
            "reference": "the float32 depth-buffer step at d as a distance, or float32's step of d if larger",
            "time": f"median of {repeats} runs of the mean of {frames} frames (two planes, 1-pixel read-back)",
            **run_info()}


def markdown(result: dict) -> str:
    """One row per distance: the smallest clean separation per API and mapping, and the bound, as s / d."""
    backends = list(dict.fromkeys(r["backend"] for r in result["rows"]))

    def separation(s: float | None, d: float) -> str:
        return "z-fights at every s" if s is None else f"{s:.2e} ({s / d:.1e})"

    text = ""
    for mapping, mine in groups(result["rows"], "mapping"):
        rows = []
        for d, at_d in groups(mine, "distance"):
            by_backend = {r["backend"]: r for r in at_d}
            rows.append([f"{d:.3g}", *(separation(by_backend[b]["min_separation"], d) for b in backends),
                         f"{at_d[0]['bound']:.2e} ({at_d[0]['bound'] / d:.1e})"])
        text += (f"**{mapping}** (smallest clean separation s, and s / d)\n\n"
                 + markdown_table(["d", *backends, "float32 bound"], rows, left=0) + "\n")
    timing = ([t["backend"], t["mapping"], f"{t['frame_ms']:.2f}"] for t in result["timing"])
    return text + markdown_table(["API", "mapping", "frame time (ms)"], timing, left=2)


def plot(result: dict, path: Path) -> None:
    fig, ax = figure(figsize=(7.0, 4.6))
    colours = dict(zip(dict.fromkeys(r["mapping"] for r in result["rows"]),
                       ("tab:red", "tab:orange", "tab:blue", "tab:green", "tab:purple")))
    styles = {"opengl": ("o", "-"), "webgpu": ("s", "--")}
    for (backend, mapping) in dict.fromkeys((r["backend"], r["mapping"]) for r in result["rows"]):
        mine = [r for r in result["rows"] if r["backend"] == backend and r["mapping"] == mapping
                and r["min_separation"] is not None]
        marker, line = styles[backend]
        ax.loglog([r["distance"] for r in mine], [r["min_separation"] for r in mine], marker=marker, ls=line, ms=4,
                  color=colours[mapping], label=f"{backend}: {mapping}")
    for mapping in colours:
        mine = [r for r in result["rows"] if r["mapping"] == mapping and r["backend"] == result["rows"][0]["backend"]]
        ax.loglog([r["distance"] for r in mine], [r["bound"] for r in mine], ":", color=colours[mapping], lw=1)
    label_axes(ax, "distance d of the front plane", "smallest separation without z-fighting",
               "Depth precision, float32 depth buffer (dotted: the float32 bound)", legend=7)
    save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    parser = StudyParser("step04_camera.study_depth", __doc__, outputs=f"{STEM}.json/.md/.png",
                         quick="two mappings, one distance a decade, coarser search", frames=(10, 10), repeats=(5, 5))
    parser.add_argument("--per-decade", type=int, default=None, help="distances a decade (default 2, quick 1)")
    parser.add_argument("--resolution", type=float, default=None,
                        help="bisection stops at this many octaves (default 0.25, quick 1)")
    args = parser.parse_args(argv)
    per_decade = args.per_decade or (1 if args.quick else 2)
    resolution = args.resolution or (1.0 if args.quick else 0.25)
    if per_decade < 1 or resolution <= 0:
        parser.error("--per-decade must be at least 1, --resolution positive")
    mappings = QUICK_MAPPINGS if args.quick else MAPPINGS
    print(f"depth study: {len(mappings)} mappings, {', '.join(args.backends)}, {per_decade} distances a decade",
          flush=True)
    result = run_study(args.backends, mappings, per_decade, resolution, args.frames, args.repeats)
    write_study(args.out, STEM, result, markdown(result), plot)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
