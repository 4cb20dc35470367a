"""Typed reading and writing of USD attributes, with errors that name the file, prim and attribute."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from pxr import Sdf, Usd, Vt

from .errors import USDSceneError

REQUIRED = object()
T = Sdf.ValueTypeNames


class FileContext:
    """The file being read or written, for error messages."""

    def __init__(self, file: str) -> None:
        self.file = file

    def fail(self, prim: Usd.Prim | str | None, attribute: str | None, detail: str) -> USDSceneError:
        path = str(prim.GetPath()) if isinstance(prim, Usd.Prim) else prim
        return USDSceneError(self.file, detail, prim=path, attribute=attribute)


def write(prim: Usd.Prim, name: str, type_name: Sdf.ValueTypeName, value: Any) -> None:
    """Author ``name`` on ``prim`` (a custom attribute unless a schema declares it)."""
    prim.CreateAttribute(name, type_name).Set(value)


def read(ctx: FileContext, prim: Usd.Prim, name: str, types: str | tuple[str, ...], default: Any = REQUIRED) -> Any:
    """The authored value of ``name``, checked against the USD type names in ``types`` (e.g. ``"double3"``).

    A missing attribute returns ``default`` or, when there is none, raises USDSceneError; so does a wrong type.
    """
    types = (types,) if isinstance(types, str) else types
    attr = prim.GetAttribute(name)
    if not attr or not attr.HasAuthoredValue():
        if default is REQUIRED:
            raise ctx.fail(prim, name, f"is missing (expected {' or '.join(types)})")
        return default
    found = str(attr.GetTypeName())
    if found not in types:
        raise ctx.fail(prim, name, f"has type {found}, expected {' or '.join(types)}")
    value = attr.Get()
    if value is None:
        raise ctx.fail(prim, name, "has no value")
    return value


def read_float(ctx: FileContext, prim: Usd.Prim, name: str, default: Any = REQUIRED, *,
               allow_inf: bool = False) -> Any:
    """A finite float (``+inf`` too with ``allow_inf``, e.g. an infinite far plane)."""
    value = read(ctx, prim, name, ("double", "float"), default)
    if value is default:
        return value
    if not (math.isfinite(value) or (allow_inf and value == math.inf)):
        raise ctx.fail(prim, name, f"must be finite, got {value}")
    return float(value)


def authored(prim: Usd.Prim, name: str) -> bool:
    """True when ``prim`` has a value for attribute ``name`` (so fallbacks need not be read at all)."""
    attribute = prim.GetAttribute(name)
    return bool(attribute) and attribute.HasAuthoredValue()


def read_floats(ctx: FileContext, prim: Usd.Prim, name: str, types: tuple[str, ...], size: int | None,
                default: Any = REQUIRED) -> Any:
    """A finite float64 vector (``double3``, ``double[]``, ...), of length ``size`` when given."""
    value = read(ctx, prim, name, types, default)
    if value is default:
        return value
    a = np.array(value, dtype=np.float64).reshape(-1)
    if size is not None and a.size != size:
        raise ctx.fail(prim, name, f"must have {size} values, got {a.size}")
    if not np.isfinite(a).all():
        raise ctx.fail(prim, name, f"values must be finite, got {a.tolist()}")
    return a


def numeric_array(ctx: FileContext, prim: Usd.Prim, name: str, types: tuple[str, ...], dtype: type,
                  width: int | None, default: Any = REQUIRED) -> Any:
    """An array attribute as numpy (shape (N, width), or (N,) when width is None), exact in its stored type."""
    value = read(ctx, prim, name, types, default)
    if value is default:
        return value
    a = np.array(value, dtype=dtype)
    if width is None:
        return a.reshape(-1)
    if a.ndim != 2 or a.shape[1] != width:
        raise ctx.fail(prim, name, f"expected rows of {width} values, got shape {a.shape}")
    return a


def simple_value(value: Any) -> tuple[Sdf.ValueTypeName, Any]:
    """The USD type and value for a registered component's field, or TypeError/ValueError saying why not."""
    if isinstance(value, (bool, np.bool_)):
        return T.Bool, bool(value)
    if isinstance(value, (int, np.integer)):
        if not -(2**63) <= int(value) < 2**63:
            raise ValueError(f"{value} does not fit a 64-bit integer")
        return T.Int64, int(value)
    if isinstance(value, (float, np.floating)):
        if not math.isfinite(value):
            raise ValueError(f"{value} is not finite")
        return T.Double, float(value)
    if isinstance(value, str):
        return T.String, value
    if isinstance(value, (Sequence, np.ndarray)):
        try:
            a = np.asarray(value, dtype=np.float64)
        except (TypeError, ValueError):
            raise TypeError(f"{value!r} is not a sequence of numbers") from None
        if a.ndim != 1 or any(isinstance(v, (str, bytes)) for v in np.asarray(value, dtype=object).reshape(-1)):
            raise TypeError(f"{value!r} is not a flat sequence of numbers")
        if not np.isfinite(a).all():
            raise ValueError(f"{value!r} has values that are not finite")
        return T.DoubleArray, Vt.DoubleArray.FromNumpy(a)
    raise TypeError(f"{type(value).__name__} values cannot be saved (use bool, int, float, str or floats)")


#: MeshData's fields and the UsdGeom.Mesh attributes they are read from: an error names the attribute in the file.
MESH_ATTRIBUTES = {"positions": "points", "indices": "faceVertexIndices", "normals": "normals", "uvs": "primvars:st",
                   "tangents": "primvars:tangents", "colors": "primvars:displayColor",
                   "patch_size": "gandalf:patchSize"}


def mesh_attribute(field: str) -> str:
    """The USD attribute a MeshData ``field`` came from (itself when it has no counterpart)."""
    return MESH_ATTRIBUTES.get(field, field)
