"""What the inspector can edit on a component, found from the component itself (no per-component GUI code).

For each component class, in this order: its columnar fields (a Transform shows translation, rotation as Euler
degrees and scale), its validated fields (:mod:`gandalf_core.components.fields` descriptors: Number, Flag,
Choice, Name, Color), public properties with a setter, fields registered for USD
(:func:`step07_advanced.usd.register_component`), and plain public attributes of simple types. A step's own
component is edited like a built-in one as soon as it has such fields. Specs are cached per class.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from gandalf_core.components import (
    CameraComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
    TransformComponent,
)
from gandalf_core.components.fields import Choice, Color, Field, Flag, Name, Number
from gandalf_core.components.light import LIGHT_KINDS
from gandalf_core.ecs import ColumnarComponent, Component, InfoComponent, LinkComponent


@dataclass(frozen=True)
class FieldSpec:
    """One editable field: ``kind`` is number, int, flag, choice, text, color, vector, resource or readonly."""

    name: str
    kind: str
    low: float | None = None
    high: float | None = None
    choices: tuple[str, ...] = ()
    size: int = 0  # vectors and colours: 2-4 components


#: Properties whose values come from a fixed list.
_CHOICES = {(LightComponent, "kind"): LIGHT_KINDS}
#: Components that name a resource: the inspector offers the scene's assets of that kind (and replaces the component).
RESOURCE_FIELDS = {MeshComponent: ("mesh", "meshes"), MaterialComponent: ("material", "materials")}
_CACHE: dict[type, tuple[FieldSpec, ...]] = {}


# --8<-- [start:kinds]
def _from_descriptor(name: str, field: Field) -> FieldSpec:
    if isinstance(field, Number):
        return FieldSpec(name, "number", field.low, field.high)
    if isinstance(field, Flag):
        return FieldSpec(name, "flag")
    if isinstance(field, Choice):
        return FieldSpec(name, "choice", choices=field.choices)
    if isinstance(field, Name):
        return FieldSpec(name, "text")
    if isinstance(field, Color):
        return FieldSpec(name, "color", size=4 if field.alpha else 3)
    return FieldSpec(name, "readonly")


def _from_value(name: str, value: Any) -> FieldSpec | None:
    if isinstance(value, (bool, np.bool_)):
        return FieldSpec(name, "flag")
    if isinstance(value, (int, np.integer)):
        return FieldSpec(name, "int")
    if isinstance(value, (float, np.floating)):
        return FieldSpec(name, "number")
    if isinstance(value, str):
        return FieldSpec(name, "text")
    if isinstance(value, (tuple, list, np.ndarray)):
        arr = np.asarray(value)
        if arr.ndim == 1 and 2 <= arr.size <= 4 and np.issubdtype(arr.dtype, np.number):
            return FieldSpec(name, "vector", size=int(arr.size))
    return None
# --8<-- [end:kinds]


def field_specs(component: Component) -> tuple[FieldSpec, ...]:
    """The editable fields of ``component`` (see the module docstring)."""
    cls = type(component)
    cached = _CACHE.get(cls)
    if cached is not None:
        return cached
    specs: list[FieldSpec] = []
    seen: set[str] = set()

    def add(spec: FieldSpec | None) -> None:
        if spec is not None and spec.name not in seen:
            seen.add(spec.name)
            specs.append(spec)

    columns = getattr(cls, "columns", {}) if isinstance(component, ColumnarComponent) else {}
    seen.update(n for n in columns if n not in ("translation", "scale"))  # quaternion, world: not edited as such
    if cls in RESOURCE_FIELDS:
        add(FieldSpec(RESOURCE_FIELDS[cls][0], "resource", choices=(RESOURCE_FIELDS[cls][1],)))
    if cls is TransformComponent:
        for name in ("translation", "rotation", "scale"):
            add(FieldSpec(name, "vector", size=3))
    elif isinstance(component, ColumnarComponent):
        for name, (shape, _default) in cls.columns.items():
            if len(shape) == 1 and 2 <= shape[0] <= 4:
                seen.discard(name)
                add(FieldSpec(name, "vector", size=shape[0]))
    # --8<-- [start:descriptors]
    for klass in reversed(cls.__mro__):
        for name, attr in vars(klass).items():
            if isinstance(attr, Field):
                add(_from_descriptor(name, attr))
    # --8<-- [end:descriptors]
    for klass in cls.__mro__:
        for name, attr in vars(klass).items():
            if isinstance(attr, property) and attr.fset is not None and not name.startswith("_") and name not in seen:
                if (klass, name) in _CHOICES:
                    add(FieldSpec(name, "choice", choices=_CHOICES[(klass, name)]))
                else:
                    try:
                        add(_from_value(name, getattr(component, name)))
                    except Exception:  # noqa: BLE001 - a property that cannot be read now is not shown
                        pass
    try:
        from ..usd.registry import registration_for

        registration = registration_for(cls)
    except ImportError:  # pragma: no cover - the registry imports no USD
        registration = None
    names = list(registration.fields) if registration is not None else []
    names += [n for n in getattr(component, "__dict__", {}) if not n.startswith("_")]
    for name in names:
        if name not in seen and hasattr(component, name):
            add(_from_value(name, getattr(component, name)))
    if cls is CameraComponent:  # near/far/fov first, as a camera panel usually reads
        specs.sort(key=lambda s: ("projection", "fov", "near", "far").index(s.name)
                   if s.name in ("projection", "fov", "near", "far") else 4)
    result = tuple(specs)
    _CACHE[cls] = result
    return result


def addable_components(scene: Any, entity: Any) -> list[tuple[str, Any]]:
    """(name, factory) of the component types the entity does not have yet and that can be made with defaults:
    the built-ins, and every class registered for USD (which must build without arguments)."""
    from gandalf_core.components import ClearColorComponent

    assets = scene.assets
    first = {kind: next(iter(getattr(assets, kind)), None) for kind in ("meshes", "materials")}
    factories: list[tuple[type, Any]] = [
        (InfoComponent, lambda: InfoComponent("entity")),
        (TransformComponent, TransformComponent),
        (CameraComponent, CameraComponent),
        (LightComponent, LightComponent),
        (ClearColorComponent, ClearColorComponent),
    ]
    if first["meshes"]:
        factories.append((MeshComponent, lambda: MeshComponent(first["meshes"])))
    if first["materials"]:
        factories.append((MaterialComponent, lambda: MaterialComponent(first["materials"])))
    from ..usd.registry import registered_components

    # The steps' registered components that can be built without arguments.
    factories += [(reg.cls, reg.cls) for reg in registered_components() if reg.default_constructible]
    have = {type(c) for c in scene.components_of(entity)}
    return [(cls.__name__, make) for cls, make in factories if cls not in have and cls is not LinkComponent]
