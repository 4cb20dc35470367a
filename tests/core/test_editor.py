"""The editor layer on both backends, headless: it draws, both backends agree, synthetic input edits the scene.

Tolerances: outside the panels an editor frame equals the frame without the editor exactly (0 levels).
The GUI is composited alike on both backends: wherever the two backends' scenes agree, their editor frames
inside the panels differ by at most 1 level (>= 99.9% of those pixels identical); over whole frames (where the two
rasterisers differ on a few cube-edge pixels) the OpenGL and WebGPU editor frames agree with PSNR >= 35 dB.
"""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from core_shaders import build_shaders

from gandalf_core import Application, InfoComponent, LinkComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, ClearColorComponent, MaterialComponent, MeshComponent
from gandalf_core.math import look_at_rotation
from gandalf_core.render import RenderSystem
from gandalf_core.resources import MaterialData, checkerboard, cube
from gandalf_tools.testing import psnr
from step07_advanced.editor import PANEL_KINDS, EditorPanelComponent, disable_editor, enable_editor, is_editor_entity

ROOT = Path(__file__).resolve().parents[2]
W, H = 640, 480
HAS_USD = importlib.util.find_spec("step07_advanced.usd") is not None


def make_app(backend: str) -> Application:
    app = Application(backend, W, H, headless=True, fixed_dt=1 / 60)
    build_shaders(app.renderer.shaders, backend, "unlit")
    return app


def editor_scene(name: str = "editor-test") -> Scene:
    """A root with three cubes under it, a camera and a background, all named."""
    scene = Scene(name)
    scene.assets.mesh("cube", cube())
    scene.assets.texture("checker", checkerboard(32, 4))
    scene.assets.material("M", MaterialData("unlit", ["checker"], color=(1.0, 0.6, 0.3)))
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.2, 0.3, 0.4)))
    root = scene.create_entity(InfoComponent("root"), TransformComponent())
    for i in range(3):
        scene.create_entity(
            InfoComponent(f"cube{i}"), LinkComponent(root),
            TransformComponent((i * 1.2 - 1.2, 0, 0), (30, 40 * i, 0), 0.8),
            MeshComponent("cube"), MaterialComponent("M"),
        )
    eye = np.array([0.0, 1.5, 6.0])
    scene.create_entity(
        InfoComponent("camera"), TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0, 0))),
        CameraComponent(50.0, 0.1, 100.0),
    )
    return scene


def named(scene: Scene, name: str):
    return next(e for e, (info,) in scene.view(InfoComponent) if info.name == name)


def panel_mask(app: Application, editor) -> np.ndarray:
    """True inside (and on a 1-pixel border around) every visible panel."""
    mask = np.zeros((H, W), dtype=bool)
    for entity in editor.panels():
        panel = app.scene.get_component(entity, EditorPanelComponent)
        if not panel.visible:
            continue
        (x, y), (w, h) = panel.position, panel.size
        mask[max(int(y) - 1, 0):int(np.ceil(y + h)) + 1, max(int(x) - 1, 0):int(np.ceil(x + w)) + 1] = True
    return mask


def middle_free(editor) -> None:
    """Hide the viewport and the console: the middle of the frame shows the app's own frame again."""
    editor.show_panel("viewport", False)
    editor.show_panel("console", False)


def center(rect) -> tuple[float, float]:
    x0, y0, x1, y1 = rect
    return (x0 + x1) / 2, (y0 + y1) / 2


def click(app: Application, x: float, y: float) -> None:
    """Hover, press, release: one frame each (as a user's click reaches ImGui)."""
    app.input.move_mouse(x, y)
    app.step()
    app.input.button(0, "press")
    app.step()
    app.input.button(0, "release")
    app.step()


@pytest.fixture
def app(backend: str):
    application = make_app(backend)
    application.add_scene(editor_scene())
    yield application
    disable_editor(application)
    application.close()


def test_editor_draws_panels_and_leaves_the_rest_of_the_frame_alone(app) -> None:
    app.run(frames=2)
    plain = app.capture()
    editor = enable_editor(app)
    middle_free(editor)
    app.run(frames=2)
    shown = app.capture()
    mask = panel_mask(app, editor)
    changed = np.any(shown != plain, axis=2)
    assert 0.2 < mask.mean() < 0.9, "the default layout leaves the middle of the frame free"
    assert changed[mask].mean() > 0.5, "the panels must cover what is under them"
    # Outside the panels the frame is untouched, exactly (tolerance: 0 levels).
    assert not changed[~mask].any(), f"{changed[~mask].sum()} pixels changed outside the panels"


