"""Components: plain data attached to entities.

Most components are ordinary objects. A :class:`ColumnarComponent` keeps its numeric fields in
scene-wide numpy columns while it belongs to a scene, so a system can update every instance at once
(``store.column("translation")`` is an ``(N, 3)`` array) while student code still writes
``transform.translation = (0, 1, 0)`` one entity at a time.

Reading a columnar field gives a live view of its row (so ``transform.translation[1] += 1`` works);
copy it (``.copy()``) to keep a value, since rows move when other entities leave the scene.

**What changed.** A store remembers which rows may have changed since a system last asked
(:meth:`ColumnStore.take_changes`), so a system that derives data from the columns (the transform system's world
matrices) recomputes only those rows. Any write of a field marks its row, and so does *reading* one (the live view
it returns may be written through); ``store.column(name)`` marks every row (the caller may write any of them).
A batch system that writes a few rows says so with :meth:`ColumnStore.touch` after writing ``store.columns``;
code that only reads uses :meth:`ColumnStore.read`. Derived columns (``derived``: the world matrix) are the
output of such a system: reading them marks nothing.
"""

from __future__ import annotations

import math
from typing import Any, ClassVar

import numpy as np

_ND = np.ndarray
_F64 = np.dtype(np.float64)
_NUMBER = (float, int, np.float64)
_NO_ROWS = np.zeros(0, dtype=np.intp)
_NO_ROWS.flags.writeable = False


class Component:
    """Base class of all components. Components hold data only; behaviour lives in systems."""

    #: True for component types whose objects never change after construction (a mesh or material name):
    #: :meth:`Scene.create_entities` then gives all the new entities the same object instead of copies.
    immutable: ClassVar[bool] = False
    #: False for a component that marks an entity as a tool's own (an editor's panel): saving a scene leaves
    #: every entity that holds one out.
    saved: ClassVar[bool] = True

    def __repr__(self) -> str:
        fields = ", ".join(f"{k}={v!r}" for k, v in vars(self).items() if not k.startswith("_"))
        return f"{type(self).__name__}({fields})"

    def _set_fields(self, **values: Any) -> None:
        """Set the fields in the order given, each through its own checks: a constructor's assignments."""
        for name, value in values.items():
            setattr(self, name, value)


class RowField:
    """Base of the descriptors of a columnar component's numeric fields: reading gives a live view of the field's row
    of the scene's column, or the component's own array before it joins a scene. (Inherited rather than called:
    reading a field is the per-entity path's hottest line.)"""

    name: str
    #: False for a derived column (``ColumnarComponent.derived``): reading its live view marks no change.
    tracks = True

    def __get__(self, obj: Any, owner: type | None = None) -> Any:
        if obj is None:
            return self
        store = obj._store
        if store is None:
            return obj._local[self.name]
        if self.tracks:  # the live view may be written through: the row counts as changed
            store.touched.add(obj._row)
        return store.columns[self.name][obj._row]

    def _store_row(self, obj: Any, value: np.ndarray) -> None:
        """Store the checked float64 ``value`` (the component's own array from now on) as the field."""
        store = obj._store
        if store is None:
            obj._local[self.name] = value
        else:
            store.columns[self.name][obj._row] = value
            store.touched.add(obj._row)

    def _store_fast(self, obj: Any, value: np.ndarray) -> bool:
        """Store the checked float64 ``value`` of a fast path (the component keeps a copy); True."""
        store = obj._store
        if store is None:
            obj._local[self.name] = value.copy()
        else:
            store.columns[self.name][obj._row] = value
            store.touched.add(obj._row)
        return True


