"""What the editor costs: frame time without it, with five panels and with every panel, per backend.

The scene is ``bench_scenes.py``'s scene5 (100 lit rotating cubes) with a cube selected (the inspector shows its
fields). Modes: ``off`` (no editor); ``five`` (the menu bar and five panels: hierarchy, inspector, systems, stats,
console; no viewport); ``shader`` (those five and the shader panel, open and idle on the selected cube's shader: it
looks at the shader's files every time the panels run); ``frame`` (those five and the frame inspector, open and idle:
no frame captured); ``all`` (every panel that starts open, the viewport
included: it renders the scene into its texture, with a gizmo, and the frame under the panels is only cleared). The
modes run in the same process in many short rounds, each mode first, second, ... in turn, so that the drift of a
shared machine and of the GPU's clocks hits all alike; every frame ends with a 1-pixel read-back so the GPU has
finished it. One JSON line per backend: milliseconds per frame of each mode: the median frame over every round (with
no input, a frame that composites the cached GUI layer) and the mean frame (which also carries the few frames that
run the panels, every 1/20 s, and a shared machine's rare long frames); the milliseconds the editor adds and its
share of the frame (``cost_percent = added / frame with the editor``, from the medians; ``cost_percent_five_mean``
from the means; the paper's figure is 20-25 %); and the share of frames that ran the panels
(``panel_frames_percent``; see the editor page).

Run by hand, never in CI::

    python benchmarks/bench_editor.py                        # both backends, 1280x720, 21 rounds x 100 frames
    python benchmarks/bench_editor.py --size 640x480 --frames 200 --backends opengl
"""

from __future__ import annotations

import gc
import statistics
import sys
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent))

from bench_common import backends_parser, per_backend  # noqa: E402
from bench_scenes import build_scene, renderer_name  # noqa: E402

SHADERS = HERE / "shaders"


def make_app(backend: str, width: int, height: int) -> Any:
    """A headless app running scene5 with the benchmark's lit shader."""
    from gandalf_core import Application

    app = Application(backend, width, height, headless=True)
    if backend == "opengl":
        app.renderer.shaders.build("lit", SHADERS / "lit.vert", SHADERS / "lit.frag")
    else:
        app.renderer.shaders.build("lit", SHADERS / "lit.wgsl")
    scene, _mesh = build_scene(100, True, "cube", "batch")
    app.add_scene(scene)
    return app


def timed_frames(app: Any, frames: int) -> list[float]:
    """Seconds of each of ``frames`` frames, each waited for with a 1-pixel read-back."""
    r = app.renderer
    seconds = []
    clock = time.perf_counter
    for _ in range(frames):
        start = clock()
        app.step()
        r.read_pixel(r.width // 2, r.height // 2)
        seconds.append(clock() - start)
    return seconds


#: The panels of the "five" mode (the menu bar is on in every mode).
FIVE = ("hierarchy", "inspector", "systems", "stats", "console")


def measure(backend: str, width: int, height: int, frames: int, rounds: int) -> dict[str, Any]:
    from gandalf_core.components import MeshComponent
    from step07_advanced.editor import PANEL_KINDS, disable_editor, enable_editor

    app = make_app(backend, width, height)
    app.run(frames=20)  # build pipelines and resources before timing
    cube = next(e for e, _ in app.scene.view(MeshComponent))
    modes = ("off", "five", "shader", "frame", "all")
    times: dict[str, list[float]] = {mode: [] for mode in modes}
    panel_frames: dict[str, list[float]] = {mode: [] for mode in modes[1:]}  # share of frames that ran the panels
    for round_ in range(rounds):
        turn = round_ % len(modes)
        for mode in modes[turn:] + modes[:turn]:  # each mode first, second, ... in turn
            editor = None
            if mode != "off":
                editor = enable_editor(app)
                editor.selected = cube
                starts_open = {kind: editor.panel_visible(kind) for kind in PANEL_KINDS}
                for kind in PANEL_KINDS:
                    editor.show_panel(kind, kind in FIVE or kind == "menu" or (mode == "all" and starts_open[kind])
                                      or (mode in ("shader", "frame") and kind == mode))
                app.run(frames=10)  # the GUI's font atlas, buffers and the viewport's target, before timing
                ran = editor.gui_frames
            gc.collect()  # what the last mode left behind is not collected inside a timed round
            times[mode].extend(timed_frames(app, frames))
            if editor is not None:
                panel_frames[mode].append((editor.gui_frames - ran) / frames)
                disable_editor(app)
    result: dict[str, Any] = {"backend": backend, "renderer": renderer_name(app), "size": f"{width}x{height}",
                              "frames": frames, "rounds": rounds}
    for mode, seconds in times.items():
        result[f"ms_{mode}"] = round(1000.0 * statistics.median(seconds), 3)
        result[f"ms_{mode}_mean"] = round(1000.0 * statistics.fmean(seconds), 3)
    for mode in modes[1:]:
        for stat in ("", "_mean"):
            added = result[f"ms_{mode}{stat}"] - result[f"ms_off{stat}"]
            result[f"added_ms_{mode}{stat}"] = round(added, 3)
            result[f"cost_percent_{mode}{stat}"] = round(100.0 * added / result[f"ms_{mode}{stat}"], 1)
        result[f"panel_frames_percent_{mode}"] = round(100.0 * statistics.mean(panel_frames[mode]), 1)
    app.close()
    return result


def main(argv: list[str] | None = None) -> int:
    parser = backends_parser(__doc__, 100, "frames per mode and round")
    parser.add_argument("--rounds", type=int, default=21)
    args = parser.parse_args(argv)
    per_backend(args, measure, args.rounds)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
