"""The editor's frame inspector panel, headless in both APIs, driven by synthetic clicks.

Capture from the panel's button lists the viewport's passes and draws (the viewport's draw counter) and then the
editor's own GUI as an overlay pass; a click on the viewport with "pick on click" picks the entity under the pointer
and selects it; the texture viewer shows a chosen cube face as its texels. The panel starts hidden and, hidden,
never records a frame.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from inspector_scene import VISIBLE_POINT, inspector_scene, pixel_of  # noqa: E402
from test_editor import center, click  # noqa: E402

from gandalf_core import Application  # noqa: E402
from step07_advanced.editor import enable_editor  # noqa: E402

W, H = 800, 600


@pytest.fixture
def app(backend: str):
    application = Application(backend, W, H, headless=True, fixed_dt=1 / 60)
    scene, entities = inspector_scene()
    application.add_scene(scene)
    application.entities = entities
    yield application
    application.close()


def test_the_panel_starts_hidden_and_records_nothing(app) -> None:
    editor = enable_editor(app)
    app.run(frames=3)
    assert not editor.panel_visible("frame")
    system = editor.panel_system("frame")
    assert system.capture is None and app.renderer.recorder is None


def test_capture_button_lists_the_viewports_passes_then_the_gui(app) -> None:
    editor = enable_editor(app)
    editor.show_panel("frame")
    app.run(frames=3)
    system = editor.panel_system("frame")
    click(app, *center(editor.item_rects["frame/capture"]))
    app.run(frames=2)
    capture = system.capture
    assert capture is not None
    assert capture.pass_names() == ["shadow", "opaque", "sky", "transparent", "overlay"]
    assert len(capture.draws) == editor.viewport.draw_calls == 10
    # The tree shows every draw as a row; selecting one shows its decoded Material block.
    draw = capture.passes[1].draws[0]
    app.run(frames=2)
    click(app, *center(editor.item_rects[f"frame/draw/{draw.index}"]))
    app.run(frames=2)
    assert system.selected_draw == draw.index
    assert "frame/block/Material" in editor.item_rects and "frame/state" in editor.item_rects


def test_a_click_on_the_viewport_picks_and_selects_the_entity_under_it(app) -> None:
    editor = enable_editor(app)
    editor.show_panel("frame")
    app.run(frames=3)
    system = editor.panel_system("frame")
    system.pick_on_click = True
    target = editor.viewport.target
    x0, y0, x1, y1 = editor.item_rects["viewport/image"]
    for name in ("red cube", "pane", "floor"):
        with target.drawing():
            px, py = pixel_of(app, VISIBLE_POINT[name])
        sx = x0 + (px + 0.5) / target.size[0] * (x1 - x0)
        sy = y0 + (py + 0.5) / target.size[1] * (y1 - y0)
        editor.selected = None
        click(app, sx, sy)
        app.run(frames=2)
        assert system.picked is not None and system.picked.entity == app.entities[name], (name, system.picked)
        assert editor.selected == app.entities[name]


def test_the_texture_viewer_shows_a_cube_face_and_reads_out_texels(app) -> None:
    editor = enable_editor(app)
    editor.show_panel("frame")
    app.run(frames=3)
    system = editor.panel_system("frame")
    system.view_texture("sky", 2, 0)
    app.run(frames=2)
    np.testing.assert_array_equal(system.texels, app.scene.assets.textures["sky"].faces[2])
    system.view_texture("frame depth")
    app.run(frames=2)
    assert system.texels.shape == (editor.viewport.target.size[1], editor.viewport.target.size[0])


def test_a_capture_armed_when_the_editor_goes_leaves_nothing_behind(app) -> None:
    from step07_advanced.editor.frame_inspector import capture

    editor = enable_editor(app)
    editor.show_panel("frame")
    app.run(frames=2)
    editor.panel_system("frame").request_capture()
    app.scene.run_system(editor.panel_system("frame"), 1 / 60)  # armed: the next render would record
    assert app.renderer.recorder is not None
    editor.disable()
    assert app.renderer.recorder is None and not capture._ACTIVE
    app.run(frames=2)
