"""A frame capture of step 07's showcase lists its particle kernel's compute dispatch as the frame's first pass, in
both APIs, before the shadow map and the scene's passes; the scene's draws are exactly the renderer's draw count."""

from __future__ import annotations

import importlib

from step07_advanced.editor.frame_inspector.capture import capture_frame


def test_the_showcase_capture_begins_with_its_compute_dispatch(backend: str) -> None:
    module = importlib.import_module(f"step07_advanced.showcase.{backend}")
    app = module.create_app(headless=True, width=96, height=72)
    try:
        app.run(frames=2)
        capture = capture_frame(app)
        assert capture.pass_names()[:2] == ["compute", "shadow"]
        (dispatch,) = capture.passes[0].draws
        assert dispatch.shader == "particles" and dispatch.state["workgroups"][0] >= 1
        assert dispatch.buffers[0]["name"] == "particles" and dispatch.buffers[0]["bytes"] > 0
        drawn = [d for p in capture.passes if p.name != "compute" for d in p.draws]
        assert len(drawn) == app.renderer.stats["draw_calls"]
    finally:
        app.close()


def test_a_capture_lists_and_times_the_gpu_motion_kernel(backend: str) -> None:
    """The GPU-driven motion pass is a dispatch of the frame like the showcase's: listed first, with its buffers and
    one workgroup per 64 rows, and timed where the timer has timestamps (a benchmark reads its milliseconds)."""
    from gandalf_core import Application
    from step07_advanced.gpu_motion.motion import WORKGROUP
    from step07_advanced.gpu_motion.scene import build_scene

    app = Application(backend, 64, 48, headless=True, fixed_dt=1 / 60)
    try:
        app.add_scene(build_scene(path="gpu", count=100))
        app.step()
        capture = capture_frame(app, describe=False)
        assert capture.pass_names()[0] == "compute", capture.pass_names()
        (dispatch,) = capture.passes[0].draws
        assert dispatch.shader == "motion" and dispatch.state["workgroups"][0] == -(-100 // WORKGROUP)
        assert [b["name"] for b in dispatch.buffers] == ["instances", "motion", "moved"]
        assert all(b["bytes"] > 0 for b in dispatch.buffers)
    finally:
        app.close()
