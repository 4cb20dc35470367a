"""The ECS: systems that are not there or belong elsewhere, entities destroyed twice or from another scene,
components added twice or shared, hierarchy cycles, bulk creation with wrong counts, scene switching to unknown
names, and destruction during an update. Errors name the scene, the entity (its Info name when it has one) and
the component type; destruction asked for during a system's update waits until that system has finished."""

from __future__ import annotations

import math

import numpy as np
import pytest

from gandalf_core import Scene, SceneManager, System
from gandalf_core.components import CameraComponent, InfoComponent, LinkComponent, TransformComponent
from gandalf_core.ecs import HierarchyCycleError, MissingComponentError, NotAComponentError, UnknownEntityError

from .catalogue import error, params, result, run


class Marker(System):
    """A system of Transform entities (for the membership cases)."""

    def __init__(self) -> None:
        super().__init__([TransformComponent])


def world():
    """A scene 'main' with an entity 'box', and a scene 'other' with an entity 'stranger'."""
    main, other = Scene("main"), Scene("other")
    box = main.create_entity(InfoComponent("box"), TransformComponent())
    stranger = other.create_entity(InfoComponent("stranger"), TransformComponent())
    return main, box, other, stranger


def destroyed_twice():
    main, box, _, _ = world()
    main.destroy_entity(box)
    main.destroy_entity(box)


def shared_transform(second_scene: bool):
    main, box, other, _ = world()
    transform = main.get_component(box, TransformComponent)
    (other if second_scene else main).create_entity(InfoComponent("thief"), transform)


def cycle():
    main, box, _, _ = world()
    child = main.create_entity(InfoComponent("child"), LinkComponent(box))
    main.add_component(box, LinkComponent(child))


def replaced_component():
    main, box, _, _ = world()
    marker = main.add_system(Marker())
    main.add_component(box, TransformComponent((1.0, 2.0, 3.0)))
    return main, box, marker


def check_replaced(value):
    main, box, marker = value
    assert len(marker) == 1, f"the system sees {len(marker)} members after a replace, expected 1"
    assert np.array_equal(main.get_component(box, TransformComponent).translation, [1, 2, 3])
    assert np.array_equal(marker.components[0][0].translation, [1, 2, 3]), "the system holds the old component"


class Destroyer(System):
    """Destroys the entities named in ``victims`` while updating the entity named ``by``; records what it saw."""

    def __init__(self, by: str, victims: list[str]) -> None:
        super().__init__([InfoComponent])
        self.by, self.victims, self.seen, self.alive_during = by, victims, [], []

    def on_update_entity(self, ts, entity, components):
        info = components[0]
        self.seen.append(info.name)
        if info.name == self.by:
            for other, (other_info,) in zip(self.entities, self.components):
                if other_info.name in self.victims:
                    self.scene.destroy_entity(other)
                    self.scene.destroy_entity(other)  # asked twice in one update: still one destruction
            self.alive_during.append(len(self.scene))


class Counter(System):
    """Runs after the Destroyer: records how many Info entities it sees."""

    def __init__(self) -> None:
        super().__init__([InfoComponent])
        self.counts = []

    def on_update_system(self, ts):
        self.counts.append(len(self))


def destroy_during_update(by: str, victims: list[str]):
    scene = Scene("frame")
    for name in ("a", "b", "c"):
        scene.create_entity(InfoComponent(name))
    destroyer = scene.add_system(Destroyer(by, victims))
    counter = scene.add_system(Counter())
    scene.update(0.1)
    return scene, destroyer, counter


def check_deferred(expected_seen, left):
    def check(value):
        scene, destroyer, counter = value
        assert destroyer.seen == expected_seen, f"the loop visited {destroyer.seen}, expected {expected_seen}"
        assert destroyer.alive_during == [3], f"entities alive inside the update: {destroyer.alive_during}, expected 3"
        assert len(scene) == left and counter.counts == [left], (
            f"after the destroying system: {len(scene)} entities, the next system saw {counter.counts}; "
            f"expected {left}")
    return check


