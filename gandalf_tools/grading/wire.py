"""The wire format between the grader and the sandboxed student process: JSON plus numpy arrays as ``.npy`` bytes.

Never pickle. A message is one frame: an 8-byte length, a 4-byte count of binary blobs, the JSON text, then each
blob (8-byte length + bytes). In the JSON, values that JSON lacks are tagged objects:

* ``{"$t": [...]}`` a tuple, ``{"$d": [[key, value], ...]}`` a dict (any plain keys), ``{"$set": [...]}`` a set;
* ``{"$r": i, "d": dtype, "s": shape}`` the i-th blob, an array's raw bytes (``dtype`` a plain number type such as
  ``"<f8"``: no object, structured or sub-array types), or ``{"$a": [numbers], "s": shape}`` a small finite float64
  array inline;
* ``{"$cb": n}`` a function of the other side, called back through the channel, or ``{"$cb": recipe}`` one the
  reader rebuilds from the course's own code (:func:`gandalf_tools.grading.sandbox.recipe`);
* ``{"$b": i}`` the i-th blob as ``bytes``;
* ``{"$f": "nan" | "inf" | "-inf"}`` a float JSON cannot spell;
* ``{"$o": "module:Qualname", "f": {field: value}}`` an engine object (a component, a resource's data, an input
  event) by its field values; the reading side decides whether and how it is rebuilt (``objects=``).

Decoding builds only builtins and numpy arrays (plus the objects the reader's ``objects`` callback makes from plain
fields): an object whose ``__eq__`` is always true or a float subclass cannot come through. This module is also
copied into the sandbox (it imports nothing of the project).
"""

from __future__ import annotations

import json
import math
import os
import select
import struct
import time
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

#: The largest frame either side accepts (a student's 50 MB of output or a giant array fails in words).
MAX_FRAME = 256 * 1024 * 1024
_HEAD = struct.Struct("<QI")
_BLOB = struct.Struct("<Q")


class WireError(ValueError):
    """A value that cannot travel (a type the wire does not carry) or a malformed frame."""


def _float(value: float) -> Any:
    value = float.__float__(value) if isinstance(value, float) else float(value)
    if math.isnan(value):
        return {"$f": "nan"}
    if math.isinf(value):
        return {"$f": "inf" if value > 0 else "-inf"}
    return value


def encode_value(value: Any, blobs: list[bytes], objects: Callable[[Any], Any] | None = None,
                 depth: int = 0, callbacks: Callable[[Any], int] | None = None) -> Any:
    """``value`` as JSON-ready data, its arrays and bytes appended to ``blobs``; ``objects(value)`` turns any
    other object into ``(type_name, fields)`` or raises :class:`WireError`; ``callbacks(fn)`` numbers a function
    the other side may call back (``{"$cb": n}``)."""
    if depth > 40:
        raise WireError("a value nested more than 40 levels deep")
    t = type(value)
    if value is None or t is bool or t is str:
        return value
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return _float(value)
    if isinstance(value, str):
        return str.__str__(value)
    if isinstance(value, (bytes, bytearray, memoryview)):
        blobs.append(bytes(value))
        return {"$b": len(blobs) - 1}
    if isinstance(value, np.ndarray):
        if value.dtype.hasobject or value.dtype.kind not in "biuf":
            raise WireError(f"an array of dtype {value.dtype} (only numbers travel)")
        if value.size <= 64 and value.dtype == np.float64 and np.isfinite(value).all():
            return {"$a": value.ravel().tolist(), "s": list(value.shape)}
        blobs.append(np.ascontiguousarray(value).tobytes())
        return {"$r": len(blobs) - 1, "d": value.dtype.str, "s": list(value.shape)}
    if isinstance(value, tuple):
        return {"$t": [encode_value(v, blobs, objects, depth + 1, callbacks) for v in value]}
    if isinstance(value, list):
        return [encode_value(v, blobs, objects, depth + 1, callbacks) for v in value]
    if isinstance(value, (set, frozenset)):
        return {"$set": [encode_value(v, blobs, objects, depth + 1, callbacks) for v in value]}
    if isinstance(value, (dict, Mapping)):  # a read-only mapping (a material's params) travels as a dict
        return {"$d": [[encode_value(k, blobs, objects, depth + 1, callbacks),
                        encode_value(v, blobs, objects, depth + 1, callbacks)] for k, v in value.items()]}
    if callbacks is not None and callable(value) and not isinstance(value, type):
        ref = callbacks(value)  # a number (called back), or a recipe the other side rebuilds the function from
        return {"$cb": ref if isinstance(ref, int) else encode_value(ref, blobs, None, depth + 1)}
    if objects is not None:
        name, fields = objects(value)
        return {"$o": name,
                "f": {str(k): encode_value(v, blobs, objects, depth + 1, callbacks) for k, v in fields.items()}}
    raise WireError(f"a {t.__name__} (only numbers, strings, tuples, lists, dicts and arrays travel)")