def test_opengl_and_webgpu_editor_frames_agree() -> None:
    plain, frames, masks = {}, {}, {}
    for backend in ("opengl", "webgpu"):
        with make_app(backend) as application:
            application.add_scene(editor_scene())
            application.run(frames=1)
            plain[backend] = application.capture()
            editor = enable_editor(application)
            middle_free(editor)
            editor.show_panel("systems", False)  # it shows measured times, which differ from run to run
            application.run(frames=3)
            frames[backend] = application.capture()
            masks[backend] = panel_mask(application, editor)
            editor.disable()
    assert np.array_equal(masks["opengl"], masks["webgpu"]), "both backends lay the panels out alike"
    # The two rasterisers differ on a few cube-edge pixels of the scene itself; over the whole frame:
    assert psnr(frames["opengl"], frames["webgpu"]) >= 35.0
    # Wherever the scenes underneath agree, the GUI composited over them agrees: at most 1 level per
    # channel (blend rounding on a few anti-aliased edge pixels), and at least 99.9% of pixels identical.
    same_scene = np.all(plain["opengl"] == plain["webgpu"], axis=2)
    inside = masks["opengl"] & same_scene
    assert inside.sum() > 0.2 * W * H
    diff = np.abs(frames["opengl"][inside].astype(int) - frames["webgpu"][inside].astype(int)).max(axis=1)
    assert diff.max() <= 1
    assert (diff == 0).mean() >= 0.999


