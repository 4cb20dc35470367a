"""The benchmarks' "two frames in flight" pacing (``bench_scenes.py --sync inflight``, ``raw_ceiling.py``
``SYNC=inflight``) waits for the frame before the last one, in both APIs: after frame N it holds frame N-1's pixel,
after ``drain()`` frame N's. Were it to wait for its own frame, or read a pixel before the frame that drew it had
finished, the fps it reports would be another measure than the page says."""

from __future__ import annotations

import sys
from pathlib import Path

from gandalf_core import Application, Scene
from gandalf_core.components import ClearColorComponent

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
import bench_common  # noqa: E402

COLOURS = [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (1.0, 1.0, 0.0)]


def _rgb(pixel: bytes | None) -> tuple[int, ...] | None:
    return None if pixel is None else tuple(pixel[:3])


def test_each_frame_waits_for_the_one_before(backend):
    with Application(backend, 32, 24, headless=True, fixed_dt=1 / 60) as app:
        scene = Scene("pacing")
        clear = ClearColorComponent(COLOURS[0])
        scene.create_entity(clear)
        app.add_scene(scene)
        r = app.renderer
        if backend == "opengl":
            pacer = bench_common.GLFramesInFlight(r.ctx, r.framebuffer, 16, 12)
        else:
            pacer = bench_common.WgpuFramesInFlight(r.device, lambda: r.frame_texture, 16, 12)
        expected = [tuple(round(255 * c) for c in colour) for colour in COLOURS]
        seen = []
        for colour in COLOURS:
            clear.color = colour
            app.step()
            pacer()
            seen.append(_rgb(pacer.pixel))
        assert seen == [None, *expected[:-1]], f"frame N must read frame N-1's pixel: {seen}"
        pacer.drain()
        assert _rgb(pacer.pixel) == expected[-1]
        assert tuple(r.read_pixel(16, 12)[:3]) == expected[-1]
