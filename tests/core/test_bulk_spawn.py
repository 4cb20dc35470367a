"""Scene.create_entities (bulk spawn), TransformComponent.batch, and the per-entity fast paths of the maths.

The fast paths (single quaternions / 3-vectors as float64 arrays or tuples of numbers) must give the same numbers
as the batched numpy path and raise the same errors; bulk-created entities must behave exactly like entities
created one by one (systems, column store, removal, USD-free round trips through the scene API).
"""

from __future__ import annotations

import uuid

import numpy as np
import pytest

from gandalf_core import Scene, System, TransformComponent, TransformSystem
from gandalf_core.components import MaterialComponent, MeshComponent
from gandalf_core.ecs import Component, LinkComponent, NotAComponentError
from gandalf_core.math import quat_conjugate, quat_from_axis_angle, quat_mul, quat_normalize, quat_rotate


class Spin(Component):
    def __init__(self, speed: float = 1.0) -> None:
        self.speed = speed


class Recorder(System):
    def __init__(self) -> None:
        super().__init__([TransformComponent, Spin])
        self.created: list[uuid.UUID] = []

    def on_create_entity(self, entity, components) -> None:
        assert isinstance(components[0], TransformComponent) and isinstance(components[1], Spin)
        self.created.append(entity)


def test_create_entities_matches_one_by_one() -> None:
    n = 50
    rng = np.random.default_rng(3)
    xyz = rng.normal(size=(n, 3))
    degrees = rng.uniform(-180, 180, size=(n, 3))
    scene = Scene()
    scene.add_system(TransformSystem())
    recorder = scene.add_system(Recorder())
    render_like = scene.add_system(System([TransformComponent, MeshComponent, MaterialComponent]))
    ids = scene.create_entities(n, TransformComponent.batch(translations=xyz, rotations=degrees, scales=2.0),
                                MeshComponent("cube"), MaterialComponent("lit"), Spin(0.5))
    assert len(ids) == n and len(set(ids)) == n and all(i.version == 4 for i in ids)
    assert recorder.created == ids  # on_create_entity once per entity, in order
    assert render_like.entities == ids
    scene.update(0.0)
    for i, entity in enumerate(ids):
        t = scene.get_component(entity, TransformComponent)
        ref = TransformComponent(xyz[i], degrees[i], 2.0)
        np.testing.assert_allclose(t.translation, ref.translation)
        np.testing.assert_allclose(t.quaternion, ref.quaternion, atol=1e-15)
        np.testing.assert_allclose(t.scale, (2.0, 2.0, 2.0))
        np.testing.assert_allclose(t.world[:3, 3], xyz[i])
    spins = [scene.get_component(e, Spin) for e in ids]
    assert len({id(s) for s in spins}) == n and all(s.speed == 0.5 for s in spins)  # copies, not one object
    # Mixed with one-by-one entities, removal swaps rows correctly.
    extra = scene.create_entity(TransformComponent((9, 9, 9)), Spin())
    scene.destroy_entity(ids[0])
    assert scene.get_component(extra, TransformComponent).translation.tolist() == [9, 9, 9]
    np.testing.assert_allclose(scene.get_component(ids[-1], TransformComponent).translation, xyz[-1])
    assert ids[0] not in recorder._members and len(recorder) == n


def test_create_entities_sequences_links_and_defaults() -> None:
    scene = Scene()
    parent = scene.create_entity(TransformComponent((1, 0, 0)))
    ids = scene.create_entities(3, TransformComponent.batch(3), [Spin(i) for i in range(3)],
                                [LinkComponent(parent) for _ in range(3)])
    assert [scene.get_component(e, Spin).speed for e in ids] == [0, 1, 2]
    assert scene.get_component(parent, LinkComponent).children == ids
    t = scene.get_component(ids[1], TransformComponent)
    assert t.quaternion.tolist() == [1, 0, 0, 0] and t.scale.tolist() == [1, 1, 1]
    assert scene.create_entities(0, TransformComponent.batch(0)) == []


def test_create_entities_errors_name_the_problem() -> None:
    scene = Scene("s")
    with pytest.raises(ValueError, match="2 rows, n is 3"):
        scene.create_entities(3, TransformComponent.batch(translations=np.zeros((2, 3))))
    with pytest.raises(ValueError, match=r"pass TransformComponent.batch\(...\)"):
        scene.create_entities(3, TransformComponent())
    with pytest.raises(NotAComponentError, match=r"pass an instance: Spin\(...\)"):
        scene.create_entities(3, Spin)
    with pytest.raises(ValueError, match="2 components given for 3 entities"):
        scene.create_entities(3, [Spin(), Spin()])
    with pytest.raises(ValueError, match="two components of one type"):
        scene.create_entities(3, Spin(), Spin())
    with pytest.raises(ValueError, match="non-negative int"):
        scene.create_entities(-1)
    with pytest.raises(ValueError, match=r"translations? must be finite \(row 1\)"):
        TransformComponent.batch(translations=[[0, 0, 0], [np.nan, 0, 0]])
    with pytest.raises(ValueError, match="must have shape"):
        TransformComponent.batch(translations=np.zeros((4, 2)))
    with pytest.raises(ValueError, match="not both"):
        TransformComponent.batch(rotations=np.zeros(3), quaternions=(1, 0, 0, 0))
    with pytest.raises(ValueError, match="quaternions: q is a zero quaternion"):
        TransformComponent.batch(quaternions=np.zeros((2, 4)))
    with pytest.raises(ValueError, match="give n"):
        TransformComponent.batch(translations=(1, 2, 3))
    with pytest.raises(ValueError, match="unknown field"):
        TransformComponent.__mro__[1].batch.__func__(TransformComponent, 2, position=(0, 0, 0))
    assert len(scene) == 0  # nothing half-made


