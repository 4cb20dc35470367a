"""Nothing paid for what did not change: the transform store reports the rows written since the last frame, the
transform system recomputes only those (and their descendants), and the render system packs and uploads only the
span of instance rows they occupy. Checked by structure (rows recomputed, rows uploaded) and by pictures: a frame
drawn from partial uploads is byte for byte the frame a fresh renderer draws from a full one."""

from __future__ import annotations

import numpy as np
import pytest
from core_shaders import build_shaders

from gandalf_core import Application, Scene, TransformComponent, TransformSystem
from gandalf_core.components import (
    CameraComponent,
    ClearColorComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
)
from gandalf_core.ecs import LinkComponent
from gandalf_core.math import look_at_rotation, quat_from_axis_angle
from gandalf_core.resources import MaterialData, cube
from gandalf_core.systems.transform_system import world_matrix

W, H = 96, 72


def test_the_store_reports_what_was_written_read_or_named() -> None:
    scene = Scene("changes")
    ids = scene.create_entities(10, TransformComponent.batch(translations=np.zeros((10, 3))))
    store = scene.store(TransformComponent)
    assert store.take_changes() is None  # new rows: anything may have changed
    assert len(store.take_changes()) == 0
    transforms = [scene.get_component(e, TransformComponent) for e in ids]
    transforms[7].translation = (1.0, 2.0, 3.0)
    transforms[2].quaternion[0] = 1.0  # written through the live view: reading marks the row
    _ = transforms[5].world  # the derived world matrix: reading it marks nothing
    assert store.take_changes().tolist() == [2, 7]
    store.columns["scale"][[4, 4, 9]] = 2.0
    store.touch(np.array([4, 4, 9]))
    store.touch(slice(0, 2))
    assert store.take_changes().tolist() == [0, 1, 4, 9]
    assert store.read("translation")[7].tolist() == [1.0, 2.0, 3.0]
    assert len(store.take_changes()) == 0  # read-only views mark nothing ...
    with pytest.raises(ValueError):
        store.read("translation")[0, 0] = 5.0  # ... and cannot be written
    store.column("translation")
    assert store.take_changes() is None  # a writable whole column: every row may change


def test_one_moving_entity_among_static_ones_recomputes_one_row() -> None:
    scene = Scene("static")
    n = 1000
    rng = np.random.default_rng(3)
    ids = scene.create_entities(n, TransformComponent.batch(translations=rng.normal(size=(n, 3))))
    system = scene.add_system(TransformSystem())
    scene.update(1 / 60)
    assert system.changed is None  # the first frame computes everything
    scene.update(1 / 60)
    assert system.changed is not None and len(system.changed) == 0
    mover = scene.get_component(ids[500], TransformComponent)
    for k in range(3):
        mover.quaternion = quat_from_axis_angle((0, 1, 0), 0.3 * k)
        mover.translation = (k, 0.5, -k)
        scene.update(1 / 60)
        assert system.changed.tolist() == [mover._row]
        np.testing.assert_allclose(mover.world, world_matrix(scene, ids[500]), atol=1e-12)


def test_a_moved_parent_recomputes_its_descendants_only() -> None:
    scene = Scene("tree")
    root = scene.create_entity(TransformComponent((1, 0, 0)))
    child = scene.create_entity(TransformComponent((0, 2, 0), (0, 0, 30)), LinkComponent(root))
    grandchild = scene.create_entity(TransformComponent((0, 0, 3), scale=2.0), LinkComponent(child))
    other = scene.create_entity(TransformComponent((5, 0, 0)))
    other_child = scene.create_entity(TransformComponent((0, 1, 0)), LinkComponent(other))
    system = scene.add_system(TransformSystem())
    scene.update(0.0)
    scene.update(0.0)
    scene.get_component(child, TransformComponent).rotation = (10, 20, 30)
    scene.update(0.0)
    rows = {scene.get_component(e, TransformComponent)._row for e in (child, grandchild)}
    assert set(system.changed.tolist()) == rows
    for e in (root, child, grandchild, other, other_child):
        np.testing.assert_allclose(scene.get_component(e, TransformComponent).world, world_matrix(scene, e),
                                   atol=1e-12)


