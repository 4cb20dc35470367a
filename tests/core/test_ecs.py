"""Tests for the ECS: scenes, components (plain and columnar), systems, queries, hierarchy, scene switching.

The centrepiece is a hypothesis state machine that drives two scenes through random enrolls, component
adds/removes, destroys, re-parents and scene switches, and checks every cached view against a plain
dictionary model after each step.
"""

from __future__ import annotations

import uuid
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, initialize, invariant, precondition, rule

from gandalf_core.components import TransformComponent
from gandalf_core.ecs import (
    Component,
    HierarchyCycleError,
    InfoComponent,
    LinkComponent,
    MissingComponentError,
    NotAComponentError,
    Scene,
    SceneManager,
    System,
    UnknownEntityError,
)
from gandalf_core.systems import TransformSystem, world_matrix


class A(Component):
    def __init__(self, value: int = 0) -> None:
        self.value = value


class B(Component):
    def __init__(self, value: int = 0) -> None:
        self.value = value


class C(Component):
    pass


class Velocity(Component):
    def __init__(self, v: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> None:
        self.v = np.asarray(v, dtype=np.float64)


class HookRecorder(System):
    """Keeps its own member set from the hooks alone, so the tests can compare it with the cache."""

    def __init__(self, types: list[type[Component]], name: str | None = None) -> None:
        super().__init__(types, name=name)
        self.created = 0
        self.removed = 0
        self.seen: dict[uuid.UUID, tuple[Any, ...]] = {}

    def on_create_entity(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        assert entity not in self.seen, f"{self.name}: on_create_entity twice for {entity}"
        self.created += 1
        self.seen[entity] = components

    def on_remove_entity(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        assert self.seen.get(entity) == components, f"{self.name}: on_remove_entity with other components"
        self.removed += 1
        del self.seen[entity]


# ---------------------------------------------------------------------------------------------
# Stateful test against a dictionary model

COMPONENT_KINDS = ("info", "transform", "velocity", "link")
KIND_TYPE = {"info": InfoComponent, "transform": TransformComponent, "velocity": Velocity, "link": LinkComponent}
SYSTEM_TYPES = (
    [TransformComponent],
    [TransformComponent, Velocity],
    [LinkComponent, InfoComponent],
    [Velocity, TransformComponent, LinkComponent],
    [InfoComponent],
)
coord = st.integers(-50, 50).map(float)


class SceneModel:
    """What one scene should contain: component objects per entity, translations, parents."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self.comps: dict[uuid.UUID, dict[type, Component]] = {}
        self.translation: dict[uuid.UUID, np.ndarray] = {}
        self.systems = [HookRecorder(types, name=f"{scene.name}-sys{i}") for i, types in enumerate(SYSTEM_TYPES)]
        for system in self.systems:
            scene.add_system(system)
        scene.add_system(TransformSystem())
        self.queries = [scene.query(InfoComponent, TransformComponent), scene.query(LinkComponent)]
        self.parents: dict[uuid.UUID, uuid.UUID | None] = {}  # entities with a Link -> their parent

    def would_cycle(self, entity: uuid.UUID, parent: uuid.UUID | None) -> bool:
        node = parent
        while node is not None:
            if node == entity:
                return True
            node = self.parents.get(node)
        return False

    def children_of(self, entity: uuid.UUID) -> set[uuid.UUID]:
        return {e for e, p in self.parents.items() if p == entity}

    def drop_link(self, entity: uuid.UUID) -> None:
        """Model of removing a Link: its children become roots."""
        for child in self.children_of(entity):
            self.parents[child] = None
        del self.parents[entity]
        del self.comps[entity][LinkComponent]

    def link_to(self, entity: uuid.UUID, parent: uuid.UUID | None) -> None:
        """Model of attaching under ``parent``: a parent without a Link gets one (as a root)."""
        self.parents[entity] = parent
        if parent is not None and LinkComponent not in self.comps[parent]:
            self.parents[parent] = None
            # The scene created that Link; take its object into the model.
            self.comps[parent][LinkComponent] = self.scene.get_component(parent, LinkComponent)


class SceneMachine(RuleBasedStateMachine):
    def __init__(self) -> None:
        super().__init__()
        self.manager = SceneManager()
        self.models = {}
        for name in ("first", "second"):
            scene = Scene(name)
            self.models[name] = SceneModel(scene)
            self.manager.add(scene)
        self.names = 0

    @property
    def model(self) -> SceneModel:
        return self.models[self.manager.active.name]

    @property
    def scene(self) -> Scene:
        return self.manager.active

    def _entity(self, data: st.DataObject, label: str = "entity") -> uuid.UUID:
        return data.draw(st.sampled_from(list(self.model.comps)), label=label)

    def _parent(self, data: st.DataObject) -> uuid.UUID | None:
        return data.draw(st.sampled_from([None, *self.model.comps]), label="parent")

    def has_entities(self) -> bool:
        return bool(self.model.comps)

    # --- rules -----------------------------------------------------------------------------------
    # (Hypothesis favours rules listed first; the cheap ones come last so the interesting ones run often.)
    @initialize()
    def populate(self) -> None:
        for model in self.models.values():
            for _ in range(4):
                model.comps[model.scene.enroll_entity()] = {}

    @precondition(has_entities)
    @rule(data=st.data(), kind=st.sampled_from(COMPONENT_KINDS), t=st.tuples(coord, coord, coord))
    def add_component(self, data: st.DataObject, kind: str, t: tuple[float, float, float]) -> None:
        model, scene = self.model, self.scene
        entity = self._entity(data)
        if kind == "link":
            parent = self._parent(data)
            if model.would_cycle(entity, parent):
                with pytest.raises(HierarchyCycleError):
                    scene.add_component(entity, LinkComponent(parent))
                return
            link = scene.add_component(entity, LinkComponent(parent))
            kept: set[uuid.UUID] = set()
            if LinkComponent in model.comps[entity]:
                # A new Link changes the parent; the entity keeps its children.
                kept = model.children_of(entity)
                model.drop_link(entity)
            model.comps[entity][LinkComponent] = link
            model.link_to(entity, parent)
            for child in kept:
                model.parents[child] = entity
            return
        if kind == "info":
            self.names += 1
            component: Component = InfoComponent(f"e{self.names}")
        elif kind == "transform":
            component = TransformComponent(translation=t)
            model.translation[entity] = np.array(t)
        else:
            component = Velocity(t)
        assert scene.add_component(entity, component) is component
        model.comps[entity][KIND_TYPE[kind]] = component

    @precondition(has_entities)
    @rule(data=st.data())
    def remove_component(self, data: st.DataObject) -> None:
        model, scene = self.model, self.scene
        entity = self._entity(data)
        present = list(model.comps[entity])
        if not present:
            with pytest.raises(MissingComponentError):
                scene.remove_component(entity, InfoComponent)
            return
        component_type = data.draw(st.sampled_from(present), label="type")
        removed = scene.remove_component(entity, component_type)
        assert removed is model.comps[entity][component_type]
        if component_type is LinkComponent:
            model.drop_link(entity)
        else:
            del model.comps[entity][component_type]
        if component_type is TransformComponent:
            # A detached component keeps its values (they are copied out of the column).
            np.testing.assert_array_equal(removed.translation, model.translation.pop(entity))

    @precondition(has_entities)
    @rule(data=st.data())
    def destroy_entity(self, data: st.DataObject) -> None:
        model, scene = self.model, self.scene
        entity = self._entity(data)
        doomed, frontier = set(), [entity]
        while frontier:
            node = frontier.pop()
            doomed.add(node)
            frontier.extend(model.children_of(node))
        scene.destroy_entity(entity)
        for node in doomed:
            del model.comps[node]
            model.translation.pop(node, None)
            model.parents.pop(node, None)
        # A surviving parent of the destroyed entity keeps its Link, without the child.
        for node in model.parents:
            assert model.parents[node] not in doomed

    @precondition(has_entities)
    @rule(data=st.data())
    def set_parent(self, data: st.DataObject) -> None:
        model, scene = self.model, self.scene
        entity = self._entity(data)
        parent = self._parent(data)
        if LinkComponent not in model.comps[entity]:
            with pytest.raises(MissingComponentError):
                scene.set_parent(entity, parent)
            return
        if model.would_cycle(entity, parent):
            with pytest.raises(HierarchyCycleError):
                scene.set_parent(entity, parent)
            return
        scene.set_parent(entity, parent)
        model.link_to(entity, parent)

    @precondition(lambda self: bool(self.model.translation))
    @rule(data=st.data(), t=st.tuples(coord, coord, coord))
    def move(self, data: st.DataObject, t: tuple[float, float, float]) -> None:
        entity = data.draw(st.sampled_from(list(self.model.translation)), label="moved")
        self.scene.get_component(entity, TransformComponent).translation = t
        self.model.translation[entity] = np.array(t)

    @rule(by_name=st.booleans())
    def switch_scene(self, by_name: bool) -> None:
        other = next(m.scene for m in self.models.values() if m.scene is not self.scene)
        self.manager.request_switch(other.name if by_name else other)
        assert self.manager.active is not other  # deferred until the next frame starts
        assert self.manager.apply_pending()
        assert self.manager.active is other

    @rule()
    def run_frame(self) -> None:
        self.scene.update(1 / 60)
        for entity in self.model.translation:
            world = self.scene.get_component(entity, TransformComponent).world
            np.testing.assert_allclose(world, world_matrix(self.scene, entity), atol=1e-9)

    @rule()
    def enroll(self) -> None:
        entity = self.scene.enroll_entity()
        assert entity not in self.model.comps
        self.model.comps[entity] = {}

    # --- invariants --------------------------------------------------------------------------------
    @invariant()
    def systems_match_model(self) -> None:
        for model in self.models.values():
            for system in [*model.systems, *model.queries]:
                expected = {e for e, comps in model.comps.items() if all(t in comps for t in system.component_types)}
                assert set(system.entities) == expected, system.name
                assert len(system.entities) == len(system.components) == len(system) == len(expected)
                for entity, components in zip(system.entities, system.components):
                    want = tuple(model.comps[entity][t] for t in system.component_types)
                    assert len(components) == len(want)
                    assert all(a is b for a, b in zip(components, want)), system.name
            for system in model.systems:
                assert set(system.seen) == set(system.entities), f"{system.name}: hooks disagree with the cache"
                assert system.created - system.removed == len(system)

    @invariant()
    def components_match_model(self) -> None:
        for model in self.models.values():
            scene = model.scene
            assert set(scene.entities) == set(model.comps)
            for entity, comps in model.comps.items():
                assert set(type(c) for c in scene.components_of(entity)) == set(comps)
                for t, component in comps.items():
                    assert scene.get_component(entity, t) is component
                for t in KIND_TYPE.values():
                    assert scene.has_component(entity, t) == (t in comps)

    @invariant()
    def columns_survive_swap_removes(self) -> None:
        for model in self.models.values():
            store = model.scene.store(TransformComponent)
            assert store.count == len(model.translation)
            for entity, t in model.translation.items():
                transform = model.comps[entity][TransformComponent]
                np.testing.assert_array_equal(transform.translation, t)
                assert store.owners[transform._row] is transform

    @invariant()
    def hierarchy_matches_model(self) -> None:
        for model in self.models.values():
            for entity, parent in model.parents.items():
                link = model.scene.get_component(entity, LinkComponent)
                assert link.parent == parent
                assert model.scene.parent_of(entity) == parent
                assert len(link.children) == len(set(link.children))
                assert set(link.children) == model.children_of(entity)


TestSceneStateful = SceneMachine.TestCase
TestSceneStateful.settings = settings(
    max_examples=60, stateful_step_count=40, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)


# ---------------------------------------------------------------------------------------------
# Membership after remove-then-add

def test_remove_then_add_keeps_membership_tuples_and_hook_counts() -> None:
    scene = Scene()
    system = scene.add_system(HookRecorder([A, B]))
    a1, b1, a2, b2 = A(1), B(1), A(2), B(2)
    e1 = scene.create_entity(a1, b1)
    e2 = scene.create_entity(a2, b2)
    assert (system.created, system.removed) == (2, 0)

    scene.remove_component(e1, A)
    assert system.entities == [e2]
    assert (system.created, system.removed) == (2, 1)

    scene.add_component(e2, C())  # unrelated type: no hook, no change
    assert system.entities == [e2]
    assert (system.created, system.removed) == (2, 1)

    a1_new = A(11)
    scene.add_component(e1, a1_new)
    assert (system.created, system.removed) == (3, 1)
    assert set(system.entities) == {e1, e2}
    members = dict(zip(system.entities, system.components))
    assert members[e1][0] is a1_new and members[e1][1] is b1
    assert members[e2][0] is a2 and members[e2][1] is b2
    assert system.column(A) == [members[e][0] for e in system.entities]
    assert system.column(1) == [members[e][1] for e in system.entities]

    # Replacing a component is a remove then an add: both hooks fire, the tuple holds the new one.
    b1_new = B(12)
    scene.add_component(e1, b1_new)
    assert (system.created, system.removed) == (4, 2)
    assert dict(zip(system.entities, system.components))[e1] == (a1_new, b1_new)


def test_system_added_late_sees_existing_entities_and_hooks_after_on_create_system() -> None:
    calls: list[str] = []

    class Late(System):
        def on_create_system(self) -> None:
            calls.append("system")

        def on_create_entity(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
            calls.append("entity")

    scene = Scene()
    e = scene.create_entity(A(), B())
    scene.create_entity(A())
    system = scene.add_system(Late([A, B]))
    assert system.entities == [e]
    assert calls == ["system", "entity"]


def test_destroy_entity_calls_on_remove_and_destroys_descendants() -> None:
    scene = Scene()
    system = scene.add_system(HookRecorder([A]))
    root = scene.create_entity(A(), LinkComponent())
    child = scene.create_entity(A(), LinkComponent(root))
    grandchild = scene.create_entity(A(), LinkComponent(child))
    other = scene.create_entity(A(), LinkComponent(root))
    keeper = scene.create_entity(A())
    scene.destroy_entity(child)
    assert set(scene.entities) == {root, other, keeper}
    assert scene.get_component(root, LinkComponent).children == [other]
    assert system.removed == 2 and set(system.entities) == {root, other, keeper}
    scene.destroy_entity(root)
    assert scene.entities == [keeper]
    for gone in (root, child, grandchild, other):
        assert gone not in scene


def test_destroying_the_root_of_a_1000_deep_chain_needs_no_recursion() -> None:
    scene = Scene()
    parent = root = scene.create_entity(LinkComponent(), TransformComponent())
    for _ in range(1000):
        parent = scene.create_entity(LinkComponent(parent), TransformComponent())
    assert len(scene) == 1001
    scene.destroy_entity(root)
    assert len(scene) == 0
    assert scene.store(TransformComponent).count == 0


def test_removing_a_link_orphans_children_and_parenting_adds_a_link_to_the_parent() -> None:
    scene = Scene()
    parent = scene.create_entity(InfoComponent("parent"))
    child = scene.create_entity(LinkComponent(parent))
    assert scene.get_component(parent, LinkComponent).children == [child]
    scene.remove_component(parent, LinkComponent)
    assert scene.parent_of(child) is None
    assert child in scene


# ---------------------------------------------------------------------------------------------
# Clear errors

def test_adding_a_non_component_names_the_type_and_the_entity() -> None:
    scene = Scene()
    e = scene.create_entity(InfoComponent("player"))
    with pytest.raises(NotAComponentError, match=r"dict is not a Component subclass") as err:
        scene.add_component(e, {"translation": (0, 1, 0)})
    assert "'player'" in str(err.value) and str(e) in str(err.value)
    assert isinstance(err.value, TypeError)
    # The class instead of an instance: the message says to pass an instance.
    with pytest.raises(NotAComponentError, match=r"pass an instance: TransformComponent\(\.\.\.\)"):
        scene.add_component(e, TransformComponent)


def test_getting_a_missing_component_names_entity_and_type() -> None:
    scene = Scene()
    e = scene.create_entity(InfoComponent("lamp"), A())
    with pytest.raises(MissingComponentError) as err:
        scene.get_component(e, TransformComponent)
    message = str(err.value)
    assert "'lamp'" in message and str(e) in message and "TransformComponent" in message
    assert "it has: InfoComponent, A" in message
    assert isinstance(err.value, KeyError)
    assert scene.try_component(e, TransformComponent) is None
    with pytest.raises(MissingComponentError, match=r"'lamp'.*has no B to remove"):
        scene.remove_component(e, B)


def test_unknown_entity_is_reported_with_the_scene_name() -> None:
    scene = Scene("level1")
    stranger = uuid.uuid4()
    for call in (
        lambda: scene.get_component(stranger, A),
        lambda: scene.add_component(stranger, A()),
        lambda: scene.destroy_entity(stranger),
        lambda: scene.has_component(stranger, A),
    ):
        with pytest.raises(UnknownEntityError, match=rf"{stranger}.*is not an entity of scene 'level1'"):
            call()
    e = scene.create_entity()
    scene.destroy_entity(e)
    with pytest.raises(UnknownEntityError):
        scene.get_component(e, A)
    with pytest.raises(UnknownEntityError, match=r"parent .* is not in scene 'level1'"):
        scene.add_component(scene.create_entity(), LinkComponent(stranger))


def test_system_with_a_non_component_type_is_rejected() -> None:
    with pytest.raises(NotAComponentError, match=r"System: <class 'int'> is not a Component subclass"):
        System([A, int])
    with pytest.raises(NotAComponentError, match=r"'transform' is not a Component subclass"):
        System(["transform"])
    with pytest.raises(ValueError, match="listed twice"):
        System([A, A])


def test_link_cycle_shows_the_chain_and_changes_nothing() -> None:
    scene = Scene()
    a = scene.create_entity(InfoComponent("a"), LinkComponent())
    b = scene.create_entity(InfoComponent("b"), LinkComponent(a))
    c = scene.create_entity(InfoComponent("c"), LinkComponent(b))
    version = scene.hierarchy_version
    with pytest.raises(HierarchyCycleError) as err:
        scene.set_parent(a, c)
    assert str(err.value) == (
        f"parenting would create a cycle: entity 'a' ({a}) -> entity 'c' ({c}) -> entity 'b' ({b}) -> entity 'a' ({a})"
    )
    with pytest.raises(HierarchyCycleError, match="entity 'a'.*-> entity 'a'"):
        scene.set_parent(a, a)
    with pytest.raises(HierarchyCycleError):
        scene.add_component(a, LinkComponent(b))
    assert scene.hierarchy_version == version
    assert scene.parent_of(a) is None and scene.parent_of(b) == a and scene.parent_of(c) == b
    assert scene.get_component(a, LinkComponent).children == [b]
    assert scene.get_component(b, LinkComponent).children == [c]


def test_one_transform_instance_cannot_join_two_entities() -> None:
    scene, other = Scene(), Scene("other")
    shared = TransformComponent(translation=(1, 2, 3))
    first = scene.create_entity(shared)
    second = scene.create_entity(InfoComponent("second"))
    with pytest.raises(ValueError, match=r"cannot add this TransformComponent to entity 'second'.*already belongs"):
        scene.add_component(second, shared)
    with pytest.raises(ValueError, match="already belongs"):
        other.add_component(other.create_entity(), shared)
    assert not scene.has_component(second, TransformComponent)
    assert scene.get_component(first, TransformComponent) is shared
    np.testing.assert_array_equal(shared.translation, (1, 2, 3))
    # Once removed it may join another entity, keeping its values.
    scene.remove_component(first, TransformComponent)
    scene.add_component(second, shared)
    np.testing.assert_array_equal(scene.get_component(second, TransformComponent).translation, (1, 2, 3))


def test_columnar_fields_check_shape_and_finiteness() -> None:
    t = TransformComponent()
    with pytest.raises(ValueError, match=r"TransformComponent.translation must have shape \(3,\)"):
        t.translation = (1.0, 2.0)
    with pytest.raises(ValueError, match="TransformComponent.scale must be finite"):
        t.scale = (1.0, float("nan"), 1.0)
    t.scale = 2.0  # a scalar broadcasts
    np.testing.assert_array_equal(t.scale, (2.0, 2.0, 2.0))


# ---------------------------------------------------------------------------------------------
# Systems: per-entity and batch paths, order, enabling

class MoverPerEntity(System):
    def __init__(self) -> None:
        super().__init__([TransformComponent, Velocity])

    def on_update_entity(self, ts: float, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        transform, velocity = components
        transform.translation = transform.translation + velocity.v * ts


class MoverBatch(System):
    def __init__(self) -> None:
        super().__init__([TransformComponent, Velocity])

    def on_update_system(self, ts: float) -> None:
        store = self.scene.store(TransformComponent)
        rows = store.rows_of(self.column(TransformComponent))
        velocities = np.array([v.v for v in self.column(Velocity)]).reshape(-1, 3)
        store.column("translation")[rows] += velocities * ts


def build_movers(system: System, seed: int) -> tuple[Scene, list[uuid.UUID]]:
    rng = np.random.default_rng(seed)
    scene = Scene()
    scene.add_system(system)
    entities = []
    for i in range(40):
        comps: list[Component] = [TransformComponent(translation=rng.normal(size=3))]
        if i % 3:
            comps.append(Velocity(rng.normal(size=3)))
        entities.append(scene.create_entity(*comps))
    # Churn so that rows and member order no longer follow creation order.
    for e in entities[::7]:
        scene.remove_component(e, TransformComponent)
        scene.add_component(e, TransformComponent(translation=rng.normal(size=3)))
    return scene, entities


def test_per_entity_hooks_and_batch_update_agree() -> None:
    per_entity, entities_a = build_movers(MoverPerEntity(), seed=3)
    batch, entities_b = build_movers(MoverBatch(), seed=3)
    for ts in (0.016, 0.02, 0.5):
        per_entity.update(ts)
        batch.update(ts)
    for ea, eb in zip(entities_a, entities_b):
        ta = per_entity.get_component(ea, TransformComponent).translation
        tb = batch.get_component(eb, TransformComponent).translation
        np.testing.assert_allclose(ta, tb, rtol=0, atol=1e-12)
    moved = [e for e in entities_a if per_entity.has_component(e, Velocity)]
    assert len(moved) == 26


def test_systems_run_in_add_order_index_inserts_and_disabled_systems_skip() -> None:
    log: list[str] = []

    class Named(System):
        def on_update_system(self, ts: float) -> None:
            log.append(self.name)

    scene = Scene()
    first = scene.add_system(Named(name="first"))
    second = scene.add_system(Named(name="second"))
    zeroth = scene.add_system(Named(name="zeroth"), index=0)
    scene.add_system(Named(name="middle"), index=2)
    assert [s.name for s in scene.systems] == ["zeroth", "first", "middle", "second"]
    scene.update(0.1)
    assert log == ["zeroth", "first", "middle", "second"]
    log.clear()
    second.enabled = False
    zeroth.enabled = False
    scene.update(0.1)
    assert log == ["first", "middle"]
    assert scene.get_system(Named) is zeroth
    scene.remove_system(first)
    log.clear()
    scene.update(0.1)
    assert log == ["middle"]
    with pytest.raises(ValueError, match="already belongs to scene"):
        Scene("b").add_system(second)


def test_query_stays_current() -> None:
    scene = Scene()
    query = scene.query(A, B)
    assert scene.query(A, B) is query  # cached
    e1 = scene.create_entity(A(), B())
    e2 = scene.create_entity(A())
    assert query.entities == [e1]
    b2 = scene.add_component(e2, B())
    assert set(query.entities) == {e1, e2}
    assert dict(zip(query.entities, query.components))[e2][1] is b2
    scene.remove_component(e1, A)
    assert query.entities == [e2]
    scene.destroy_entity(e2)
    assert query.entities == [] and len(query) == 0
    assert list(scene.view(B)) == [(e1, (scene.get_component(e1, B),))]
    assert query not in scene.systems  # a query is never updated as a system


# ---------------------------------------------------------------------------------------------
# Scene manager

def test_scene_manager_switches_only_when_pending_is_applied() -> None:
    manager = SceneManager()
    events: list[tuple[str | None, str]] = []
    manager.on_switch.append(lambda prev, new: events.append((None if prev is None else prev.name, new.name)))
    one = manager.add(Scene("one"))
    two = manager.add(Scene("two"))
    assert manager.active is one and events == [(None, "one")]
    manager.request_switch("two")
    assert manager.active is one
    assert manager.apply_pending() and manager.active is two
    assert not manager.apply_pending()
    manager.request_switch(two)  # already active: nothing happens
    assert not manager.apply_pending()
    assert events == [(None, "one"), ("one", "two")]
    with pytest.raises(KeyError, match=r"no scene named 'three' \(have: one, two\)"):
        manager.request_switch("three")
    three = Scene("three")
    manager.request_switch(three)  # an unregistered scene object is registered on request
    assert manager.get("three") is three
    with pytest.raises(ValueError, match="a different scene named 'one'"):
        manager.request_switch(Scene("one"))
    assert manager.apply_pending() and manager.active is three


def test_each_scene_has_its_own_transform_columns() -> None:
    one, two = Scene("one"), Scene("two")
    t1 = TransformComponent(translation=(1, 0, 0))
    t2 = TransformComponent(translation=(2, 0, 0))
    one.create_entity(t1)
    two.create_entity(t2)
    assert one.store(TransformComponent) is not two.store(TransformComponent)
    assert one.store(TransformComponent).count == two.store(TransformComponent).count == 1
    np.testing.assert_array_equal(t1.translation, (1, 0, 0))
    np.testing.assert_array_equal(t2.translation, (2, 0, 0))


def test_column_store_grows_and_keeps_values() -> None:
    scene = Scene()
    transforms = [TransformComponent(translation=(i, -i, 2 * i)) for i in range(100)]
    entities = [scene.create_entity(t) for t in transforms]
    store = scene.store(TransformComponent)
    assert store.count == 100 and store.capacity >= 100
    for e in entities[::3]:
        scene.remove_component(e, TransformComponent)
    for i, t in enumerate(transforms):
        np.testing.assert_array_equal(t.translation, (i, -i, 2 * i))
    np.testing.assert_array_equal(
        np.sort(store.column("translation")[:, 0]), [i for i in range(100) if i % 3]
    )


def test_replacing_a_link_changes_the_parent_and_keeps_the_children() -> None:
    scene = Scene("relink")
    a, b, c = (scene.create_entity(InfoComponent(n)) for n in "abc")
    scene.add_component(b, LinkComponent(None))
    scene.add_component(c, LinkComponent(b))
    scene.add_component(b, LinkComponent(a))
    assert scene.parent_of(b) == a
    assert scene.parent_of(c) == b
    assert scene.get_component(b, LinkComponent).children == [c]
    with pytest.raises(HierarchyCycleError):
        scene.add_component(b, LinkComponent(c))  # c is b's child: still a cycle


# --- destruction during an update, removing systems -------------------------------------------------------------
def test_an_entity_destroyed_during_an_update_is_not_visited_later_in_that_loop():
    from gandalf_core import Scene, System, TransformComponent

    class Killer(System):
        def __init__(self):
            super().__init__([TransformComponent])
            self.visited = []

        def on_update_entity(self, ts, entity, components):
            self.visited.append(entity)
            if entity == first and second in self.scene:
                self.scene.destroy_entity(second)  # asked for mid-loop: waits until the loop is done

    scene = Scene("kill")
    first = scene.create_entity(TransformComponent())
    second = scene.create_entity(TransformComponent())
    third = scene.create_entity(TransformComponent())
    killer = scene.add_system(Killer())
    scene.update(0.0)
    # Deferred to the end of the system: the loop runs over the entities as they were when it began.
    assert killer.visited == [first, second, third]
    assert second not in scene.entities and scene.pending_destroy == []
    killer.visited.clear()
    scene.update(0.0)
    assert killer.visited == [first, third]


def test_removing_a_system_that_is_not_there_names_the_scene():
    from gandalf_core import Scene, System, TransformComponent

    scene = Scene("level")
    with pytest.raises(ValueError, match="scene 'level' has no system .* to remove"):
        scene.remove_system(System([TransformComponent]))


def test_a_gui_only_system_costs_no_update_but_still_steps_once_when_asked() -> None:
    """``updates_each_frame = False`` (the editor's panels): ``update`` skips the system; ``run_system`` runs it."""
    calls: list[str] = []

    class GuiOnly(System):
        updates_each_frame = False

        def on_update_system(self, ts: float) -> None:
            calls.append("gui-only")

    class Every(System):
        def on_update_system(self, ts: float) -> None:
            calls.append("every")

    scene = Scene("gui")
    gui_only = scene.add_system(GuiOnly())
    scene.add_system(Every())
    scene.update(0.1)
    scene.update(0.1)
    assert calls == ["every", "every"]
    scene.run_system(gui_only, 0.1)
    assert calls[-1] == "gui-only"