def test_bulk_spawn_100k_is_fast() -> None:
    """Not a timing target (CI machines vary): a loose bound that catches a per-entity Python path."""
    import time

    n = 100_000
    scene = Scene()
    scene.add_system(TransformSystem())
    scene.add_system(System([TransformComponent, MeshComponent, MaterialComponent]))
    xyz = np.zeros((n, 3))
    t0 = time.process_time()
    ids = scene.create_entities(n, TransformComponent.batch(translations=xyz), MeshComponent("m"),
                                MaterialComponent("x"))
    cpu = time.process_time() - t0
    assert len(ids) == n and scene.store(TransformComponent).count == n
    assert cpu < 4.0, f"creating {n} entities took {cpu:.2f} s of CPU (target 0.5 s on a quiet machine)"


@pytest.mark.parametrize("seed", range(5))
def test_single_fast_paths_equal_batched(seed: int) -> None:
    rng = np.random.default_rng(seed)
    for _ in range(50):
        a, b = rng.normal(size=4), rng.normal(size=4)
        v = rng.normal(size=3) * 10
        axis, angle = rng.normal(size=3), float(rng.normal() * 4)
        np.testing.assert_allclose(quat_mul(a, b), quat_mul(a[None], b[None])[0], rtol=0, atol=1e-15)
        np.testing.assert_allclose(quat_mul(tuple(a), list(b)), quat_mul(a, b), rtol=0, atol=0)
        np.testing.assert_allclose(quat_normalize(a), quat_normalize(a[None])[0], rtol=0, atol=1e-15)
        np.testing.assert_allclose(quat_rotate(quat_normalize(a), v), quat_rotate(quat_normalize(a)[None], v[None])[0],
                                   rtol=0, atol=1e-13)
        np.testing.assert_allclose(quat_conjugate(a), quat_conjugate(a[None])[0])
        half = 0.5 * angle
        ref = np.concatenate([[np.cos(half)], np.sin(half) * axis / np.linalg.norm(axis)])
        np.testing.assert_allclose(quat_from_axis_angle(axis, angle), ref, rtol=0, atol=1e-15)
        np.testing.assert_allclose(quat_from_axis_angle(tuple(axis), np.float64(angle)), ref, rtol=0, atol=1e-15)


@pytest.mark.parametrize("bad", [(np.nan, 0, 0, 0), (np.inf, 0, 0, 1)])
def test_single_fast_paths_keep_their_errors(bad) -> None:
    q = np.array(bad, dtype=np.float64)
    one = np.array([1.0, 0, 0, 0])
    with pytest.raises(ValueError, match="a must be finite"):
        quat_mul(q, one)
    with pytest.raises(ValueError, match="b must be finite"):
        quat_mul(one, q)
    with pytest.raises(ValueError, match="q must be finite"):
        quat_normalize(q)
    with pytest.raises(ValueError, match="q must be finite"):
        quat_rotate(q, np.ones(3))
    with pytest.raises(ValueError, match="q must be finite"):
        quat_conjugate(q)


def test_single_fast_paths_edge_inputs() -> None:
    with pytest.raises(ValueError, match="zero quaternion"):
        quat_normalize(np.zeros(4))
    with pytest.raises(ValueError, match="their product is zero"):
        quat_mul(np.zeros(4), np.array([1.0, 0, 0, 0]))
    with pytest.raises(ValueError, match="non-zero vector"):
        quat_from_axis_angle(np.zeros(3), 1.0)
    with pytest.raises(ValueError, match="radians must be finite"):
        quat_from_axis_angle(np.ones(3), float("inf"))
    # Extreme but valid lengths take the careful path and still give unit quaternions.
    for scale in (1e-200, 1e200):
        q = quat_normalize(np.array([1.0, 1.0, 0, 0]) * scale)
        np.testing.assert_allclose(q, [2**-0.5, 2**-0.5, 0, 0], rtol=1e-15)
        np.testing.assert_allclose(quat_from_axis_angle(np.array([0, 0, scale]), np.pi), [np.cos(np.pi / 2), 0, 0, 1],
                                   atol=1e-15)


def test_column_setter_fast_path_checks() -> None:
    scene = Scene()
    e = scene.create_entity(TransformComponent())
    t = scene.get_component(e, TransformComponent)
    t.translation = np.array([1.0, 2.0, 3.0])
    t.quaternion = (0.0, 1.0, 0.0, 0.0)
    assert t.translation.tolist() == [1, 2, 3] and t.quaternion.tolist() == [0, 1, 0, 0]
    for bad in (np.array([np.nan, 0, 0]), (np.inf, 0, 0), [1e308, 1e308, -np.inf]):
        with pytest.raises(ValueError, match="TransformComponent.translation must be finite"):
            t.translation = bad
    t.translation = (1e308, 1e308, 1e308)  # the sum overflows: the full check decides, and it is finite
    assert t.translation[0] == 1e308
    with pytest.raises(ValueError, match="must have shape"):
        t.translation = np.zeros(4)
    loose = TransformComponent()
    loose.translation = np.array([4.0, 5.0, 6.0])
    value = loose.translation
    value[0] = 7.0  # an unattached component's local value is its own copy
    assert loose.translation[0] == 7.0
