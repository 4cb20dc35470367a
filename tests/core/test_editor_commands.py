"""Undo and redo of every kind of editor edit, and the small ECS hooks the editor's panels rely on.

Each edit kind round-trips: after the edit the scene is in state B, undo brings back state A exactly (same entity
ids, same component values, float64 equality), redo gives B again. Material colour and texture edits run in both
APIs (they reach the renderer); the rest is ECS data and runs on OpenGL only.
"""

from __future__ import annotations

import sys
import uuid
import warnings
from pathlib import Path

import numpy as np
import pytest

from gandalf_core import InfoComponent, LinkComponent, Scene, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent
from gandalf_core.components.fields import FieldError
from gandalf_core.ecs import System
from gandalf_core.resources import checkerboard
from step07_advanced.editor import disable_editor, enable_editor, is_editor_entity

sys.path.insert(0, str(Path(__file__).parent))
from test_editor import editor_scene, make_app, named  # noqa: E402


def state(scene: Scene) -> dict:
    """Everything an edit may change, comparable with ==: per entity its parent and its components' values."""
    out = {}
    for entity in scene.entities:
        if is_editor_entity(scene, entity):
            continue
        comps = {}
        for c in scene.components_of(entity):
            if isinstance(c, LinkComponent):
                comps["parent"] = c.parent
                comps["children"] = tuple(c.children)
            elif isinstance(c, TransformComponent):
                comps["T"] = (tuple(c.translation), tuple(c.quaternion), tuple(c.scale))
            else:
                comps[type(c).__name__] = repr(c)
        out[entity] = comps
    return out


@pytest.fixture
def gl_app():
    app = make_app("opengl")
    app.add_scene(editor_scene())
    editor = enable_editor(app)
    app.run(frames=1)
    yield app, editor
    disable_editor(app)
    app.close()


def round_trip(editor, scene: Scene, edit) -> tuple[dict, dict]:
    """Run ``edit``; check undo gives the state before and redo the state after. Returns (before, after)."""
    before = state(scene)
    edit()
    after = state(scene)
    assert after != before, "the edit changed nothing"
    assert editor.undo() is not None
    assert state(scene) == before, "undo did not bring the scene back exactly"
    assert editor.redo() is not None
    assert state(scene) == after, "redo did not give the edited scene again"
    assert editor.undo() is not None
    assert state(scene) == before
    return before, after


def test_transform_round_trips(gl_app) -> None:
    app, editor = gl_app
    cube = named(app.scene, "cube1")
    round_trip(editor, app.scene, lambda: editor.set_transform(cube, (1.0, 2.0, 3.0), (0.0, 1.0, 0.0, 0.0), (2, 2, 2)))
    round_trip(editor, app.scene, lambda: editor.set_world_matrix(cube, np.diag([2.0, 2.0, 2.0, 1.0])))


def test_rename_round_trips_and_names_an_unnamed_entity(gl_app) -> None:
    app, editor = gl_app
    cube = named(app.scene, "cube1")
    round_trip(editor, app.scene, lambda: editor.rename_entity(cube, "renamed"))
    bare = app.scene.create_entity(TransformComponent())
    round_trip(editor, app.scene, lambda: editor.rename_entity(bare, "now named"))


def test_create_destroy_duplicate_round_trip(gl_app) -> None:
    app, editor = gl_app
    scene = app.scene
    root = named(scene, "root")
    made: list[uuid.UUID] = []
    round_trip(editor, scene, lambda: made.append(editor.create_entity("new", parent=root)))
    editor.redo()
    assert scene.parent_of(made[0]) == root and made[0] in scene.get_component(root, LinkComponent).children
    editor.undo()
    # Destroying the root takes its three cubes; undo brings all four back with the same ids and values.
    before, after = round_trip(editor, scene, lambda: editor.destroy_entity(root))
    assert len(before) - len(after) == 4
    copies: list[uuid.UUID] = []
    before, after = round_trip(editor, scene, lambda: copies.append(editor.duplicate_entity(root)))
    assert len(after) - len(before) == 4, "the copy has the root's children too"
    editor.redo()
    assert scene.get_component(copies[0], InfoComponent).name == "root copy"
    assert len(scene.get_component(copies[0], LinkComponent).children) == 3


def test_reparent_round_trips_and_keeps_the_world_place(gl_app) -> None:
    app, editor = gl_app
    scene = app.scene
    cube, camera = named(scene, "cube0"), named(scene, "camera")
    scene.get_component(named(scene, "root"), TransformComponent).translation = (0.5, -1.0, 2.0)
    app.run(frames=1)
    world = np.array(scene.get_component(cube, TransformComponent).world)
    round_trip(editor, scene, lambda: editor.reparent(cube, camera))
    editor.redo()
    app.run(frames=1)
    assert scene.parent_of(cube) == camera
    np.testing.assert_allclose(scene.get_component(cube, TransformComponent).world, world, atol=1e-12)
    editor.undo()
    round_trip(editor, scene, lambda: editor.reparent(cube, None))
    with pytest.raises(ValueError, match="inside it"):
        editor.reparent(named(scene, "root"), cube)


def test_add_and_remove_component_round_trip(gl_app) -> None:
    app, editor = gl_app
    scene = app.scene
    cube = named(scene, "cube2")
    round_trip(editor, scene, lambda: editor.add_component(cube, LightComponent("point", (1, 0.5, 0.2))))
    round_trip(editor, scene, lambda: editor.add_component(cube, InfoComponent("other")))  # replaces: undo restores
    round_trip(editor, scene, lambda: editor.remove_component(cube, MaterialComponent))
    round_trip(editor, scene, lambda: editor.remove_component(cube, TransformComponent))
    with pytest.raises(Exception, match="LightComponent"):
        editor.remove_component(cube, LightComponent)


