"""Steps' own components in USD files: a registry of component classes and the fields to save.

``register_component(Spin, fields=["speed", "axis"])`` saves each listed field of every ``Spin`` as a
``gandalf:Spin:<field>`` attribute and restores it on load. Field values must be simple: bool, int, float,
str, or a fixed-length sequence of floats (tuple, list or 1-D numpy array). A registered class must be
constructible without arguments: the loader builds ``Spin()`` and then assigns each saved field, taking the
type (and sequence length) of the default value as the field's schema. Nothing here imports USD.
"""

from __future__ import annotations

import inspect
from collections.abc import Sequence
from dataclasses import dataclass

from ..ecs import Component


@dataclass(frozen=True)
class Registration:
    """A registered component class and the names of its saved fields."""

    cls: type[Component]
    fields: tuple[str, ...]


_REGISTRY: dict[str, Registration] = {}


def _builtin_names() -> frozenset[str]:
    from . import mapping

    return frozenset(t.__name__ for t in mapping.BUILTIN_TYPES)


def register_component(cls: type[Component], fields: Sequence[str] = ()) -> None:
    """Save and load ``cls`` components by their ``fields`` (see the module docstring).

    Registering the same class (or a reloaded class of the same module and name) again replaces its fields;
    another class with the same name, a built-in component, a class needing constructor arguments or a
    field name that is not an identifier raises ValueError/TypeError naming it.
    """
    if not (isinstance(cls, type) and issubclass(cls, Component)):
        raise TypeError(f"register_component: {cls!r} is not a Component subclass")
    name = cls.__name__
    if name in _builtin_names():
        raise ValueError(f"register_component: {name} is a built-in component and is saved already")
    if isinstance(fields, str):
        raise TypeError(f"register_component({name}): fields must be a list of names, got the string {fields!r}")
    fields = tuple(fields)
    for f in fields:
        if not isinstance(f, str) or not f.isidentifier() or not f.isascii():
            raise ValueError(f"register_component({name}): field {f!r} is not an ASCII identifier")
    try:
        inspect.signature(cls).bind()
    except TypeError:
        raise TypeError(f"register_component({name}): the loader needs {name}() to work without arguments") from None
    old = _REGISTRY.get(name)
    if old is not None and (old.cls.__module__, old.cls.__qualname__) != (cls.__module__, cls.__qualname__):
        raise ValueError(
            f"register_component: another class named {name} ({old.cls.__module__}.{old.cls.__qualname__}) "
            "is registered already"
        )
    _REGISTRY[name] = Registration(cls, fields)


def unregister_component(cls: type[Component]) -> None:
    """Forget ``cls`` (nothing happens when it is not registered)."""
    reg = _REGISTRY.get(cls.__name__)
    if reg is not None and reg.cls is cls:
        del _REGISTRY[cls.__name__]


def registration_for(cls: type) -> Registration | None:
    """The registration of exactly this class, or None."""
    reg = _REGISTRY.get(cls.__name__)
    return reg if reg is not None and reg.cls is cls else None


def registration_named(name: str) -> Registration | None:
    """The registration of the component class called ``name``, or None."""
    return _REGISTRY.get(name)