class _ColumnField(RowField):
    """Descriptor that reads/writes one row of a column, or local storage before the component joins a scene."""

    def __init__(self, name: str, shape: tuple[int, ...]) -> None:
        self.name = name
        self.shape = shape
        self.flat = len(shape) == 1  # vectors get the cheap finiteness check of the fast path

    def _fast_set(self, obj: ColumnarComponent, value: np.ndarray) -> bool:
        """Store a float64 vector of the right shape without numpy's per-call checks; False if it needs them.

        The sum of the components is finite exactly when all of them are, unless it overflows (then the full
        check below decides): one ``tolist`` and a Python ``sum`` instead of ``np.isfinite(...).all()``.
        """
        if not math.isfinite(sum(value.tolist())):
            return False
        return self._store_fast(obj, value)

    def __set__(self, obj: ColumnarComponent, value: Any) -> None:
        if self.flat:
            t = type(value)
            if t is _ND:
                if value.dtype is _F64 and value.shape == self.shape and self._fast_set(obj, value):
                    return
            elif (t is tuple or t is list) and len(value) == self.shape[0] and all(type(c) in _NUMBER for c in value):
                try:
                    arr = np.array(value, dtype=np.float64)
                except OverflowError:  # an int beyond float range: the full path below says so
                    pass
                else:
                    if self._fast_set(obj, arr):
                        return
        arr = np.asarray(value, dtype=np.float64)
        if arr.shape != self.shape:
            try:
                arr = np.broadcast_to(arr, self.shape)
            except ValueError:
                raise ValueError(
                    f"{type(obj).__name__}.{self.name} must have shape {self.shape}, got {np.shape(value)}"
                ) from None
        if not np.isfinite(arr).all():
            raise ValueError(f"{type(obj).__name__}.{self.name} must be finite, got {value!r}")
        self._store_row(obj, np.array(arr, dtype=np.float64) if obj._store is None else arr)


class ColumnarComponent(Component):
    """A component whose float64 fields live in per-scene numpy columns.

    Subclasses list their fields in ``columns = {"name": (shape, default)}``.
    """

    columns: ClassVar[dict[str, tuple[tuple[int, ...], Any]]] = {}
    #: Columns a system computes from the others (a world matrix): reading them marks no row as changed.
    derived: ClassVar[frozenset[str]] = frozenset()
    _defaults: ClassVar[dict[str, np.ndarray]] = {}

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        # Validated fields declared on the class (``translation = Vector(3, 0.0)``, see components.fields) are
        # columns too: anything with a ``column_shape`` and a ``column_default`` (the ECS imports no component).
        declared = {name: (tuple(attr.column_shape), attr.column_default) for name, attr in vars(cls).items()
                    if hasattr(attr, "column_shape") and hasattr(attr, "column_default")}
        if declared:
            cls.columns = {**cls.columns, **declared}
        for name, (shape, _default) in cls.columns.items():
            if not hasattr(getattr(cls, name, None), "column_shape"):  # a plain column: the unchecked descriptor
                setattr(cls, name, _ColumnField(name, tuple(shape)))
            descriptor = vars(cls).get(name)
            if isinstance(descriptor, RowField):
                descriptor.tracks = name not in cls.derived
        # Built once per class: creating 100k components then costs a few array copies each.
        cls._defaults = {
            name: np.array(np.broadcast_to(np.asarray(default, np.float64), shape))
            for name, (shape, default) in cls.columns.items()
        }

    def __init__(self) -> None:
        self._store: ColumnStore | None = None
        self._row = -1
        self._local = {name: default.copy() for name, default in self._defaults.items()}

    def __repr__(self) -> str:
        fields = ", ".join(f"{k}={getattr(self, k).tolist()!r}" for k in self.columns)
        return f"{type(self).__name__}({fields})"

    @classmethod
    def batch(cls, n: int | None = None, **values: Any) -> ColumnBatch:
        """Field values of ``n`` new components at once, for :meth:`Scene.create_entities`.

        Each keyword names a column and gives either one value for every component (the field's shape) or
        one per component (shape ``(n, *field_shape)``); columns not given take their defaults. ``n`` may be
        left out when an array gives it. No component objects are made here: the scene writes the rows
        straight into its column store.
        """
        return ColumnBatch(cls, n, values)

    @classmethod
    def _bare(cls) -> ColumnarComponent:
        """A component object for a row written by a bulk attach (``__init__`` is not called: its work was done
        by :meth:`batch`). Subclasses that keep state outside their columns override this."""
        return object.__new__(cls)


