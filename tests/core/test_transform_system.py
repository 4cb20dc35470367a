"""Tests for the transform system: vectorised world matrices by hierarchy level against a naive reference.

``world_matrix`` walks the ancestors one by one with scalar ``trs``; the system builds every local
matrix at once and resolves the hierarchy level by level. They must agree for any hierarchy, after any
change, at any depth and for extreme scales.
"""

from __future__ import annotations

import uuid

import numpy as np
import pytest

from gandalf_core.components import InfoComponent, LinkComponent, TransformComponent
from gandalf_core.ecs import Scene
from gandalf_core.math import quat_from_axis_angle, trs
from gandalf_core.systems import TransformSystem, set_parent_keep_world, world_matrix


def random_quaternion(rng: np.random.Generator) -> np.ndarray:
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)


def random_hierarchy(seed: int, n: int = 80) -> tuple[Scene, list[uuid.UUID]]:
    """Entities with random TRS under random parents; some links carry no Transform, rows get shuffled."""
    rng = np.random.default_rng(seed)
    scene = Scene()
    scene.add_system(TransformSystem())
    entities: list[uuid.UUID] = []
    for i in range(n):
        parent = entities[int(rng.integers(len(entities)))] if entities and rng.random() < 0.8 else None
        comps = [LinkComponent(parent), InfoComponent(f"n{i}")]
        if rng.random() < 0.9:  # a Link without Transform counts as identity for its children
            scale = rng.uniform(0.3, 3.0, size=3) if rng.random() < 0.5 else rng.uniform(0.3, 3.0)
            comps.append(TransformComponent(rng.uniform(-5, 5, 3), quaternion=random_quaternion(rng), scale=scale))
        entities.append(scene.create_entity(*comps))
    # Re-parent some entities under later ones so a child's row can come before its parent's.
    for entity in rng.permutation(entities)[: n // 4]:
        parent = entities[int(rng.integers(n))]
        if parent != entity and not is_ancestor(scene, entity, parent):
            scene.set_parent(entity, parent)
    return scene, entities


def is_ancestor(scene: Scene, ancestor: uuid.UUID, entity: uuid.UUID) -> bool:
    node = scene.parent_of(entity)
    while node is not None:
        if node == ancestor:
            return True
        node = scene.parent_of(node)
    return False


def assert_worlds_match_reference(scene: Scene, atol: float = 1e-9) -> None:
    """Every Transform's system-written world equals the recursive reference (entries of size ~1..1e3)."""
    for entity in scene.entities:
        transform = scene.try_component(entity, TransformComponent)
        if transform is not None:
            np.testing.assert_allclose(transform.world, world_matrix(scene, entity), rtol=1e-12, atol=atol)


@pytest.mark.parametrize("seed", range(6))
def test_world_matrices_equal_the_recursive_reference(seed: int) -> None:
    scene, entities = random_hierarchy(seed)
    depth = max(sum(1 for _ in ancestors(scene, e)) for e in entities)
    assert depth >= 4  # the random tree really is a hierarchy
    scene.update(0.0)
    assert_worlds_match_reference(scene)


def ancestors(scene: Scene, entity: uuid.UUID):
    node = scene.parent_of(entity)
    while node is not None:
        yield node
        node = scene.parent_of(node)


def test_hierarchy_and_membership_changes_are_picked_up() -> None:
    scene, entities = random_hierarchy(11)
    rng = np.random.default_rng(5)
    scene.update(0.0)
    for round_ in range(10):
        victim = entities[int(rng.integers(len(entities)))]
        if victim in scene and scene.has_component(victim, TransformComponent) and round_ % 2:
            scene.remove_component(victim, TransformComponent)  # swap-remove moves another row
        elif victim in scene and round_ % 3 == 0:
            scene.destroy_entity(victim)
        mover = next(e for e in rng.permutation(entities) if e in scene)
        new_parent = next(e for e in rng.permutation(entities) if e in scene)
        if new_parent != mover and not is_ancestor(scene, mover, new_parent):
            scene.set_parent(mover, new_parent)
        scene.update(0.0)
        assert_worlds_match_reference(scene)


def test_child_follows_when_only_an_ancestor_moved() -> None:
    scene = Scene()
    scene.add_system(TransformSystem())
    root = scene.create_entity(TransformComponent((1, 0, 0)), LinkComponent())
    middle = scene.create_entity(TransformComponent((0, 2, 0), rotation=(0, 0, 90)), LinkComponent(root))
    leaf = scene.create_entity(TransformComponent((3, 0, 0)), LinkComponent(middle))
    scene.update(0.0)
    leaf_t = scene.get_component(leaf, TransformComponent)
    # Rz(90) maps the leaf's (3, 0, 0) to (0, 3, 0): world position (1, 2, 0) + (0, 3, 0).
    np.testing.assert_allclose(leaf_t.world_position, (1, 5, 0), atol=1e-12)
    scene.get_component(root, TransformComponent).translation = (10, 0, 0)
    scene.update(0.0)
    np.testing.assert_allclose(leaf_t.world_position, (10, 5, 0), atol=1e-12)
    scene.get_component(middle, TransformComponent).rotation = (0, 0, 180)
    scene.update(0.0)
    np.testing.assert_allclose(leaf_t.world_position, (7, 2, 0), atol=1e-12)
    assert_worlds_match_reference(scene)


def test_thousand_deep_chain_matches_the_closed_form() -> None:
    # Every link translates by (1, 0, 0) and turns by theta about z, so the world matrix of depth k is
    # known exactly: rotation k*theta, position sum_{j<k} R(j*theta) (1, 0, 0).
    depth, theta = 1000, 2 * np.pi / 997
    q = quat_from_axis_angle((0, 0, 1), theta)
    scene = Scene()
    scene.add_system(TransformSystem())
    chain, parent = [], None
    for _ in range(depth):
        parent = scene.create_entity(TransformComponent((1, 0, 0), quaternion=q), LinkComponent(parent))
        chain.append(parent)
    scene.update(0.0)
    angles = theta * np.arange(depth + 1)
    px, py = np.cumsum(np.cos(angles)), np.cumsum(np.sin(angles))
    worst = 0.0
    for k in (1, 2, 10, 333, 999, 1000):
        world = scene.get_component(chain[k - 1], TransformComponent).world
        a = angles[k]
        exact = np.array([[np.cos(a), -np.sin(a), 0, px[k - 1]], [np.sin(a), np.cos(a), 0, py[k - 1]],
                          [0, 0, 1, 0], [0, 0, 0, 1]])
        assert np.all(np.isfinite(world))
        worst = max(worst, float(np.max(np.abs(world - exact))))
    # 1000 products of rounded matrices: error grows about linearly, ~1000 * 1e-16 per unit of size.
    assert worst < 1e-10, worst
    tip = chain[-1]
    np.testing.assert_allclose(scene.get_component(tip, TransformComponent).world, world_matrix(scene, tip), atol=1e-10)


@pytest.mark.parametrize("scale", [1e-6, 1e6])
def test_extreme_scales_stay_finite_and_exact(scale: float) -> None:
    scene = Scene()
    scene.add_system(TransformSystem())
    rng = np.random.default_rng(1)
    parent, chain = None, []
    for _ in range(10):
        parent = scene.create_entity(
            TransformComponent(rng.uniform(-1, 1, 3), quaternion=random_quaternion(rng), scale=scale),
            LinkComponent(parent),
        )
        chain.append(parent)
    scene.update(0.0)
    for k, entity in enumerate(chain, start=1):
        world = scene.get_component(entity, TransformComponent).world
        assert np.all(np.isfinite(world))
        reference = world_matrix(scene, entity)
        # Relative to the size of the entries (scale**k for the 3x3 part), not absolute.
        np.testing.assert_allclose(world[:3, :3] / scale**k, reference[:3, :3] / scale**k, atol=1e-12)
        size = max(1.0, scale ** (k - 1))
        np.testing.assert_allclose(world[:3, 3] / size, reference[:3, 3] / size, atol=1e-12)


def test_set_parent_keep_world_keeps_the_pose() -> None:
    rng = np.random.default_rng(7)
    scene = Scene()
    scene.add_system(TransformSystem())

    def node(parent: uuid.UUID | None, uniform: bool = True) -> uuid.UUID:
        scale = rng.uniform(0.5, 2.0) if uniform else rng.uniform(0.5, 2.0, 3)
        t = TransformComponent(rng.uniform(-5, 5, 3), quaternion=random_quaternion(rng), scale=scale)
        return scene.create_entity(t, LinkComponent(parent))

    # Uniform scales on the ancestors: a rotated child under a non-uniform parent would need shear,
    # which a TRS cannot hold.
    a = node(None)
    a1 = node(a)
    b = node(None)
    b1 = node(b)
    b2 = node(b1)
    mover = node(a1, uniform=False)
    loose = scene.create_entity(TransformComponent((1, 2, 3), rotation=(10, 20, 30), scale=0.5))
    for target in (b2, None, b, a, b1):
        before = world_matrix(scene, mover)
        set_parent_keep_world(scene, mover, target)
        assert scene.parent_of(mover) == target
        np.testing.assert_allclose(world_matrix(scene, mover), before, rtol=0, atol=1e-9)
        scene.update(0.0)
        np.testing.assert_allclose(scene.get_component(mover, TransformComponent).world, before, rtol=0, atol=1e-9)
    # An entity without a Link gets one.
    before = world_matrix(scene, loose)
    set_parent_keep_world(scene, loose, b2)
    assert scene.parent_of(loose) == b2
    np.testing.assert_allclose(world_matrix(scene, loose), before, rtol=0, atol=1e-9)


def test_zero_quaternion_is_treated_as_identity() -> None:
    scene = Scene()
    scene.add_system(TransformSystem())
    parent = scene.create_entity(TransformComponent((1, 2, 3), scale=2.0), LinkComponent())
    child = scene.create_entity(TransformComponent((1, 0, 0)), LinkComponent(parent))
    scene.get_component(parent, TransformComponent).quaternion = (0, 0, 0, 0)
    scene.update(0.0)
    expected_parent = trs((1, 2, 3), (1, 0, 0, 0), 2.0)
    world = scene.get_component(parent, TransformComponent).world
    np.testing.assert_array_equal(world, expected_parent)
    np.testing.assert_allclose(scene.get_component(child, TransformComponent).world_position, (3, 2, 3), atol=1e-15)
    np.testing.assert_array_equal(world_matrix(scene, parent), expected_parent)
    # Unnormalised quaternions are renormalised, not applied as a scaling.
    scene.get_component(parent, TransformComponent).quaternion = (5, 0, 0, 0)
    scene.update(0.0)
    np.testing.assert_allclose(scene.get_component(parent, TransformComponent).world, expected_parent, atol=1e-15)


def test_entities_without_a_transform_count_as_identity_in_the_chain() -> None:
    scene = Scene()
    scene.add_system(TransformSystem())
    root = scene.create_entity(TransformComponent((0, 1, 0)), LinkComponent())
    group = scene.create_entity(InfoComponent("group"), LinkComponent(root))
    leaf = scene.create_entity(TransformComponent((2, 0, 0)), LinkComponent(group))
    scene.update(0.0)
    np.testing.assert_allclose(scene.get_component(leaf, TransformComponent).world_position, (2, 1, 0))
    scene.add_component(group, TransformComponent((0, 0, 5)))  # now the group moves its children
    scene.update(0.0)
    np.testing.assert_allclose(scene.get_component(leaf, TransformComponent).world_position, (2, 1, 5))


def test_hundred_thousand_entities_update() -> None:
    n = 100_000
    rng = np.random.default_rng(0)
    translations = rng.uniform(-100, 100, (n, 3))
    scene = Scene()
    system = scene.add_system(TransformSystem())
    entities = [scene.create_entity(TransformComponent(translations[i])) for i in range(n)]
    # A few hierarchies among them: every 1000th entity is parented under the entity before it.
    for i in range(1000, n, 1000):
        scene.add_component(entities[i], LinkComponent(entities[i - 1]))
    store = scene.store(TransformComponent)
    store.column("quaternion")[:] = quat_from_axis_angle((0, 1, 0), 0.5)
    scene.update(1 / 60)
    assert len(system) == n and store.count == n
    assert np.all(np.isfinite(store.column("world")))
    for i in (0, 1, 999, 1000, 54_321, n - 1):
        entity = entities[i]
        np.testing.assert_allclose(
            scene.get_component(entity, TransformComponent).world, world_matrix(scene, entity), atol=1e-9
        )


def test_a_non_finite_value_written_through_a_view_names_the_entity() -> None:
    scene = Scene("nan")
    scene.create_entity(InfoComponent("fine"), TransformComponent())
    broken = scene.create_entity(InfoComponent("broken"), TransformComponent())
    system = scene.add_system(TransformSystem())
    scene.get_component(broken, TransformComponent).translation[1] = float("nan")
    with pytest.raises(ValueError, match=r"entity 'broken'.*TransformComponent.translation is not finite"):
        system.on_update_system(0.0)


@pytest.mark.parametrize("seed", range(3))
def test_deep_forests_resolved_by_pointer_jumping_match_the_reference(seed: int, monkeypatch) -> None:
    """Deeper than DEEP levels the system jumps pointers instead of walking levels: a forest of a long chain,
    random branches off it and shallow trees (with Transform-less links) must give the same world matrices."""
    import gandalf_core.systems.transform_system as module

    scene, entities = random_hierarchy(seed, n=60)
    rng = np.random.default_rng(seed)
    chain = entities[-1]
    for i in range(40):  # a chain well past DEEP, hanging off the random tree
        chain = scene.create_entity(LinkComponent(chain), InfoComponent(f"c{i}"),
                                    TransformComponent(rng.uniform(-0.2, 0.2, 3), quaternion=random_quaternion(rng),
                                                       scale=rng.uniform(0.9, 1.1)))
        if rng.random() < 0.3:  # side branches
            scene.create_entity(LinkComponent(chain), TransformComponent(rng.uniform(-1, 1, 3)))
    system = next(s for s in scene.systems if isinstance(s, TransformSystem))
    scene.update(0.0)
    assert system._jumps is not None, "the forest should be deep enough for pointer jumping"
    assert_worlds_match_reference(scene, atol=1e-8)
    monkeypatch.setattr(module, "DEEP", 10**6)  # the level-by-level walk gives the same matrices
    system._plan_key = None
    scene.update(0.0)
    assert system._jumps is None
    assert_worlds_match_reference(scene, atol=1e-8)
