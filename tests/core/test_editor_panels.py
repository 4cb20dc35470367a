"""The editor's panels driven by synthetic input, headless, in both APIs.

Each test clicks, drags or types through ``app.input`` (as a user's events reach ImGui) and checks the scene, the
undo history and, where a picture is involved, the viewport's texture. Tolerances: the viewport's texture equals the
renderer's own frame at the same size exactly (0 levels) in each API; the two APIs' viewport textures agree with
PSNR >= 35 dB.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from gandalf_core import InfoComponent, LinkComponent, TransformComponent
from gandalf_core.components import LightComponent, MeshComponent
from gandalf_core.render import RenderSystem
from gandalf_tools.testing import psnr
from step07_advanced.editor import EditorPanelComponent, enable_editor

sys.path.insert(0, str(Path(__file__).parent))
import test_editor  # noqa: E402
from test_editor import H, center, click, editor_scene, make_app, named  # noqa: E402

app = test_editor.app  # the editor's app fixture, shared


def drag(app, start, end, steps: int = 6) -> None:
    """Press at ``start``, move to ``end`` over ``steps`` frames, release there (an ImGui drag and drop)."""
    app.input.move_mouse(*start)
    app.step()
    app.input.button(0, "press")
    app.step()
    for i in range(1, steps + 1):
        t = i / steps
        app.input.move_mouse(start[0] + t * (end[0] - start[0]), start[1] + t * (end[1] - start[1]))
        app.step()
    app.step()
    app.input.button(0, "release")
    app.step()
    app.step()


def keys(app, *names: str) -> None:
    """Press the keys together (a shortcut), then release them in reverse order."""
    for name in names:
        app.input.key(name, "press")
        app.step()
    for name in reversed(names):
        app.input.key(name, "release")
    app.step()


def test_viewport_shows_the_scene_at_the_panel_size_and_follows_a_resize(app) -> None:
    editor = enable_editor(app)
    app.run(frames=3)
    target = editor.viewport.target
    x0, y0, x1, y1 = editor.item_rects["viewport/image"]
    assert target.size == (int(x1 - x0), int(y1 - y0))
    # The texture is the scene drawn at that size: the renderer's own frame at the same size, exactly.
    picture = target.read_pixels()
    with make_app(app.renderer.backend) as plain:
        plain.renderer.resize(*target.size)
        scene = editor_scene()
        plain.add_scene(scene)
        plain.run(frames=3)
        np.testing.assert_array_equal(picture, plain.capture())
    w, h = target.size
    panel = editor.panel("viewport")
    panel.size = (panel.size[0] - 100, panel.size[1] - 60)
    app.run(frames=3)
    assert editor.viewport.target.size == (w - 100, h - 60)
    assert editor.viewport.target.read_pixels().shape == (h - 60, w - 100, 4)


def test_viewport_textures_agree_between_the_apis() -> None:
    pictures = {}
    for backend in ("opengl", "webgpu"):
        with make_app(backend) as application:
            application.add_scene(editor_scene())
            editor = enable_editor(application)
            application.run(frames=3)
            pictures[backend] = editor.viewport.target.read_pixels()
            editor.disable()
    assert pictures["opengl"].shape == pictures["webgpu"].shape
    assert psnr(pictures["opengl"], pictures["webgpu"]) >= 35.0


def gizmo_handle(app, editor, target, world_axes: bool = False) -> tuple[float, float]:
    """A point on the translate gizmo's X arrow: walk from the entity's screen position along the projected X axis
    until ImGuizmo says the pointer is over its X arrow (found by hovering, as a user finds it)."""
    scene = app.scene
    render = scene.get_system(RenderSystem)
    _e, camera, cam_transform = render.primary_camera()
    x0, y0, x1, y1 = editor.item_rects["viewport/image"]
    w, h = x1 - x0, y1 - y0
    clip = camera.projection_matrix("opengl", w / h) @ np.linalg.inv(cam_transform.world)
    world = scene.get_component(target, TransformComponent).world

    def screen(p: np.ndarray) -> np.ndarray:
        c = clip @ np.append(p, 1.0)
        return np.array([x0 + (c[0] / c[3] + 1) * w / 2, y0 + (1 - c[1] / c[3]) * h / 2])

    origin = screen(world[:3, 3])
    direction = np.array([1.0, 0.0, 0.0]) if world_axes else world[:3, 0] / np.linalg.norm(world[:3, 0])
    axis = screen(world[:3, 3] + direction) - origin
    axis /= np.linalg.norm(axis)
    for distance in [d * sign for d in range(10, 120, 3) for sign in (1, -1)]:  # ImGuizmo may flip an axis
        p = origin + distance * axis
        app.input.move_mouse(*p)
        app.step()
        app.step()
        if editor.gizmo_hovered == "move_x":  # the X arrow, not the screen-plane handle at the centre
            return float(p[0]), float(p[1])
    raise AssertionError("no gizmo handle found along the X axis")


@pytest.mark.parametrize("mode", ["local", "world"])
def test_gizmo_drag_moves_the_selected_entity_in_one_undo_step(app, mode: str) -> None:
    editor = enable_editor(app)
    target = named(app.scene, "cube1")
    editor.selected = target
    app.run(frames=2)
    click(app, *center(editor.item_rects[f"viewport/{mode}"]))
    assert editor.viewport.mode == mode
    start = app.scene.get_component(target, TransformComponent).translation.copy()
    before_picture = editor.viewport.target.read_pixels()
    hx, hy = gizmo_handle(app, editor, target, world_axes=mode == "world")
    drag(app, (hx, hy), (hx + 60, hy), steps=6)
    moved = app.scene.get_component(target, TransformComponent).translation.copy()
    assert np.linalg.norm(moved - start) > 0.2, f"the gizmo moved nothing: {start} -> {moved}"
    assert not np.any(np.isnan(moved))
    step = moved - start
    along = np.array([1.0, 0.0, 0.0]) if mode == "world" else \
        app.scene.get_component(target, TransformComponent).world[:3, 0] / 0.8  # the X axis of the cube (scale 0.8)
    np.testing.assert_allclose(step / np.linalg.norm(step), along * np.sign(step @ along), atol=0.02,
                               err_msg=f"the {mode} X arrow moves along that axis only")
    assert np.any(editor.viewport.target.read_pixels() != before_picture, axis=2).sum() > 100
    assert len(editor.commands.done) == 1, [c.label for c in editor.commands.done]
    editor.undo()
    np.testing.assert_allclose(app.scene.get_component(target, TransformComponent).translation, start, atol=1e-12)


def test_gizmo_modes_switch_with_the_toolbar(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    click(app, *center(editor.item_rects["viewport/rotate"]))
    click(app, *center(editor.item_rects["viewport/world"]))
    assert (editor.viewport.operation, editor.viewport.mode) == ("rotate", "world")
    click(app, *center(editor.item_rects["viewport/scale"]))
    assert editor.viewport.operation == "scale"


def test_hierarchy_buttons_create_duplicate_and_delete(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    count = len(app.scene)
    click(app, *center(editor.item_rects["hierarchy:create"]))
    assert len(app.scene) == count + 1
    created = editor.selected
    assert app.scene.get_component(created, InfoComponent).name == "Entity"
    click(app, *center(editor.item_rects["hierarchy:duplicate"]))
    assert len(app.scene) == count + 2 and editor.selected != created
    assert app.scene.get_component(editor.selected, InfoComponent).name == "Entity copy"
    click(app, *center(editor.item_rects["hierarchy:delete"]))
    assert len(app.scene) == count + 1
    assert [c.label.split()[0] for c in editor.commands.done] == ["create", "duplicate", "destroy"]
    click(app, *center(editor.item_rects[f"hierarchy/{created}"]))  # select (and focus the panel)
    keys(app, "LEFT_CONTROL", "D")
    assert len(app.scene) == count + 2
    keys(app, "DELETE")
    assert len(app.scene) == count + 1 and created in app.scene


def test_dragging_a_row_onto_another_reparents_it_and_onto_free_space_makes_a_root(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    camera, cube = named(app.scene, "camera"), named(app.scene, "cube2")
    drag(app, center(editor.item_rects[f"hierarchy/{camera}"]), center(editor.item_rects[f"hierarchy/{cube}"]))
    assert app.scene.parent_of(camera) == cube
    x0, y0, x1, y1 = editor.item_rects["hierarchy:free"]
    drag(app, center(editor.item_rects[f"hierarchy/{camera}"]), ((x0 + x1) / 2, y0 + 10))
    assert app.scene.parent_of(camera) is None
    editor.undo()
    assert app.scene.parent_of(camera) == cube


def test_renaming_from_the_row_context_menu(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    cube = named(app.scene, "cube2")
    x, y = center(editor.item_rects[f"hierarchy/{cube}"])
    app.input.move_mouse(x, y)
    app.step()
    app.input.button(1, "press")
    app.step()
    app.input.button(1, "release")
    app.run(frames=2)
    click(app, *center(editor.item_rects["hierarchy:menu/rename"]))
    app.run(frames=2)  # the popup opens with the name field focused
    for key in ("END", "BACKSPACE", "X", "ENTER"):
        app.input.key(key, "press")
        app.step()
        app.input.key(key, "release")
        app.step()
    assert app.scene.get_component(cube, InfoComponent).name == "cubex"
    editor.undo()
    assert app.scene.get_component(cube, InfoComponent).name == "cube2"


def test_unnamed_entities_get_readable_rows(app) -> None:
    editor = enable_editor(app)
    bare = app.scene.create_entity(TransformComponent(), LightComponent())
    app.run(frames=2)
    assert f"hierarchy/{bare}" in editor.item_rects
    from step07_advanced.editor.entities import display_name

    assert display_name(app.scene, bare).startswith("Light (")


def test_inspector_adds_and_removes_components(app) -> None:
    editor = enable_editor(app)
    target = named(app.scene, "cube0")
    editor.selected = target
    panel = editor.panel("inspector")
    panel.position, panel.size = (panel.position[0], 20.0), (panel.size[0], H - 20.0)  # room for every component
    app.run(frames=2)
    click(app, *center(editor.item_rects["inspector/add"]))
    click(app, *center(editor.item_rects["inspector/add/LightComponent"]))
    assert app.scene.has_component(target, LightComponent)
    app.run(frames=1)
    click(app, *center(editor.item_rects["inspector/remove/LightComponent"]))
    assert not app.scene.has_component(target, LightComponent)
    editor.undo()
    assert app.scene.has_component(target, LightComponent)


def test_inspector_typing_a_name_renames_in_one_undo_step(app) -> None:
    editor = enable_editor(app)
    target = named(app.scene, "cube0")
    editor.selected = target
    app.run(frames=2)
    x0, y0, x1, y1 = editor.item_rects["inspector/name"]
    click(app, x0 + 5, (y0 + y1) / 2)
    for key in ("END", "X", "Y"):
        app.input.key(key, "press")
        app.step()
        app.input.key(key, "release")
        app.step()
    click(app, *center(editor.item_rects["viewport/image"]))  # away from the field: the edit is done
    assert app.scene.get_component(target, InfoComponent).name == "cube0xy"
    editor.undo()
    assert app.scene.get_component(target, InfoComponent).name == "cube0"


def test_systems_panel_pauses_steps_and_times(app) -> None:
    from gandalf_core.systems import TransformSystem

    editor = enable_editor(app)
    app.run(frames=3)
    transform = app.scene.get_system(TransformSystem)
    assert transform.update_seconds > 0.0
    click(app, *center(editor.item_rects[f"systems/run/{transform.name}"]))
    assert not transform.enabled
    cube = named(app.scene, "cube0")
    app.scene.get_component(cube, TransformComponent).translation = (0.0, 3.0, 0.0)
    app.run(frames=2)
    assert app.scene.get_component(cube, TransformComponent).world[1, 3] == pytest.approx(0.0), "paused"
    click(app, *center(editor.item_rects[f"systems/step/{transform.name}"]))
    assert app.scene.get_component(cube, TransformComponent).world[1, 3] == pytest.approx(3.0), "one step ran"
    render = app.scene.get_system(RenderSystem)
    click(app, *center(editor.item_rects[f"systems/run/{render.name}"]))
    assert render.enabled, "the render system cannot be paused"
    order = app.scene.systems
    click(app, *center(editor.item_rects[f"systems/down/{transform.name}"]))
    assert app.scene.systems.index(transform) == order.index(transform) + 1
    app.step()  # the rows are drawn in the new order from the next frame on
    click(app, *center(editor.item_rects[f"systems/up/{transform.name}"]))
    assert app.scene.systems == order


def test_content_browser_drags_a_mesh_into_the_viewport_and_a_texture_onto_a_material(app) -> None:
    from gandalf_core.resources import checkerboard

    app.scene.assets.texture("other", checkerboard(16, 2))
    editor = enable_editor(app)
    app.run(frames=2)
    meshes = len(list(app.scene.view(MeshComponent)))
    drag(app, center(editor.item_rects["content/mesh/cube"]), center(editor.item_rects["viewport/image"]))
    assert len(list(app.scene.view(MeshComponent))) == meshes + 1
    drag(app, center(editor.item_rects["content/texture/other"]), center(editor.item_rects["content/material/M"]))
    assert app.scene.assets.materials["M"].textures == ("other",)
    assert [c.label for c in editor.commands.done] == ["create cube", "texture of M"]


def test_console_shows_a_shader_error_with_its_file_and_line(app, tmp_path: Path) -> None:
    editor = enable_editor(app)
    app.run(frames=1)
    if app.renderer.backend == "opengl":
        (tmp_path / "bad.vert").write_text("#version 330\nin vec3 position;\nvoid main() {\n  gl_Position = nope;\n}\n")
        (tmp_path / "bad.frag").write_text("#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n")
        ok = editor.build_shader("bad", tmp_path / "bad.vert", tmp_path / "bad.frag")
        where = "bad.vert:4"
    else:
        (tmp_path / "bad.wgsl").write_text("@vertex\nfn vs_main() -> @builtin(position) vec4<f32> {\n"
                                           "  return nope;\n}\n")
        ok = editor.build_shader("bad", tmp_path / "bad.wgsl")
        where = "bad.wgsl:3"
    assert ok is False
    errors = [e for e in editor.log.entries if e.level == "error"]
    assert errors and where in errors[-1].text, errors
    app.run(frames=2)  # drawn, wrapped, nothing raised


def test_menu_bar_undo_redo_shortcuts_and_view_toggles(app) -> None:
    editor = enable_editor(app)
    app.run(frames=2)
    cube = named(app.scene, "cube0")
    editor.rename_entity(cube, "renamed")
    keys(app, "LEFT_CONTROL", "Z")
    assert app.scene.get_component(cube, InfoComponent).name == "cube0"
    keys(app, "LEFT_CONTROL", "Y")
    assert app.scene.get_component(cube, InfoComponent).name == "renamed"
    click(app, *center(editor.item_rects["menu/edit"]))
    click(app, *center(editor.item_rects["menu/edit/undo"]))
    assert app.scene.get_component(cube, InfoComponent).name == "cube0"
    click(app, *center(editor.item_rects["menu/view"]))
    click(app, *center(editor.item_rects["menu/view/console"]))
    assert not editor.panel_visible("console")


def type_text(app, text: str) -> None:
    for ch in text:
        key = ch.upper()
        app.input.key(key, "press")
        app.step()
        app.input.key(key, "release")
        app.step()


def test_menu_bar_new_save_as_open_and_recent(app, tmp_path: Path, monkeypatch) -> None:
    pytest.importorskip("pxr")
    monkeypatch.chdir(tmp_path)
    editor = enable_editor(app)
    app.run(frames=2)
    click(app, *center(editor.item_rects["menu/file"]))
    click(app, *center(editor.item_rects["menu/file/save_as"]))
    app.run(frames=2)
    x0, y0, x1, y1 = editor.item_rects["menu/dialog/path"]
    click(app, x0 + 5, (y0 + y1) / 2)
    keys(app, "LEFT_CONTROL", "A")  # select what is there, type over it
    type_text(app, "menu.usda")
    click(app, *center(editor.item_rects["menu/dialog/ok"]))
    assert (tmp_path / "menu.usda").is_file(), editor.status
    assert editor.recent[0] == "menu.usda" and editor.path == "menu.usda"
    click(app, *center(editor.item_rects["menu/file"]))
    click(app, *center(editor.item_rects["menu/file/new"]))
    app.run(frames=1)
    assert app.scene.name == "untitled" and len(editor.panels()) > 0
    assert not any(k.startswith("hierarchy/") for k in editor.item_rects), "the new scene is empty"
    # File > Open Recent > menu.usda: the submenu opens on hover.
    click(app, *center(editor.item_rects["menu/file"]))
    app.input.move_mouse(*center(editor.item_rects["menu/file/recent"]))
    app.run(frames=3)
    click(app, *center(editor.item_rects["menu/file/recent/0"]))
    app.run(frames=1)
    assert app.scene.name.startswith("editor-test"), editor.status
    assert named(app.scene, "cube1") is not None


def test_loading_after_a_colour_edit_works_and_a_failed_load_is_shown_whole(app, tmp_path: Path) -> None:
    pytest.importorskip("pxr")
    editor = enable_editor(app)
    app.run(frames=2)
    path = tmp_path / "scene.usda"
    assert editor.save(path), editor.status
    editor.set_material_color("M", (0.2, 0.9, 0.2))
    app.run(frames=1)
    assert editor.load(path), editor.status  # pyGANDALF-style clash: "material 'M' already in use" before
    app.run(frames=2)
    assert editor.material_color("M") == pytest.approx((1.0, 0.6, 0.3))
    long_name = "a_very_long_folder_name_" * 6
    assert not editor.load(tmp_path / long_name / "missing.usda")
    app.run(frames=2)
    x0, y0, x1, y1 = editor.item_rects["file/status"]
    panel = editor.panel("file")
    assert x1 <= panel.position[0] + panel.size[0] + 1, "the message stays inside the panel"
    assert y1 - y0 > 30, "a long message wraps onto several lines"
    assert long_name in editor.status and editor.log.entries[-1].text == editor.status


def test_a_scene_that_sets_a_panel_hidden_keeps_it_hidden_across_frames(app) -> None:
    editor = enable_editor(app)
    app.run(frames=1)
    for entity in editor.panels():
        component = app.scene.get_component(entity, EditorPanelComponent)
        if component.kind == "systems":
            component.visible = False
    app.run(frames=2)
    assert not any(k.startswith("systems/") for k in editor.item_rects)
    assert isinstance(app.scene.get_component(named(app.scene, "cube0"), LinkComponent), LinkComponent)


def test_idle_frames_draw_the_cached_gui_and_input_runs_the_panels(app) -> None:
    """An idle frame composites the GUI layer of the last panel run: the same picture as running the panels."""
    editor = enable_editor(app)
    editor.selected = named(app.scene, "cube1")
    app.run(frames=3)
    editor.gui_interval = 0.0  # every frame runs the panels
    app.run(frames=2)
    full = app.capture()
    editor.gui_interval = 1.0e9  # only input or a change runs them
    ran, skipped = editor.gui_frames, editor.skipped_gui_frames
    app.run(frames=4)
    assert editor.gui_frames == ran and editor.skipped_gui_frames == skipped + 4
    np.testing.assert_array_equal(app.capture(), full)  # the scene is still: exactly the same frame
    app.input.move_mouse(5.0, 5.0)
    app.step()
    assert editor.gui_frames == ran + 1, "input runs the panels"
    app.run(frames=3)
    editor.rename_entity(named(app.scene, "cube0"), "renamed")
    before = editor.gui_frames
    app.step()
    assert editor.gui_frames == before + 1, "an edit runs the panels"


def test_stats_panel_shows_the_gpu_memory_the_renderer_holds(app) -> None:
    from step07_advanced.editor.panels import StatsPanelSystem

    editor = enable_editor(app)
    app.run(frames=3)
    stats = app.scene.get_system(StatsPanelSystem)
    assert "stats/gpu_memory" in editor.item_rects
    held = app.renderer.gpu_memory()
    assert stats.gpu_memory == held and held["total"] > held["frame targets"] > 0
    app.input.move_mouse(*center(editor.item_rects["stats/gpu_memory"]))  # hovered: the breakdown's tooltip
    app.run(frames=2)
    assert stats.gpu_memory == app.renderer.gpu_memory()