def decode_value(data: Any, blobs: list[bytes], objects: Callable[[str, dict[str, Any]], Any] | None = None,
                 callbacks: Callable[[int], Any] | None = None) -> Any:
    """The value :func:`encode_value` made; ``objects(name, fields)`` rebuilds a tagged object (or raises),
    ``callbacks(n)`` makes the stand-in of the other side's function ``n``."""
    if data is None or isinstance(data, (bool, int, float, str)):
        return data
    if isinstance(data, list):
        return [decode_value(v, blobs, objects, callbacks) for v in data]
    if not isinstance(data, dict) or len(data) not in (1, 2, 3):
        raise WireError(f"malformed value {str(data)[:80]}")
    if "$t" in data:
        return tuple(decode_value(v, blobs, objects, callbacks) for v in data["$t"])
    if "$set" in data:
        return {decode_value(v, blobs, objects, callbacks) for v in data["$set"]}
    if "$d" in data:
        return {decode_value(k, blobs, objects, callbacks): decode_value(v, blobs, objects, callbacks)
                for k, v in data["$d"]}
    if "$f" in data:
        return float(data["$f"])
    if "$b" in data:
        return bytes(blobs[int(data["$b"])])
    if "$a" in data:
        return np.array([float(x) for x in data["$a"]], dtype=np.float64).reshape([int(n) for n in data["s"]])
    if "$r" in data:
        return _raw_array(blobs[int(data["$r"])], data.get("d"), data.get("s"))
    if "$cb" in data and callbacks is not None:
        ref = data["$cb"]
        return callbacks(ref if isinstance(ref, int) else decode_value(ref, blobs))
    if "$o" in data and objects is not None:
        fields = {str(k): decode_value(v, blobs, objects, callbacks) for k, v in dict(data.get("f", {})).items()}
        return objects(str(data["$o"]), fields)
    raise WireError(f"malformed value {str(data)[:80]}")


def _raw_array(blob: bytes, dtype: Any, shape: Any) -> np.ndarray:
    """The array ``{"$r": ...}`` names: a plain number type only, its bytes exactly the shape's (a copy: writable)."""
    try:
        kind = np.dtype(str(dtype))
        dims = [int(n) for n in shape]
    except (TypeError, ValueError) as exc:
        raise WireError(f"an array of type {str(dtype)[:40]!r} ({exc})") from None
    if kind.kind not in "biuf" or kind.fields is not None or kind.subdtype is not None or min(dims, default=0) < 0:
        raise WireError(f"an array of type {kind} (only numbers travel)")
    if math.prod(dims) * kind.itemsize != len(blob):
        raise WireError(f"an array of shape {dims} and type {kind} in {len(blob)} bytes")
    return np.frombuffer(blob, dtype=kind).reshape(dims).copy()


def pack(message: Any, objects: Callable[[Any], Any] | None = None,
         callbacks: Callable[[Any], int] | None = None) -> bytes:
    """One frame holding ``message``."""
    blobs: list[bytes] = []
    text = json.dumps(encode_value(message, blobs, objects, 0, callbacks), allow_nan=False).encode()
    parts = [text]
    for blob in blobs:
        parts += [_BLOB.pack(len(blob)), blob]
    body = b"".join(parts)
    if len(body) > MAX_FRAME:
        raise WireError(f"a message of {len(body) / 2**20:.0f} MiB (at most {MAX_FRAME // 2**20} MiB)")
    return _HEAD.pack(len(text), len(blobs)) + _BLOB.pack(len(body)) + body


