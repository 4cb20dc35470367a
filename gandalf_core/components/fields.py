"""Validated component fields, declared once: ``fov = Number(low=0, high=180)`` instead of a hand-written
property per field. Every assignment (in the constructor, from the editor, from a USD file, from a system) is
checked, and a bad value raises :class:`FieldError` naming the component and the field::

    CameraComponent("wide")  ->  FieldError: CameraComponent.fov must be a number in (0, 180), got 'wide'
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np


class FieldError(TypeError, ValueError):
    """A component field set to a value of the wrong type or range (both a TypeError and a ValueError, so code
    that catches either keeps working)."""


class Field:
    """A descriptor that checks (and converts) every value assigned to it; subclasses define :meth:`convert`."""

    #: What the field holds, for the error message ("a number in (0, 180)").
    expected = "a valid value"

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    # The value lives in the instance's __dict__ under the field's own name: a data descriptor always wins the
    # attribute lookup, so it never collides with another attribute or method.
    def __get__(self, obj: Any, objtype: type | None = None) -> Any:
        if obj is None:
            return self
        try:
            return obj.__dict__[self.name]
        except KeyError:
            raise AttributeError(f"{type(obj).__name__}.{self.name} has not been set") from None

    def __set__(self, obj: Any, value: Any) -> None:
        try:
            converted = self.convert(value)
        except (TypeError, ValueError, OverflowError):
            converted = _INVALID
        if converted is _INVALID:
            raise FieldError(f"{type(obj).__name__}.{self.name} must be {self.expected}, got {value!r}") from None
        obj.__dict__[self.name] = converted

    def convert(self, value: Any) -> Any:
        """The stored value, or ``_INVALID``; may raise TypeError/ValueError (also reported as invalid)."""
        raise NotImplementedError


_INVALID = object()


def _real(value: Any) -> float:
    """A float from a real number (never from a string, a bool or a sequence)."""
    if isinstance(value, (bool, np.bool_, str, bytes)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError
    return float(value)


class Number(Field):
    """A finite float (``math.inf`` too with ``allow_inf``) within ``low``/``high`` (open ends by default)."""

    def __init__(self, low: float | None = None, high: float | None = None, *, low_inclusive: bool = False,
                 allow_inf: bool = False, optional: bool = False, note: str = "") -> None:
        self.low, self.high, self.low_inclusive = low, high, low_inclusive
        self.allow_inf, self.optional = allow_inf, optional
        if low is not None and high is not None:
            text = f"a number in {'[' if low_inclusive else '('}{low:g}, {high:g})"
        elif low is not None:
            text = f"a finite number {'>=' if low_inclusive else '>'} {low:g}"
        else:
            text = "a finite number"
        if allow_inf:
            text += " (or math.inf)"
        if optional:
            text += ", or None"
        self.expected = text + (f" ({note})" if note else "")

    def convert(self, value: Any) -> Any:
        if value is None and self.optional:
            return None
        x = _real(value)
        if math.isnan(x) or (math.isinf(x) and not (self.allow_inf and x > 0)):
            return _INVALID
        if self.low is not None and (x < self.low or (x == self.low and not self.low_inclusive)):
            return _INVALID
        if self.high is not None and x >= self.high:
            return _INVALID
        return x


class Flag(Field):
    """True or False (numpy bools too); nothing else, not even 0 or 1."""

    expected = "True or False"

    def convert(self, value: Any) -> Any:
        return bool(value) if isinstance(value, (bool, np.bool_)) else _INVALID


class Choice(Field):
    """One of a fixed set of strings."""

    def __init__(self, choices: Sequence[str]) -> None:
        self.choices = tuple(choices)
        self.expected = f"one of {', '.join(repr(c) for c in self.choices)}"

    def convert(self, value: Any) -> Any:
        return value if isinstance(value, str) and value in self.choices else _INVALID


class Name(Field):
    """A non-empty string naming a resource (a mesh, a material, a texture)."""

    def __init__(self, what: str) -> None:
        self.expected = f"{what} (a non-empty string)"

    def convert(self, value: Any) -> Any:
        return value if isinstance(value, str) and value else _INVALID


class Color(Field):
    """An sRGB colour: 3 floats, or 3 or 4 with ``alpha`` (alpha 1 when left out), finite and >= 0; clipped to
    [0, 1] with ``clip``. Stored as a float64 numpy array."""

    def __init__(self, *, alpha: bool = False, clip: bool = False) -> None:
        self.alpha, self.clip = alpha, clip
        self.expected = ("3 or 4 finite floats >= 0 (sRGB, alpha 1 when left out)" if alpha
                         else "3 finite floats >= 0 (sRGB)")

    def convert(self, value: Any) -> Any:
        if isinstance(value, (str, bytes)):
            return _INVALID
        c = np.asarray(value, dtype=np.float64).ravel()
        if self.alpha and c.shape == (3,):
            c = np.append(c, 1.0)
        if c.shape != ((4,) if self.alpha else (3,)) or not np.all(np.isfinite(c)) or np.any(c < 0):
            return _INVALID
        return np.clip(c, 0.0, 1.0) if self.clip else c