def destroy_parent_during_update():
    scene = Scene("tree")
    parent = scene.create_entity(InfoComponent("a"))
    scene.create_entity(InfoComponent("child"), LinkComponent(parent))
    scene.create_entity(InfoComponent("b"))
    scene.add_system(Destroyer("b", ["a"]))
    scene.update(0.1)
    return sorted(scene.get_component(e, InfoComponent).name for e in scene.entities)


def manager():
    m = SceneManager()
    m.add(Scene("level"))
    return m


def _shared_info():
    """One InfoComponent object added to a second entity: renaming one would rename both."""
    scene = Scene("main")
    info = InfoComponent("box")
    scene.create_entity(info, TransformComponent())
    scene.create_entity(TransformComponent(), info)


def _held_info_in_bulk():
    scene = Scene("main")
    info = InfoComponent("box")
    scene.create_entity(info)
    scene.create_entities(1, [info])


def _info_moved():
    """Taken off one entity, the object may go to another."""
    scene = Scene("main")
    info = InfoComponent("box")
    first = scene.create_entity(info)
    scene.remove_component(first, InfoComponent)
    second = scene.create_entity(TransformComponent())
    scene.add_component(second, info)
    return scene.get_component(second, InfoComponent).name


def _info_back_after_destroy():
    scene = Scene("main")
    info = InfoComponent("box")
    scene.destroy_entity(scene.create_entity(info))
    return scene.get_component(scene.create_entity(info), InfoComponent).name


def _info_in_two_scenes():
    first, second = Scene("a"), Scene("b")
    info = InfoComponent("box")
    first.create_entity(info)
    return second.create_entity(info)


def _info_in_two_scenes_in_bulk():
    first, second = Scene("a"), Scene("b")
    info = InfoComponent("box")
    first.create_entity(info)
    return second.create_entities(1, [info])


def _info_of_a_dropped_scene():
    """A scene dropped while a reference cycle still holds it (its systems point back at it) does not keep the
    component from a new scene."""
    info = InfoComponent("box")
    old = Scene("old")
    old.create_entity(info)
    old.cycle = old  # garbage only a collection finds
    del old
    scene = Scene("new")
    return scene.get_component(scene.create_entity(info), InfoComponent).name