class Timeout(Exception):
    """The other side did not answer before the deadline."""


def _read_exact(fd: int, n: int, deadline: float | None = None) -> bytes:
    chunks, left = [], n
    while left:
        if deadline is not None:
            wait = deadline - time.monotonic()
            if wait <= 0 or not select.select([fd], [], [], wait)[0]:
                raise Timeout
        chunk = os.read(fd, min(left, 1 << 20))
        if not chunk:
            raise EOFError("the other side closed the channel")
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def read_frame(fd: int, deadline: float | None = None) -> tuple[Any, list[bytes]]:
    """The next frame on ``fd`` as (JSON data, blobs); EOFError when the writer is gone, :class:`Timeout` when it
    has not all come by ``deadline`` (``time.monotonic()``)."""
    text_len, count = _HEAD.unpack(_read_exact(fd, _HEAD.size, deadline))
    (body_len,) = _BLOB.unpack(_read_exact(fd, _BLOB.size, deadline))
    if body_len > MAX_FRAME or text_len > body_len or count > body_len:
        raise WireError(f"a frame of {body_len} bytes (at most {MAX_FRAME})")
    body = _read_exact(fd, body_len, deadline)
    data = json.loads(body[:text_len])
    blobs, at = [], text_len
    for _ in range(count):
        (size,) = _BLOB.unpack(body[at:at + _BLOB.size])
        at += _BLOB.size
        if at + size > body_len:
            raise WireError("a blob past the end of its frame")
        blobs.append(body[at:at + size])
        at += size
    return data, blobs


def write_frame(fd: int, frame: bytes) -> None:
    view = memoryview(frame)
    while view:
        written = os.write(fd, view)
        view = view[written:]


# ---------------------------------------------------------------------------------------------------
# Engine objects by their fields (duck-typed: this module imports nothing of the project)
# ---------------------------------------------------------------------------------------------------


def type_name(cls: type) -> str:
    return f"{cls.__module__}:{cls.__qualname__}"


def fields_of(obj: Any) -> dict[str, Any]:
    """An engine object's field values: a dataclass's fields, a columnar component's columns (copied), or an
    ordinary component's attributes and slots."""
    import dataclasses

    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return {f.name: getattr(obj, f.name) for f in dataclasses.fields(obj)}
    columns = getattr(type(obj), "columns", None)
    if isinstance(columns, dict) and hasattr(obj, "_local"):
        return {name: np.array(getattr(obj, name), dtype=np.float64) for name in columns}
    if not hasattr(obj, "__dict__") and not hasattr(type(obj), "__slots__"):
        raise WireError(f"a {type(obj).__name__} (only numbers, strings, tuples, lists, dicts and arrays travel)")
    fields = dict(getattr(obj, "__dict__", {}))  # private ones too (a light keeps its kind behind a property)
    for cls in type(obj).__mro__:  # slots (an asset name component keeps its name in one)
        slots = getattr(cls, "__slots__", ())
        for slot in (slots,) if isinstance(slots, str) else slots:
            if slot not in ("__dict__", "__weakref__") and hasattr(obj, slot):
                fields[slot] = getattr(obj, slot)
    return fields


def build_object(cls: type, fields: dict[str, Any]) -> Any:
    """An object of ``cls`` with ``fields``: a dataclass through its constructor (and its checks), a component
    field by field through its setters (and their checks), without running its ``__init__``."""
    import dataclasses

    if dataclasses.is_dataclass(cls):
        return cls(**fields)
    obj = cls.__new__(cls)
    columnar = next((base for base in cls.__mro__ if base.__name__ == "ColumnarComponent"), None)
    if columnar is not None:
        columnar.__init__(obj)
    for name, value in fields.items():
        setattr(obj, name, value)
    return obj
