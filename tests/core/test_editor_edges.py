"""Editor edits at their edges, headless, in both APIs: reparenting an entity created in the same frame keeps it
where it is, pausing and moving a system are undoable like every other edit, and at 640×480 every button of the
content browser lies inside its panel."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from gandalf_core import TransformComponent
from step07_advanced.editor import enable_editor

sys.path.insert(0, str(Path(__file__).parent))
import test_editor  # noqa: E402
from test_editor import H, W, center, click, named  # noqa: E402

app = test_editor.app  # the editor's app fixture, shared


def test_reparenting_an_entity_created_this_frame_keeps_it_in_place(app) -> None:
    editor = enable_editor(app)
    app.run(frames=1)
    scene = app.scene
    root = named(scene, "root")
    scene.get_component(root, TransformComponent).translation = (1.0, 2.0, 3.0)  # moved this frame too
    entity = editor.create_entity("fresh", TransformComponent((4.0, -1.0, 0.5), rotation=(0.0, 30.0, 0.0)))
    editor.reparent(entity, root)  # no frame in between: neither world matrix is up to date
    app.run(frames=1)
    world = np.array(scene.get_component(entity, TransformComponent).world)
    np.testing.assert_allclose(world[:3, 3], (4.0, -1.0, 0.5), atol=1e-12)
    np.testing.assert_allclose(scene.get_component(entity, TransformComponent).translation, (3.0, -3.0, -2.5),
                               atol=1e-12)
    editor.undo()
    app.run(frames=1)
    np.testing.assert_allclose(scene.get_component(entity, TransformComponent).world[:3, 3], (4.0, -1.0, 0.5),
                               atol=1e-12)


def test_pausing_and_moving_a_system_are_undoable(app) -> None:
    editor = enable_editor(app)
    app.run(frames=3)
    scene = app.scene
    system = next(s for s in scene.systems if s.name == "TransformSystem")
    order = list(scene.systems)
    editor.set_system_enabled(system, False)
    assert not system.enabled and editor.commands.done[-1].label == "pause TransformSystem"
    editor.undo()
    assert system.enabled
    editor.redo()
    assert not system.enabled
    editor.set_system_enabled(system, False)  # no change: no new undo step
    assert [c.label for c in editor.commands.done] == ["pause TransformSystem"]
    editor.move_system(system, 1)
    assert scene.systems.index(system) == order.index(system) + 1
    editor.undo()
    assert scene.systems == order
    editor.undo()
    assert system.enabled
    click(app, *center(editor.item_rects["systems/run/TransformSystem"]))  # the panel's checkbox: the same edit
    assert not system.enabled and editor.commands.done[-1].label == "pause TransformSystem"


def test_the_content_browser_shows_all_its_buttons_at_640x480(app) -> None:
    from core_shaders import FILES, SHADERS

    assert (app.renderer.width, app.renderer.height) == (W, H) == (640, 480)
    editor = enable_editor(app)
    # A shader with a long name, built from files: it gets a reload button.
    files = [SHADERS / f for f in FILES["unlit"][:2]] if app.renderer.backend == "opengl" else \
        [SHADERS / FILES["unlit"][2]]
    long_name = "a_shader_with_a_rather_long_name_for_a_narrow_panel"
    assert editor.build_shader(long_name, *files)
    app.run(frames=2)
    panel = editor.panel("content")
    left, right = panel.position[0], panel.position[0] + panel.size[0]
    buttons = {k: r for k, r in editor.item_rects.items() if k.startswith(("content/spawn/", "content/reload/"))}
    assert f"content/reload/{long_name}" in buttons and "content/spawn/cube" in buttons, sorted(buttons)
    for key, (x0, _y0, x1, _y1) in buttons.items():
        assert left <= x0 and x1 <= right, f"{key} spans x {x0:.0f}..{x1:.0f}, the panel {left:.0f}..{right:.0f}"
    editor.status = ""
    click(app, *center(buttons[f"content/reload/{long_name}"]))
    assert editor.status == f"built shader '{long_name}'", editor.status
