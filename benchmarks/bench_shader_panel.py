"""What the editor's shader panel costs on the CPU: its system's GUI hook per GUI frame, closed and open but idle
(on the selected cube's shader), and one look at its files (``poll``: a ``stat`` per file).

The scene is ``bench_editor.py``'s (scene5, 100 lit rotating cubes, a cube selected). The panels run on every frame
here (``gui_interval = 0``); an idle editor runs them at most 20 times a second, so the panel's share of a second is
at most 20 times its figure. One JSON line per backend: microseconds, medians of ``--frames`` GUI frames and of 2000
polls.

Run by hand, never in CI::

    python benchmarks/bench_shader_panel.py
    python benchmarks/bench_shader_panel.py --backends opengl --frames 500
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent))

from bench_common import backends_parser, per_backend  # noqa: E402
from bench_editor import make_app  # noqa: E402
from bench_scenes import renderer_name  # noqa: E402


def measure(backend: str, width: int, height: int, frames: int) -> dict:
    from gandalf_core.components import MeshComponent
    from step07_advanced.editor import enable_editor

    app = make_app(backend, width, height)
    app.run(frames=5)
    editor = enable_editor(app)
    editor.gui_interval = 0.0
    editor.selected = next(e for e, _ in app.scene.view(MeshComponent))
    system = editor.panel_system("shader")
    hook, spent = system.on_gui_update, []

    def timed() -> None:
        start = time.perf_counter()
        hook()
        spent.append(time.perf_counter() - start)

    system.on_gui_update = timed
    result = {"backend": backend, "renderer": renderer_name(app), "size": f"{width}x{height}", "frames": frames}
    for shown in (False, True):
        editor.show_panel("shader", shown)
        app.run(frames=10)
        spent.clear()
        app.run(frames=frames)
        result[f"us_per_gui_frame_{'open' if shown else 'closed'}"] = round(1e6 * statistics.median(spent), 1)
    polls = []
    for _ in range(2000):
        start = time.perf_counter()
        editor.shader_edits.poll()
        polls.append(time.perf_counter() - start)
    result["us_per_poll"] = round(1e6 * statistics.median(polls), 2)
    result["files_watched"] = len(editor.shader_edits.open(system.shader))
    editor.disable()
    app.close()
    return result


def main(argv: list[str] | None = None) -> int:
    per_backend(backends_parser(__doc__, 200, "GUI frames per state").parse_args(argv), measure)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
