"""The Info component: a human-readable name (and optional tag) for an entity."""

from __future__ import annotations

from typing import Any

from .component import Component


class _Text:
    """A field that holds a string; anything else is a TypeError naming the component and the field."""

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    def __get__(self, obj: Any, objtype: type | None = None) -> Any:
        if obj is None:
            return self
        return obj.__dict__[self.name]

    def __set__(self, obj: Any, value: Any) -> None:
        if not isinstance(value, str):
            raise TypeError(f"{type(obj).__name__}.{self.name} must be a string, got {value!r}")
        obj.__dict__[self.name] = value


class InfoComponent(Component):
    """Name and tag of an entity, used in the editor, in USD paths and in error messages (both strings)."""

    name = _Text()
    tag = _Text()

    def __init__(self, name: str = "entity", tag: str = "") -> None:
        self.name = name
        self.tag = tag
