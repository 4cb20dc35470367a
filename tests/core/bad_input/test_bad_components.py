"""Components: every validated field of every core component, given a wrong type, a wrong shape, NaN or infinity,
or a value out of range, in the constructor and by assignment. Each error is a FieldError (or the component's own
TypeError/ValueError) naming ``Component.field`` and the value given; a refused assignment keeps the old value.
Right results: the conversions and allowances the components document (a uniform scale, a clipped colour, a
quaternion scaled to unit length, 0 and negative scales)."""

from __future__ import annotations

import math
import uuid

import numpy as np
import pytest

from gandalf_core import ClearColorComponent, InfoComponent, LinkComponent, TransformComponent
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent, SkyboxComponent
from gandalf_core.components.fields import FieldError
from gandalf_core.ecs import Scene
from gandalf_core.systems import TransformSystem

from .catalogue import error, params, result, run

nan, inf = math.nan, math.inf

#: Values no vector field takes, with what the message says is wrong.
BAD_VECTORS = [
    ("string", "abc", "must be numbers"),
    ("none", None, "must be numbers"),
    ("bool", True, "must be numbers"),
    ("text-numbers", ["1", "2", "3"], "must be numbers"),
    ("dict", {"x": 1.0}, "must be numbers"),
    ("int-beyond-float", (10**400, 0, 0), "must be numbers"),
    ("nan", (nan, 0.0, 0.0), "must be finite"),
    ("inf", (0.0, inf, 0.0), "must be finite"),
    ("minus-inf-array", np.array([0.0, 0.0, -inf]), "must be finite"),
    ("two-values", (1.0, 2.0), "must have shape (3,)"),
    ("four-values", (1.0, 2.0, 3.0, 4.0), "must have shape (3,)"),
    ("matrix", np.eye(3), "must have shape (3,)"),
]


def _assign(field: str, value):
    def action():
        t = TransformComponent()
        setattr(t, field, value)
        return t
    return action


def _assign_in_scene(field: str, value):
    def action():
        t = TransformComponent()
        Scene("s").create_entity(t)
        setattr(t, field, value)
        return t
    return action


def _short(value) -> str:
    text = repr(value)
    return text if len(text) < 40 else text[:20]


TRANSFORM = []
for label, value, why in BAD_VECTORS:
    words = (f"TransformComponent.translation {why}", f"got {_short(value)}")
    TRANSFORM.append(error(f"translation-ctor-{label}", lambda v=value: TransformComponent(v), FieldError, *words))
    TRANSFORM.append(error(f"translation-set-{label}", _assign("translation", value), FieldError, *words))
    if label in ("string", "nan", "two-values", "bool"):
        TRANSFORM.append(error(f"translation-set-in-scene-{label}", _assign_in_scene("translation", value),
                               FieldError, *words))
for label, value, why in BAD_VECTORS:  # a uniform scale takes one number, but never a bool
    words = ("TransformComponent.scale", why)
    TRANSFORM.append(error(f"scale-ctor-{label}", lambda v=value: TransformComponent(scale=v), FieldError, *words))
for label, value in [("string", "abc"), ("nan", (nan, 0, 0)), ("two-values", (1, 2)), ("none", None),
                     ("inf", (0, 0, inf)), ("matrix", np.eye(3))]:
    TRANSFORM.append(error(f"rotation-ctor-{label}", lambda v=value: TransformComponent(rotation=v), FieldError,
                           "TransformComponent.rotation", "Euler degrees"))
    TRANSFORM.append(error(f"rotation-set-{label}", _assign("rotation", value), FieldError,
                           "TransformComponent.rotation"))
for label, value, why in [("string", "wxyz", "must be numbers"), ("nan", (nan, 0, 0, 1), "must be finite"),
                          ("three-values", (0, 0, 1), "must have shape (4,)"), ("none", None, "must be numbers"),
                          ("inf", (inf, 0, 0, 0), "must be finite")]:
    if value is not None:  # quaternion=None means "not given"
        TRANSFORM.append(error(f"quaternion-ctor-{label}", lambda v=value: TransformComponent(quaternion=v),
                               FieldError, f"TransformComponent.quaternion {why}"))
    TRANSFORM.append(error(f"quaternion-set-{label}", _assign("quaternion", value), FieldError,
                           f"TransformComponent.quaternion {why}"))
for label, value, why in [("string", "I", "must be numbers"), ("3x3", np.eye(3), "must have shape (4, 4)"),
                          ("nan", np.full((4, 4), nan), "must be finite"), ("flat-16", np.eye(4).ravel(),
                                                                               "must have shape (4, 4)")]:
    TRANSFORM.append(error(f"world-set-{label}", _assign("world", value), FieldError,
                           f"TransformComponent.world {why}"))