def grid_scene(n: int) -> tuple[Scene, list]:
    scene = Scene("grid")
    scene.assets.mesh("cube", cube())
    scene.assets.material("M", MaterialData("lit", color=(0.8, 0.5, 0.3)))
    scene.create_entity(ClearColorComponent((0.1, 0.1, 0.15)))
    side = int(np.ceil(np.sqrt(n)))
    i = np.arange(n)
    positions = np.stack([(i % side) - side / 2, (i // side) - side / 2, np.full(n, -side * 1.2)], 1) * 1.1
    ids = scene.create_entities(n, TransformComponent.batch(translations=positions, scales=0.5),
                                MeshComponent("cube"), MaterialComponent("M"))
    sun = (2.0, 3.0, 4.0)
    scene.create_entity(TransformComponent(sun, quaternion=look_at_rotation(sun, (0, 0, 0))),
                        LightComponent("directional", (1.0, 1.0, 1.0)))
    eye = np.array([0.0, 0.0, 4.0])
    scene.create_entity(TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0, -side))),
                        CameraComponent(60.0, 0.1, 500.0))
    return scene, ids


def app_with(backend: str, scene: Scene) -> Application:
    app = Application(backend, W, H, headless=True, fixed_dt=1 / 60)
    build_shaders(app.renderer.shaders, backend, "lit")
    app.add_scene(scene)
    return app


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_static_entities_are_not_uploaded_again_and_the_picture_is_the_full_ones(backend: str) -> None:
    scene, ids = grid_scene(400)
    app = app_with(backend, scene)
    try:
        app.step()
        assert app.renderer.stats["instances_uploaded"] == 400
        app.step()
        assert app.renderer.stats["instances_uploaded"] == 0  # nothing moved: nothing uploaded
        movers = [scene.get_component(ids[k], TransformComponent) for k in (37, 41)]
        for frame in range(4):
            for k, mover in enumerate(movers):
                mover.rotation = (20.0 * frame, 35.0 * frame + 10 * k, 0.0)
                mover.scale = 0.5 + 0.1 * frame
            app.step()
            assert app.renderer.stats["instances_uploaded"] == 41 - 37 + 1  # the span of the two rows
        partial = app.capture()
        # The same state drawn by a fresh renderer, every row uploaded: the same bytes.
        fresh_scene, fresh_ids = grid_scene(400)
        for k, e in enumerate((37, 41)):
            fresh = fresh_scene.get_component(fresh_ids[e], TransformComponent)
            fresh.rotation, fresh.scale = (60.0, 105.0 + 10 * k, 0.0), 0.8
        fresh_app = app_with(backend, fresh_scene)
        try:
            fresh_app.step()
            assert fresh_app.renderer.stats["instances_uploaded"] == 400
            full = fresh_app.capture()
        finally:
            fresh_app.close()
        assert np.count_nonzero(np.any(partial != full, axis=-1)) == 0
        assert len(np.unique(partial.reshape(-1, 4), axis=0)) > 5  # lit cubes drawn, not a blank frame
    finally:
        app.close()


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_a_moving_camera_repacks_every_row(backend: str) -> None:
    scene, _ids = grid_scene(50)
    app = app_with(backend, scene)
    try:
        app.step()
        app.step()
        camera = next(t for t, c in scene.query(TransformComponent, CameraComponent).components)
        camera.translation = camera.translation + (0.25, 0.0, 0.0)
        app.step()
        assert app.renderer.stats["instances_uploaded"] == 50  # camera-relative rows all moved
    finally:
        app.close()


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_with_the_transform_system_paused_every_row_is_packed(backend: str) -> None:
    """Paused, the transform system says nothing about what changed: a world matrix written by hand must still
    be drawn, so every row is packed and uploaded."""
    scene, ids = grid_scene(20)
    app = app_with(backend, scene)
    try:
        app.step()
        next(s for s in scene.systems if isinstance(s, TransformSystem)).enabled = False
        moved = scene.get_component(ids[3], TransformComponent)
        moved.world = moved.world @ np.diag([2.0, 2.0, 2.0, 1.0])
        app.step()
        assert app.renderer.stats["instances_uploaded"] == 20
    finally:
        app.close()


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_unchanged_lights_are_not_uploaded_again_and_a_changed_light_is_drawn(backend: str) -> None:
    scene, _ids = grid_scene(20)
    app = app_with(backend, scene)
    try:
        app.step()
        assert app.renderer.stats["lights_uploaded"] == 1
        app.step()
        before = app.capture()
        assert app.renderer.stats["lights_uploaded"] == 0  # same lights, same camera: the buffer holds them
        light = next(lc for lc, _t in scene.query(LightComponent, TransformComponent).components)
        light.color = (1.0, 0.2, 0.2)
        app.step()
        assert app.renderer.stats["lights_uploaded"] == 1
        reddened = app.capture()
        assert np.count_nonzero(np.any(reddened != before, axis=-1)) > 100, "the changed light was not drawn"
        app.step()
        assert app.renderer.stats["lights_uploaded"] == 0
        assert np.array_equal(app.capture(), reddened)
    finally:
        app.close()