def test_component_field_round_trips_and_bad_values_are_refused(gl_app) -> None:
    app, editor = gl_app
    scene = app.scene
    camera = named(scene, "camera")
    round_trip(editor, scene, lambda: editor.set_field(camera, CameraComponent, "fov", 70.0))
    depth = len(editor.commands.done)
    with pytest.raises(FieldError, match=r"CameraComponent\.fov"):
        editor.set_field(camera, CameraComponent, "fov", 400.0)
    with pytest.raises(AttributeError, match="no field 'nope'"):
        editor.set_field(camera, CameraComponent, "nope", 1.0)
    assert len(editor.commands.done) == depth, "a refused value is not recorded"
    assert scene.get_component(camera, CameraComponent).fov == 50.0


def test_a_drag_is_one_undo_step(gl_app) -> None:
    app, editor = gl_app
    cube = named(app.scene, "cube1")
    start = app.scene.get_component(cube, TransformComponent).translation.copy()
    for i in range(1, 6):
        editor.set_transform(cube, start + (0.1 * i, 0, 0), merge=True)
    editor.commands.seal()
    editor.set_transform(cube, start + (5.0, 0, 0))
    assert len(editor.commands.done) == 2
    editor.undo()
    np.testing.assert_allclose(app.scene.get_component(cube, TransformComponent).translation, start + (0.5, 0, 0))
    editor.undo()
    np.testing.assert_array_equal(app.scene.get_component(cube, TransformComponent).translation, start)
    editor.set_transform(cube, start + (1.0, 0, 0))
    assert not editor.commands.can_redo, "a new edit clears the redo list"


def test_material_colour_and_texture_round_trip(backend) -> None:
    with make_app(backend) as app:
        scene = editor_scene()
        scene.assets.texture("other", checkerboard(16, 2, (0.0, 0.0, 1.0), (1.0, 1.0, 1.0)))
        app.add_scene(scene)
        editor = enable_editor(app)
        editor.show_panel("viewport", True)
        app.run(frames=2)
        pictures = [editor.viewport.target.read_pixels()]
        editor.set_material_color("M", (0.1, 0.9, 0.1))
        app.run(frames=1)
        pictures.append(editor.viewport.target.read_pixels())
        assert editor.undo() == "colour of M"
        app.run(frames=1)
        assert editor.material_color("M") == pytest.approx((1.0, 0.6, 0.3))
        np.testing.assert_array_equal(editor.viewport.target.read_pixels(), pictures[0])
        editor.set_material_texture("M", "other")
        app.run(frames=1)
        assert scene.assets.materials["M"].textures == ("other",)
        textured = editor.viewport.target.read_pixels()
        assert np.any(textured != pictures[0], axis=2).sum() > 100, "the new texture shows"
        editor.undo()
        app.run(frames=1)
        assert scene.assets.materials["M"].textures == ("checker",)
        np.testing.assert_array_equal(editor.viewport.target.read_pixels(), pictures[0])
        editor.redo()
        app.run(frames=1)
        np.testing.assert_array_equal(editor.viewport.target.read_pixels(), textured)
        with pytest.raises(ValueError, match="no texture 'nope'"):
            editor.set_material_texture("M", "nope")
        editor.disable()


def test_spawn_mesh_names_and_places_it(gl_app) -> None:
    app, editor = gl_app
    entity = editor.spawn_mesh("cube", position=(0, 1, 0))
    assert app.scene.get_component(entity, InfoComponent).name == "cube"
    assert app.scene.get_component(entity, MaterialComponent).material == "M"
    with pytest.raises(ValueError, match="no mesh 'sphere'.*known: cube"):
        editor.spawn_mesh("sphere")


# --- the ECS hooks ---------------------------------------------------------------------------------------
class Counter(System):
    def __init__(self) -> None:
        super().__init__([TransformComponent])
        self.calls = 0

    def on_update_system(self, ts: float) -> None:
        self.calls += 1


def test_scene_hooks_enroll_with_an_id_move_and_run_systems() -> None:
    scene = Scene("hooks")
    entity = scene.create_entity(TransformComponent())
    with pytest.raises(ValueError, match="exists already"):
        scene.enroll_entity(entity)
    with pytest.raises(TypeError, match="uuid.UUID"):
        scene.enroll_entity("not-an-id")
    fresh = uuid.uuid4()
    assert scene.enroll_entity(fresh) == fresh and fresh in scene
    a, b = scene.add_system(Counter()), scene.add_system(Counter())
    scene.move_system(b, 0)
    assert scene.systems == [b, a]
    scene.move_system(b, 99)
    assert scene.systems == [a, b]
    a.enabled = False
    scene.update(1 / 60)
    assert (a.calls, b.calls) == (0, 1), "a paused system is skipped"
    scene.run_system(a, 1 / 60)
    assert a.calls == 1, "run_system runs a paused system once (the editor's single step)"
    assert b.update_seconds > 0.0


def test_the_console_collects_warnings_and_logging(gl_app) -> None:
    import logging

    _app, editor = gl_app
    with warnings.catch_warnings():
        warnings.simplefilter("always")
        warnings.warn("something odd", UserWarning, stacklevel=1)
    logging.getLogger("gandalf_core.test").warning("a log record")
    entries = list(editor.log.entries)
    assert any(e.level == "warning" and "something odd" in e.text and "test_editor_commands.py:" in e.text
               for e in entries), entries
    assert any(e.level == "warning" and e.source == "gandalf_core.test" and e.text == "a log record" for e in entries)
    editor.disable()
    logging.getLogger("gandalf_core.test").warning("after")
    assert "after" not in [e.text for e in editor.log.entries], "the handler goes with the editor"