CASES = [
    # systems
    error("remove-system-not-there", lambda: Scene("main").remove_system(Marker()), ValueError, "scene 'main'",
          "has no system Marker to remove"),
    error("one-info-on-two-entities", _shared_info, ValueError, "InfoComponent", "entity 'box'", "already belongs",
          "copy"),
    error("one-info-twice-in-a-bulk-creation", lambda: (lambda i: Scene("main").create_entities(2, [i, i]))(
          InfoComponent("twin")), ValueError, "InfoComponent number 1", "same object as number 0"),
    error("a-held-info-in-a-bulk-creation", _held_info_in_bulk, ValueError, "InfoComponent number 0",
          "entity 'box'"),
    error("one-info-in-two-scenes", _info_in_two_scenes, ValueError, "InfoComponent", "entity 'box'", "of scene 'a'",
          "already belongs", "copy"),
    error("one-info-in-two-scenes-in-bulk", _info_in_two_scenes_in_bulk, ValueError, "InfoComponent number 0",
          "entity 'box'", "of scene 'a'"),
    result("an-info-of-a-dropped-scene-reused", _info_of_a_dropped_scene, lambda name: name == "box"),
    result("an-info-moved-after-removal", _info_moved, lambda name: name == "box"),
    result("an-info-given-back-after-destroy", _info_back_after_destroy, lambda name: name == "box"),
    error("remove-system-of-another-scene", lambda: Scene("main").remove_system(Scene("other").add_system(Marker())),
          ValueError, "scene 'main'", "has no system"),
    error("remove-system-not-a-system", lambda: Scene("main").remove_system(3), ValueError, "has no system 3"),
    error("add-system-twice", lambda: (lambda s, m: (s.add_system(m), s.add_system(m)))(Scene("main"), Marker()),
          ValueError, "Marker", "already belongs to scene 'main'"),
    error("add-system-to-second-scene", lambda: Scene("b").add_system(Scene("a").add_system(Marker())), ValueError,
          "Marker", "already belongs to scene 'a'"),
    error("add-system-class", lambda: Scene("main").add_system(Marker), TypeError, "scene 'main'", "is not a System"),
    error("system-of-non-component", lambda: System([int]), NotAComponentError, "int", "not a Component subclass"),
    error("system-of-component-instance", lambda: System([InfoComponent("x")]), NotAComponentError,
          "not a Component subclass"),
    error("system-type-listed-twice", lambda: System([InfoComponent, InfoComponent]), ValueError, "listed twice"),
    error("get-system-not-there", lambda: Scene("main").get_system(Marker), KeyError, "scene 'main'", "no Marker"),
    # entities
    error("destroy-twice", destroyed_twice, UnknownEntityError, "is not an entity of scene 'main'"),
    error("destroy-entity-of-another-scene", lambda: (lambda m, b, o, s: m.destroy_entity(s))(*world()),
          UnknownEntityError, "not an entity of scene 'main'"),
    error("destroy-a-string", lambda: Scene("main").destroy_entity("box"), UnknownEntityError, "'box'",
          "scene 'main'"),
    error("destroy-none", lambda: Scene("main").destroy_entity(None), UnknownEntityError, "None"),
    error("get-component-missing", lambda: (lambda m, b, o, s: m.get_component(b, CameraComponent))(*world()),
          MissingComponentError, "entity 'box'", "has no CameraComponent", "InfoComponent, TransformComponent"),
    error("get-component-entity-of-another-scene",
          lambda: (lambda m, b, o, s: m.get_component(s, InfoComponent))(*world()), UnknownEntityError,
          "scene 'main'"),
    error("remove-component-missing", lambda: (lambda m, b, o, s: m.remove_component(b, CameraComponent))(*world()),
          MissingComponentError, "entity 'box'", "no CameraComponent to remove"),
    error("add-component-class", lambda: (lambda m, b, o, s: m.add_component(b, TransformComponent))(*world()),
          NotAComponentError, "entity 'box'", "pass an instance: TransformComponent(...)"),
    error("add-component-not-a-component", lambda: (lambda m, b, o, s: m.add_component(b, 3))(*world()),
          NotAComponentError, "entity 'box'", "int is not a Component subclass"),
    error("add-component-to-unknown-entity", lambda: (lambda m, b, o, s: m.add_component(s, InfoComponent()))(
        *world()), UnknownEntityError, "scene 'main'"),
    error("one-transform-on-two-entities", lambda: shared_transform(False), ValueError, "TransformComponent",
          "entity 'thief'", "already belongs to an entity"),
    error("one-transform-in-two-scenes", lambda: shared_transform(True), ValueError, "TransformComponent",
          "already belongs to an entity"),
    result("add-component-twice-replaces", replaced_component, check_replaced),
    # hierarchy
    error("parent-is-self", lambda: (lambda m, b, o, s: m.add_component(b, LinkComponent(b)))(*world()),
          HierarchyCycleError, "cycle", "entity 'box'"),
    error("parent-cycle", cycle, HierarchyCycleError, "cycle", "entity 'box'", "entity 'child'"),
    error("parent-in-another-scene", lambda: (lambda m, b, o, s: m.add_component(b, LinkComponent(s)))(*world()),
          UnknownEntityError, "parent", "of entity 'box'", "is not in scene 'main'"),
    error("set-parent-without-link", lambda: (lambda m, b, o, s: m.set_parent(b, None))(*world()),
          MissingComponentError, "entity 'box'", "has no LinkComponent"),
    error("set-parent-in-another-scene",
          lambda: (lambda m, b, o, s: (m.add_component(b, LinkComponent()), m.set_parent(b, s)))(*world()),
          UnknownEntityError, "of entity 'box'", "not in scene 'main'"),
    # bulk creation
    error("create-entities-negative", lambda: Scene("main").create_entities(-1), ValueError, "scene 'main'",
          "non-negative int n", "-1"),
    error("create-entities-float", lambda: Scene("main").create_entities(2.0), ValueError, "non-negative int n"),
    error("create-entities-one-transform", lambda: Scene("main").create_entities(2, TransformComponent()),
          ValueError, "argument 1", "TransformComponent.batch"),
    error("create-entities-batch-rows", lambda: Scene("main").create_entities(2, TransformComponent.batch(3)),
          ValueError, "TransformComponent batch has 3 rows, n is 2"),
    error("create-entities-type-twice", lambda: Scene("main").create_entities(2, InfoComponent("a"),
                                                                            InfoComponent("b")),
          ValueError, "two components of one type"),
    error("create-entities-class", lambda: Scene("main").create_entities(2, InfoComponent), NotAComponentError,
          "argument 1", "pass an instance: InfoComponent(...)"),
    error("create-entities-short-sequence", lambda: Scene("main").create_entities(2, [InfoComponent("a")]),
          ValueError, "1 components given for 2 entities"),
    error("batch-unknown-field", lambda: TransformComponent.batch(2, colour=1), TypeError, "colour"),
    error("batch-nan-row", lambda: TransformComponent.batch(translations=[[0, 0, 0], [math.nan, 0, 0]]), ValueError,
          "TransformComponent.batch", "translation must be finite (row 1)"),
    error("batch-wrong-shape", lambda: TransformComponent.batch(translations=[[0, 0], [0, 0]]), ValueError,
          "TransformComponent.batch", "translation must have shape (3,)"),
    error("batch-text", lambda: TransformComponent.batch(2, translations="abc"), ValueError,
          "TransformComponent.batch", "translation must be numbers", "'abc'"),
    error("batch-scales-text", lambda: TransformComponent.batch(2, scales="big"), ValueError,
          "TransformComponent.batch", "scales must be numbers"),
    error("batch-rotations-nan", lambda: TransformComponent.batch(rotations=[[0, math.nan, 0]]), ValueError,
          "TransformComponent.batch", "rotations"),
    error("batch-rotation-and-quaternion", lambda: TransformComponent.batch(1, rotations=(0, 0, 0),
                                                                           quaternions=(1, 0, 0, 0)),
          ValueError, "TransformComponent.batch", "not both"),
    # scenes
    error("manager-second-scene-same-name", lambda: manager().add(Scene("level")), ValueError,
          "scene named 'level'"),
    error("manager-unknown-name", lambda: manager().get("lobby"), KeyError, "no scene named 'lobby'", "have: level"),
    error("switch-to-unknown-name", lambda: manager().request_switch("lobby"), KeyError, "'lobby'"),
    error("update-nan-time-step", lambda: Scene("main").update(math.nan), ValueError, "scene 'main'", "update(ts)",
          "nan"),
    error("update-negative-time-step", lambda: Scene("main").update(-0.1), ValueError, "scene 'main'", "-0.1"),
    error("update-infinite-time-step", lambda: Scene("main").update(math.inf), ValueError, "scene 'main'", "inf"),
    error("update-text-time-step", lambda: Scene("main").update("0.1"), TypeError, "scene 'main'", "'0.1'"),
    result("update-numpy-time-step", lambda: Scene("main").update(np.float32(0.1)), lambda r: r is None),
    # destruction during an update: deferred to the end of the system
    result("destroy-later-entity-during-update", lambda: destroy_during_update("a", ["c"]),
           check_deferred(["a", "b", "c"], 2)),
    result("destroy-earlier-entity-during-update", lambda: destroy_during_update("c", ["a"]),
           check_deferred(["a", "b", "c"], 2)),
    result("destroy-self-during-update", lambda: destroy_during_update("b", ["b"]),
           check_deferred(["a", "b", "c"], 2)),
    result("destroy-parent-during-update-takes-children", destroy_parent_during_update,
           lambda names: names == ["b"]),
]


@pytest.mark.parametrize("case", params(CASES))
def test_ecs(case):
    run(case)
