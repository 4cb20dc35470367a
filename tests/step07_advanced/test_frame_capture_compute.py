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
