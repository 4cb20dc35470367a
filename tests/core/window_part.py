"""Open one part (a step, concept or technique) in a real window in each API, run a few frames, resize the
window, run again and close: ``python tests/core/window_part.py step07_advanced.pbr_model [opengl webgpu]``.

Run by ``test_window_parts.py`` in a process of its own per part (a driver abort cannot take pytest down, and
both APIs share the process's imports). Prints one line ``<part> <api> ok <w>x<h>`` per API, or the error and
exits 1.
"""

from __future__ import annotations

import importlib
import sys
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # this checkout's packages, not an installed copy

#: The launcher's smallest useful window and the size it is resized to.
SIZE, RESIZED = (96, 72), (120, 80)


def open_part(part: str, api: str) -> str:
    variant = importlib.import_module(f"{part}.{api}")
    with variant.create_app(headless=False, width=SIZE[0], height=SIZE[1]) as app:
        if app.window is None:
            raise RuntimeError("no window was opened (is there a display?)")
        app.run(frames=2)
        app.window._glfw.set_window_size(app.window.handle, *RESIZED)
        for _ in range(30):  # the X server answers asynchronously
            app.step()
            if (app.renderer.width, app.renderer.height) == RESIZED:
                break
        got = (app.renderer.width, app.renderer.height)
        if got != RESIZED:
            raise RuntimeError(f"the window was resized to {RESIZED} but the renderer draws {got}")
        app.run(frames=2)
        frame = app.capture()
        if frame.shape[:2] != (RESIZED[1], RESIZED[0]):
            raise RuntimeError(f"the frame after the resize is {frame.shape}, expected {RESIZED[1]}x{RESIZED[0]}")
    return f"{got[0]}x{got[1]}"


def main(argv: list[str]) -> int:
    part, apis = argv[0], argv[1:] or ["opengl", "webgpu"]
    status = 0
    for api in apis:
        try:
            print(f"{part} {api} ok {open_part(part, api)}", flush=True)
        except Exception:  # noqa: BLE001 - reported whole, the other API still runs
            print(f"{part} {api} FAILED\n{traceback.format_exc()}", flush=True)
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