def _refused_then_read(field: str, good, bad):
    def action():
        t = TransformComponent()
        setattr(t, field, good)
        with pytest.raises(FieldError):
            setattr(t, field, bad)
        return getattr(t, field)
    return action


def _world_after_update(q):
    scene = Scene("q")
    scene.add_system(TransformSystem())
    entity = scene.create_entity(TransformComponent((1.0, 2.0, 3.0), quaternion=q))
    scene.update(0.0)
    return scene.get_component(entity, TransformComponent).world


TRANSFORM += [
    error("rotation-and-quaternion", lambda: TransformComponent(rotation=(0, 90, 0), quaternion=(1, 0, 0, 0)),
          FieldError, "rotation", "quaternion", "not both"),
    result("refused-translation-keeps-old", _refused_then_read("translation", (1.0, 2.0, 3.0), (nan, 0, 0)),
           lambda v: np.array_equal(v, [1, 2, 3])),
    result("refused-scale-keeps-old", _refused_then_read("scale", (2.0, 2.0, 2.0), "big"),
           lambda v: np.array_equal(v, [2, 2, 2])),
    result("scale-uniform-number", lambda: TransformComponent(scale=2).scale, lambda v: np.array_equal(v, [2, 2, 2])),
    result("zero-quaternion-reads-as-no-rotation", lambda: TransformComponent(quaternion=(0, 0, 0, 0)).rotation,
           lambda v: np.array_equal(v, [0, 0, 0])),
    result("scale-zero-allowed", lambda: TransformComponent(scale=0.0).scale, lambda v: np.array_equal(v, [0, 0, 0])),
    result("scale-mirrored-allowed", lambda: TransformComponent(scale=(-1, 1, 1)).scale,
           lambda v: np.array_equal(v, [-1, 1, 1])),
    result("translation-float32-array", lambda: TransformComponent(np.array([1, 2, 3], np.float32)).translation,
           lambda v: v.dtype == np.float64 and np.array_equal(v, [1, 2, 3])),
    result("translation-int-tuple", lambda: TransformComponent((1, 2, 3)).translation,
           lambda v: np.array_equal(v, [1.0, 2.0, 3.0])),
    result("translation-numpy-scalars", lambda: TransformComponent((np.float32(1), np.int64(2), 3.0)).translation,
           lambda v: np.array_equal(v, [1.0, 2.0, 3.0])),
    result("quaternion-scaled-to-unit", lambda: TransformComponent(quaternion=(2, 0, 0, 0)).quaternion,
           lambda v: np.array_equal(v, [1, 0, 0, 0])),
    result("quaternion-set-scaled-to-unit", lambda: _assign("quaternion", (0, 3, 0, 4))().quaternion,
           lambda v: np.allclose(v, [0, 0.6, 0, 0.8], atol=1e-15)),
    result("quaternion-huge-scaled-to-unit", lambda: TransformComponent(quaternion=(1e300, 1e300, 0, 0)).quaternion,
           lambda v: np.allclose(v, [math.sqrt(0.5), math.sqrt(0.5), 0, 0], atol=1e-15)),
    result("quaternion-zero-reads-as-no-rotation", lambda: _world_after_update((0, 0, 0, 0)),
           lambda w: np.array_equal(w[:3, :3], np.eye(3)) and np.array_equal(w[:3, 3], [1, 2, 3])),
    result("rotation-degrees", lambda: TransformComponent(rotation=(0, 90, 0)).quaternion,
           lambda v: np.allclose(v, [math.sqrt(0.5), 0, math.sqrt(0.5), 0], atol=1e-15)),
]