class ColumnBatch:
    """Validated float64 rows for ``count`` new components of one columnar type (see ColumnarComponent.batch)."""

    def __init__(self, component_type: type[ColumnarComponent], n: int | None, values: dict[str, Any]) -> None:
        name = f"{component_type.__name__}.batch"
        unknown = sorted(set(values) - set(component_type.columns))
        if unknown:
            raise ValueError(f"{name}: unknown field(s) {', '.join(unknown)}; the fields are "
                             f"{', '.join(component_type.columns)}")
        if n is not None and (isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 0):
            raise ValueError(f"{name}: n must be a non-negative int, got {n!r}")
        arrays: dict[str, np.ndarray] = {}
        count = None if n is None else int(n)
        for field, value in values.items():
            if value is None:
                continue
            shape = tuple(component_type.columns[field][0])
            arr = np.asarray(value) if not isinstance(value, (str, bytes)) else np.asarray(None)
            if arr.dtype.kind not in "iuf":
                raise ValueError(f"{name}: {field} must be numbers of shape {shape} (one value for all) or (n, "
                                 f"{', '.join(map(str, shape))}) (one per component), got {value!r:.80}")
            arr = arr.astype(np.float64, copy=False)
            if arr.shape != shape:
                if arr.ndim != len(shape) + 1 or arr.shape[1:] != shape:
                    raise ValueError(f"{name}: {field} must have shape {shape} (one value for all) or "
                                     f"(n, {', '.join(map(str, shape))}) (one per component), got {arr.shape}")
                if count is None:
                    count = len(arr)
                elif len(arr) != count:
                    raise ValueError(f"{name}: {field} has {len(arr)} rows but n is {count}")
            finite = np.isfinite(arr).reshape(arr.shape[: arr.ndim - len(shape)] + (-1,)).all(axis=-1)
            if not np.all(finite):
                where = "" if arr.shape == shape else f" (row {int(np.argmin(finite))})"
                raise ValueError(f"{name}: {field} must be finite{where}")
            arrays[field] = arr
        if count is None:
            raise ValueError(f"{name}: give n, or per-component arrays of shape (n, ...), to say how many")
        self.component_type = component_type
        self.count = count
        self.columns = arrays

    def __len__(self) -> int:
        return self.count

    def __repr__(self) -> str:
        return f"ColumnBatch({self.component_type.__name__}, count={self.count}, fields={list(self.columns)})"