def test_clicking_a_hierarchy_row_selects_that_entity(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    target = named(app.scene, "cube1")
    assert editor.selected is None
    click(app, *center(editor.item_rects[f"hierarchy/{target}"]))
    assert editor.selected == target
    other = named(app.scene, "camera")
    click(app, *center(editor.item_rects[f"hierarchy/{other}"]))
    assert editor.selected == other


def test_dragging_the_inspector_translation_moves_the_entity_and_the_picture(app) -> None:
    editor = enable_editor(app)
    target = named(app.scene, "cube1")
    editor.selected = target
    app.run(frames=2)
    before = editor.viewport.target.read_pixels()
    start = app.scene.get_component(target, TransformComponent).translation.copy()
    x0, y0, x1, y1 = editor.item_rects["inspector/translation"]
    x, y = x0 + (x1 - x0) / 6, (y0 + y1) / 2  # the middle of the X field (a third of the widget)
    app.input.move_mouse(x, y)
    app.step()
    app.input.button(0, "press")
    app.step()
    for i in range(1, 9):  # 80 pixels to the right, 10 per frame
        app.input.move_mouse(x + 10 * i, y)
        app.step()
    app.input.button(0, "release")
    app.run(frames=2)
    moved = app.scene.get_component(target, TransformComponent).translation
    assert moved[0] > start[0] + 0.3, f"x should grow by ~0.01 per dragged pixel: {start} -> {moved}"
    np.testing.assert_allclose(moved[1:], start[1:])
    after = editor.viewport.target.read_pixels()
    assert np.any(after != before, axis=2).sum() > 100, "the cube moved in the viewport"


def test_inspector_material_colour_changes_the_picture(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    before = editor.viewport.target.read_pixels()
    assert editor.material_color("M") == pytest.approx((1.0, 0.6, 0.3))
    editor.set_material_color("M", (0.1, 0.9, 0.1))
    app.run(frames=1)
    after = editor.viewport.target.read_pixels()
    assert np.any(after != before, axis=2).sum() > 100
    with pytest.raises(ValueError, match="'nope'"):
        editor.set_material_color("nope", (1, 1, 1))


def test_typing_into_the_path_field(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    x0, y0, x1, y1 = editor.item_rects["file/save"]
    click(app, x0 + 4, y0 - 12)  # the path field sits one row above the Save button
    assert editor.wants_keyboard
    for key in ("END", "BACKSPACE", "BACKSPACE", "BACKSPACE", "BACKSPACE", "U", "S", "D", "C"):
        app.input.key(key, "press")
        app.step()
        app.input.key(key, "release")
        app.step()
    assert editor.path == "scene.usdc"


def test_editor_entities_are_hidden_and_not_drawn(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    panels = editor.panels()
    assert len(panels) == len(PANEL_KINDS)
    assert {app.scene.get_component(p, EditorPanelComponent).kind for p in panels} == set(PANEL_KINDS)
    assert all(is_editor_entity(app.scene, p) for p in panels)
    listed = {key.split("/", 1)[1] for key in editor.item_rects if key.startswith("hierarchy/")}
    user = {str(e) for e in app.scene.entities if not is_editor_entity(app.scene, e)}
    assert listed == user
    render = app.scene.get_system(RenderSystem)
    assert not set(panels) & set(render.entities)
    middle_free(editor)  # the frame draws the scene itself again (the viewport does while it is shown)
    app.run(frames=1)
    assert app.renderer.stats["draw_calls"] == 1  # the three cubes, one instanced draw


def test_while_the_viewport_shows_the_scene_the_frame_under_the_panels_is_only_cleared(app) -> None:
    """The default layout covers the frame with panels: the scene is drawn once, into the viewport."""
    render = app.scene.get_system(RenderSystem)
    editor = enable_editor(app)
    app.run(frames=3)
    assert not render.draws_scene and app.renderer.stats["draw_calls"] == 0
    assert editor.viewport.draw_calls == 1  # the stats panel counts the viewport's draws with the frame's
    picture = editor.viewport.target.read_pixels()
    assert len(np.unique(picture.reshape(-1, 4), axis=0)) > 2, "the viewport still shows the scene"
    editor.show_panel("viewport", False)
    app.run(frames=1)
    assert render.draws_scene and app.renderer.stats["draw_calls"] == 1
    editor.show_panel("viewport", True)
    app.run(frames=3)
    assert not render.draws_scene
    disable_editor(app)
    app.run(frames=1)
    assert render.draws_scene and app.renderer.stats["draw_calls"] == 1


def test_hidden_panel_draws_nothing(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    for entity in editor.panels():
        app.scene.get_component(entity, EditorPanelComponent).visible = False
    app.run(frames=1)
    hidden = app.capture()
    disable_editor(app)
    app.run(frames=1)
    assert np.array_equal(hidden, app.capture())


def test_switched_to_scenes_get_the_editor(app) -> None:
    editor = enable_editor(app)
    app.run(frames=1)
    second = editor_scene("second")
    second.assets = app.scene.assets  # one set of named resources per renderer
    app.switch_scene(second)
    app.run(frames=2)
    assert len(editor.panels(second)) == len(PANEL_KINDS)
    assert any(key.startswith("hierarchy/") for key in editor.item_rects)


def test_enabling_and_disabling_many_times_leaks_nothing(app) -> None:
    app.run(frames=1)
    scene = app.scene
    baseline = (app.renderer.live_objects(), len(app.renderer.overlays), len(scene), len(scene.systems),
                len(app.scenes.on_switch))
    for _ in range(6):
        editor = enable_editor(app)
        assert enable_editor(app) is editor  # one editor per app
        app.run(frames=2)
        assert len(app.renderer.overlays) == baseline[1] + 1
        gui = editor._gui
        disable_editor(app)
        textures = gui.textures if app.renderer.backend == "opengl" else gui.backend._textures
        assert not textures, "ImGui's textures are freed"
    after = (app.renderer.live_objects(), len(app.renderer.overlays), len(scene), len(scene.systems),
             len(app.scenes.on_switch))
    assert after == baseline
    app.run(frames=1)  # the app still runs without it


def test_load_errors_are_reported_not_raised(app, tmp_path: Path) -> None:
    editor = enable_editor(app)
    app.run(frames=1)
    assert editor.load(tmp_path / "missing.usda") is False
    assert editor.status_is_error and editor.status
    app.run(frames=1)  # the message is drawn; nothing crashes


@pytest.mark.skipif(not HAS_USD, reason="step07_advanced.usd is not available")
def test_save_writes_no_editor_entities_and_load_switches(app, tmp_path: Path) -> None:
    from step07_advanced.usd import load_scene

    editor = enable_editor(app)
    app.run(frames=1)
    path = tmp_path / "saved.usda"
    assert editor.save(path), editor.status
    assert len(editor.panels()) == len(PANEL_KINDS), "panels are back after saving"
    loaded = load_scene(path)
    assert not any(loaded.view(EditorPanelComponent))
    names = sorted(info.name for _e, (info,) in loaded.view(InfoComponent))
    assert names == ["background", "camera", "cube0", "cube1", "cube2", "root"]
    assert editor.load(path), editor.status
    app.run(frames=2)
    assert app.scene.name == "editor-test (2)"
    assert len(editor.panels(app.scene)) == len(PANEL_KINDS)


def test_editor_is_off_by_default_and_not_imported() -> None:
    code = (
        "import sys\n"
        "import gandalf_core, step07_advanced.editor\n"
        f"sys.path.insert(0, {str(ROOT / 'tests' / 'core')!r})\n"
        "from test_editor import make_app, editor_scene\n"
        "app = make_app('opengl'); app.add_scene(editor_scene()); app.run(frames=2)\n"
        "assert app.renderer.overlays == [], app.renderer.overlays\n"
        "app.close()\n"
        "print(','.join(m for m in ('imgui_bundle', 'OpenGL') if m in sys.modules))\n"
    )
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120,
                            check=False)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "", f"imported without the editor: {result.stdout.strip()}"
