"""Validated component fields, declared once: ``fov = Number(low=0, high=180)`` instead of a hand-written
property per field (a columnar component's vectors too: ``translation = Vector(3, 0.0)``). Every assignment
(in the constructor, from the editor, from a USD file, from a system) is checked, and a bad value raises
:class:`FieldError` naming the component and the field::

    CameraComponent("wide")  ->  FieldError: CameraComponent.fov must be a number in (0, 180), got 'wide'
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..ecs.component import RowField


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
        self._store_value(obj, converted)

    def _store_value(self, obj: Any, value: Any) -> None:
        obj.__dict__[self.name] = value

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


_ND = np.ndarray
_F64 = np.dtype(np.float64)
_NUMBER = (float, int, np.float64)
#: A unit quaternion's squared norm may differ from 1 by this much before the field renormalises it (float64
#: products of unit quaternions stay within ~1e-15; a value saved to a file and read back stays exact).
_UNIT_TOLERANCE = 1e-9


def as_floats(value: Any, shape: tuple[int, ...], *, uniform: bool = False) -> np.ndarray | None:
    """``value`` as a finite float64 array of ``shape`` (one number for all with ``uniform``), or None.

    Only numbers count: no strings (numpy would parse "1"), no booleans, no None, no objects."""
    if isinstance(value, (str, bytes)):
        return None
    arr = np.asarray(value)
    if arr.dtype.kind not in "iuf":
        return None
    arr = arr.astype(np.float64)  # a copy: the caller's array is never kept
    if arr.shape != shape:
        if not (uniform and arr.ndim == 0):
            return None
        arr = np.full(shape, float(arr))
    return arr if np.isfinite(arr).all() else None


class Vector(RowField, Field):
    """A float64 vector or matrix of a fixed shape, every entry finite: a field of a columnar component.

    While its component belongs to a scene the value lives in the scene's numpy column for the field (the
    scene reads ``column_shape`` and ``column_default`` to build it), so a batch system updates every entity at
    once; reading gives a live view of the row. ``uniform`` takes one number for all entries (a uniform scale);
    ``unit`` makes a quaternion: any but an all-zero one (kept; the transform system reads it as no rotation) is
    scaled to unit length (a rotation's state is a unit quaternion), one already of unit length is kept exactly.

    Assigning a float64 array or a tuple/list of plain numbers of the right length takes a fast path (one sum
    decides that all entries are finite); anything else is converted and checked in full.
    """

    def __init__(self, shape: int | tuple[int, ...], default: Any, *, uniform: bool = False, unit: bool = False,
                 expected: str = "") -> None:
        self.column_shape = (shape,) if isinstance(shape, int) else tuple(shape)
        self.column_default = default
        self.uniform, self.unit = uniform, unit
        self.flat = len(self.column_shape) == 1
        self.size = self.column_shape[0]
        dims = "x".join(map(str, self.column_shape))
        self.expected = expected or (f"{self.size} numbers" if self.flat else f"a {dims} array")

    def __set__(self, obj: Any, value: Any) -> None:
        if self.flat:  # the per-entity teaching path: no numpy call beyond one tolist()
            t = type(value)
            if t is _ND:
                if value.dtype is _F64 and value.shape == self.column_shape and self._fast_set(obj, value):
                    return
            elif (t is tuple or t is list) and len(value) == self.size and all(type(c) in _NUMBER for c in value):
                try:
                    arr = np.array(value, dtype=np.float64)
                except OverflowError:  # an int beyond float range: the full path below names the field
                    pass
                else:
                    if self._fast_set(obj, arr):
                        return
        converted = self.convert(value)
        if converted is _INVALID:
            raise FieldError(f"{type(obj).__name__}.{self.name} {self._reason(value)} ({self.expected}), "
                             f"got {value!r}")
        self._store_value(obj, converted)

    def _reason(self, value: Any) -> str:
        """What is wrong with a refused value, in the words of the error message."""
        if isinstance(value, (str, bytes)) or np.asarray(value).dtype.kind not in "iuf":
            return "must be numbers"
        if np.shape(value) != self.column_shape and not (self.uniform and np.ndim(value) == 0):
            return f"must have shape {self.column_shape}"
        return "must be finite"

    def _fast_set(self, obj: Any, value: np.ndarray) -> bool:
        """Store ``value`` if it surely passes (finite; unit length for a quaternion); False sends it the long way.

        The sum of the entries is finite exactly when all of them are, unless it overflows (then the full check
        decides); a quaternion's squared norm is finite and within the tolerance of 1 only for a finite unit one.
        """
        items = value.tolist()
        if self.unit:
            w, x, y, z = items
            if not abs(w * w + x * x + y * y + z * z - 1.0) <= _UNIT_TOLERANCE:
                return False
        elif not math.isfinite(sum(items)):
            return False
        return self._store_fast(obj, value)

    def convert(self, value: Any) -> Any:
        arr = as_floats(value, self.column_shape, uniform=self.uniform)
        if arr is None:
            return _INVALID
        if self.unit:
            peak = float(np.max(np.abs(arr)))
            if peak == 0.0:
                return arr  # all zero: kept, and read as no rotation (the transform system's rule)
            if peak > 1.0 or not abs(float(np.dot(arr, arr)) - 1.0) <= _UNIT_TOLERANCE:  # no overflow past 1
                scaled = arr / peak  # dividing by the largest entry first: no overflow or underflow
                arr = scaled / math.sqrt(float(np.dot(scaled, scaled)))
        return arr

    # The value goes into the column (or the component's local storage before it joins a scene), not __dict__.
    def _store_value(self, obj: Any, value: np.ndarray) -> None:
        self._store_row(obj, value)