class ColumnStore:
    """The columns of one columnar component type in one scene; rows are packed (swap-remove)."""

    def __init__(self, component_type: type[ColumnarComponent]) -> None:
        self.component_type = component_type
        self.capacity = 16
        self.count = 0
        self.columns: dict[str, np.ndarray] = {
            name: np.zeros((self.capacity, *shape)) for name, (shape, _) in component_type.columns.items()
        }
        self.owners: list[ColumnarComponent] = []
        #: Bumped when a row moves (a removal swaps the last row in): caches of row indices compare it.
        self.layout_version = 0
        #: Rows written (or read through a live view) one at a time since :meth:`take_changes`.
        self.touched: set[int] = set()
        self._touched_all = True  # every row may have changed (new rows, a whole-column view handed out)
        self._touched_runs: list[np.ndarray] = []  # rows a batch system named with touch()

    def attach(self, component: ColumnarComponent) -> None:
        if self.count == self.capacity:
            self._grow()
        row = self.count
        for name, col in self.columns.items():
            col[row] = component._local[name]
        component._store, component._row = self, row
        self.owners.append(component)
        self.count += 1
        self._touched_all = True

    def attach_batch(self, batch: ColumnBatch) -> list[ColumnarComponent]:
        """Append ``batch.count`` rows in one write per column; return their new component objects."""
        n = batch.count
        if self.count + n > self.capacity:
            self._grow(self.count + n)
        start, end = self.count, self.count + n
        defaults = self.component_type._defaults
        for name, col in self.columns.items():
            value = batch.columns.get(name)
            col[start:end] = defaults[name] if value is None else value
        ctype = self.component_type
        if ctype._bare.__func__ is ColumnarComponent._bare.__func__:  # type: ignore[attr-defined]
            made = [object.__new__(ctype) for _ in range(n)]
        else:
            bare = ctype._bare
            made = [bare() for _ in range(n)]
        for row, component in enumerate(made, start):
            state = component.__dict__
            state["_store"] = self
            state["_row"] = row
            state["_local"] = None
        self.owners.extend(made)
        self.count = end
        self._touched_all = True
        return made

    def detach(self, component: ColumnarComponent) -> None:
        row, last = component._row, self.count - 1
        component._local = {name: col[row].copy() for name, col in self.columns.items()}
        if row != last:
            moved = self.owners[last]
            for col in self.columns.values():
                col[row] = col[last]
            moved._row = row
            self.owners[row] = moved
        self.owners.pop()
        component._store, component._row = None, -1
        self.count -= 1
        self.layout_version += 1
        self._touched_all = True

    def column(self, name: str) -> np.ndarray:
        """A writable view of the live rows of column ``name`` (shape ``(count, *field_shape)``). Every row
        counts as changed (the caller may write any); read with :meth:`read`, or name the rows written with
        :meth:`touch` after writing ``columns[name]``, to say less."""
        if name not in self.component_type.derived:
            self._touched_all = True
        return self.columns[name][: self.count]

    def read(self, name: str) -> np.ndarray:
        """A read-only view of the live rows of column ``name``: marks nothing as changed."""
        view = self.columns[name][: self.count]
        view.flags.writeable = False
        return view

    def touch(self, rows: Any = None) -> None:
        """Say which rows were written through ``columns``: an index array, a slice, one row, or None for all."""
        if rows is None:
            self._touched_all = True
        elif isinstance(rows, (int, np.integer)):
            self.touched.add(int(rows))
        else:
            rows = (np.arange(*rows.indices(self.count)) if isinstance(rows, slice)
                    else np.asarray(rows, dtype=np.intp).reshape(-1))
            if 2 * len(rows) > self.count:  # most rows: recomputing them all (whole columns, no gathering) is cheaper
                self._touched_all = True
            else:
                self._touched_runs.append(rows)

    def take_changes(self) -> np.ndarray | None:
        """The rows that may have changed since the last call (sorted, each once), or None for "any row"; the
        record starts empty again. (One system owns it: the transform system for the transform store.)"""
        everything = self._touched_all
        touched, runs = self.touched, self._touched_runs
        self._touched_all = False
        if everything:
            touched.clear()
            runs.clear()
            return None
        if not touched and not runs:
            return _NO_ROWS
        if not runs:  # rows written one at a time only: unique already
            rows = np.fromiter(touched, dtype=np.intp, count=len(touched))
            rows.sort()
        else:  # rows named by touch() may repeat
            parts = [*runs, np.fromiter(touched, dtype=np.intp, count=len(touched))]
            rows = np.unique(np.concatenate(parts))
        touched.clear()
        runs.clear()
        return rows[rows < self.count]

    def rows_of(self, components: list[ColumnarComponent]) -> np.ndarray:
        """Row indices of ``components`` (for fancy indexing into columns)."""
        return np.fromiter((c._row for c in components), dtype=np.intp, count=len(components))

    def _grow(self, needed: int = 0) -> None:
        self.capacity = max(self.capacity * 2, needed)
        for name, col in self.columns.items():
            grown = np.zeros((self.capacity, *col.shape[1:]))
            grown[: self.count] = col[: self.count]
            self.columns[name] = grown