OTHERS = [
    # ClearColor: sRGB, 3 or 4 values >= 0, clipped to 1
    error("clear-color-name", lambda: ClearColorComponent("blue"), FieldError, "ClearColorComponent.color", "'blue'"),
    error("clear-color-two-values", lambda: ClearColorComponent((1, 2)), FieldError, "ClearColorComponent.color"),
    error("clear-color-five-values", lambda: ClearColorComponent((1, 1, 1, 1, 1)), FieldError,
          "ClearColorComponent.color"),
    error("clear-color-nan", lambda: ClearColorComponent((nan, 0, 0)), FieldError, "ClearColorComponent.color",
          "finite"),
    error("clear-color-negative", lambda: ClearColorComponent((-0.1, 0, 0)), FieldError, "ClearColorComponent.color",
          ">= 0"),
    error("clear-color-none", lambda: ClearColorComponent(None), FieldError, "ClearColorComponent.color"),
    result("clear-color-clipped", lambda: ClearColorComponent((2.0, 0.5, 0.0)).color,
           lambda c: np.array_equal(c, [1.0, 0.5, 0.0, 1.0])),
    # Camera fields by type (the degenerate projections are in test_bad_cameras.py)
    error("camera-fov-string", lambda: CameraComponent("wide"), FieldError, "CameraComponent.fov", "'wide'"),
    error("camera-near-string", lambda: CameraComponent(near="close"), FieldError, "CameraComponent.near"),
    error("camera-far-none", lambda: CameraComponent(far=None), FieldError, "CameraComponent.far"),
    error("camera-projection-unknown", lambda: CameraComponent(projection="fisheye"), FieldError,
          "CameraComponent.projection", "'fisheye'", "'perspective'"),
    error("camera-height-negative", lambda: CameraComponent(projection="orthographic", height=-2), FieldError,
          "CameraComponent.height"),
    error("camera-aspect-ratio-text", lambda: CameraComponent(aspect="16:9"), FieldError, "CameraComponent.aspect"),
    error("camera-primary-int", lambda: CameraComponent(primary=1), FieldError, "CameraComponent.primary",
          "True or False"),
    error("camera-reverse-z-text", lambda: CameraComponent(reverse_z="yes"), FieldError, "CameraComponent.reverse_z"),
    error("camera-fov-bool", lambda: CameraComponent(fov=True), FieldError, "CameraComponent.fov"),
    error("camera-fov-set-later", lambda: setattr(CameraComponent(), "fov", 200), FieldError, "CameraComponent.fov",
          "200"),
    # Light
    error("light-kind-unknown", lambda: LightComponent("spot"), ValueError, "LightComponent.kind", "'spot'"),
    error("light-color-name", lambda: LightComponent(color="red"), FieldError, "LightComponent.color", "'red'"),
    error("light-intensity-negative", lambda: LightComponent(intensity=-1), FieldError, "LightComponent.intensity"),
    error("light-intensity-nan", lambda: LightComponent(intensity=nan), FieldError, "LightComponent.intensity"),
    error("light-range-negative", lambda: LightComponent(range=-1), FieldError, "LightComponent.range"),
    error("light-shadows-on-point", lambda: LightComponent("point", cast_shadows=True), ValueError,
          "LightComponent.cast_shadows", "directional"),
    error("light-shadows-int", lambda: LightComponent("directional", cast_shadows=1), TypeError,
          "LightComponent.cast_shadows"),
    error("light-shadow-extent-zero", lambda: LightComponent("directional", shadow_extent=0), FieldError,
          "LightComponent.shadow_extent"),
    error("light-shadow-depth-inf", lambda: LightComponent("directional", shadow_depth=inf), FieldError,
          "LightComponent.shadow_depth"),
    error("light-shadow-bias-negative", lambda: LightComponent("directional", shadow_bias=-1), FieldError,
          "LightComponent.shadow_bias"),
    error("light-kind-change-with-shadows",
          lambda: setattr(LightComponent("directional", cast_shadows=True), "kind", "point"), ValueError,
          "LightComponent.kind", "cannot cast shadows"),
    # Names of resources
    error("mesh-empty-name", lambda: MeshComponent(""), TypeError, "MeshComponent.mesh"),
    error("mesh-number", lambda: MeshComponent(3), TypeError, "MeshComponent.mesh", "3"),
    error("material-none", lambda: MaterialComponent(None), TypeError, "MaterialComponent.material", "None"),
    error("skybox-number", lambda: SkyboxComponent(3), FieldError, "SkyboxComponent.texture"),
    error("skybox-empty", lambda: SkyboxComponent(""), FieldError, "SkyboxComponent.texture"),
    # Info and Link (the ECS's own components)
    error("info-name-number", lambda: InfoComponent(3), TypeError, "InfoComponent.name", "3"),
    error("info-tag-none", lambda: InfoComponent("a", None), TypeError, "InfoComponent.tag", "None"),
    error("info-name-set-later", lambda: setattr(InfoComponent("a"), "name", b"bytes"), TypeError,
          "InfoComponent.name"),
    error("link-parent-string", lambda: LinkComponent("abc"), TypeError, "LinkComponent.parent", "'abc'"),
    error("link-parent-int", lambda: LinkComponent(3), TypeError, "LinkComponent.parent"),
    result("link-parent-uuid", lambda: LinkComponent(uuid.uuid4()).parent, lambda p: isinstance(p, uuid.UUID)),
]


@pytest.mark.parametrize("case", params(TRANSFORM))
def test_transform_component(case):
    run(case)


@pytest.mark.parametrize("case", params(OTHERS))
def test_other_components(case):
    run(case)
