"""The grader's stand-ins for a sandboxed student package: what the ``impl`` fixture returns with ``--student``.

* :class:`RemotePackage` (and a :class:`RemoteModule` per module of the package, put in ``sys.modules`` so that
  ``load_impl(step, student=True)`` and ``import <step>.exercises.<module>`` find them, never the student's files):
  an attribute is a :class:`RemoteFunction`, a :class:`RemoteClass`, or a value copied out as plain data.
  ``__file__`` is the student's ``__init__.py``: shader exercises are read from its folder as text.
* A function's arguments travel as plain data (a callable argument is called back here); its result comes back
  as plain data only: floats, ints, strings, tuples, lists, dicts, numpy arrays, and engine objects rebuilt here from
  their field values (:func:`trusted_object`) — never an object of the student's making.
* A class is a system: :func:`system_class` makes a trusted :class:`~gandalf_core.System` subclass whose instance
  forwards the hooks the student's class overrides to the instance in the sandbox, with copies of the components'
  field values, and applies back only the field values that come back with the same type and shape
  (:func:`apply_fields`) and the meshes, textures and materials registered in ``scene.assets``.

The stand-ins' own frames carry ``__tracebackhide__``: a failed test's traceback (the grade's log) goes from the test's
line to the student's error, without the grader's relay in between (``--fulltrace`` shows it), and pytest does not
read and parse this module's source again for every failed test.
"""

from __future__ import annotations

import builtins
import dataclasses
import sys
import types
import uuid
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from . import feedback, wire
from .sandbox import ALLOWED_MODULE, Sandbox, SandboxFailure
from .watchdog import ExerciseTimeout, describe_call

_ALLOWED_MODULE = ALLOWED_MODULE


class StudentError(Exception):
    """An exception of a type the grader does not know, raised by the student's code (its name and message)."""


def trusted_object(name: str, fields: dict[str, Any]) -> Any:
    """An engine object (a component, a resource's data, an input event) of the type ``module:Qualname``, built
    here from plain ``fields`` through its own checks; only types of the engine and the steps' own modules
    (never ``exercises`` or ``solutions``) that this process has already imported."""
    module, _, qualname = name.partition(":")
    if not _ALLOWED_MODULE.match(module) or module not in sys.modules:
        raise wire.WireError(f"a {qualname or name} (only numbers, strings, tuples, lists, dicts and arrays travel)")
    cls: Any = sys.modules[module]
    for part in qualname.split("."):
        cls = getattr(cls, part, None)
    from gandalf_core import Component

    if not isinstance(cls, type) or not (dataclasses.is_dataclass(cls) or issubclass(cls, Component)
                                         or cls.__name__ == "Input"):
        raise wire.WireError(f"a {qualname} (not a data type of the engine)")
    return wire.build_object(cls, fields)


def _encode_object(value: Any) -> tuple[str, dict[str, Any]]:
    module = type(value).__module__
    if not _ALLOWED_MODULE.match(module):
        raise wire.WireError(f"a {type(value).__name__} cannot be sent to the student's code")
    return wire.type_name(type(value)), wire.fields_of(value)


def _raise(error: dict[str, Any], label: str) -> None:
    __tracebackhide__ = True
    message = str(error.get("message", ""))
    where = f" (at {error['where']})" if error.get("where") else ""
    for name in error.get("types", []):
        cls = getattr(builtins, str(name), None)
        if isinstance(cls, type) and issubclass(cls, Exception) and cls is not Exception:
            try:
                exc = cls(message)
            except Exception:  # noqa: BLE001 - an exception type with another signature
                continue
            exc.gandalf_where = str(error.get("where") or "")  # type: ignore[attr-defined]  # the stub's file
            raise exc
    if "FieldError" == error.get("name"):
        from gandalf_core.components.fields import FieldError

        raise FieldError(message)
    raise StudentError(f"{label} raised {error.get('name', 'an exception')}: {message}{where}")


def _warn(caught: list[Any]) -> None:
    for categories, message in caught or ():
        category = next((getattr(builtins, c) for c in categories if isinstance(getattr(builtins, c, None), type)
                         and issubclass(getattr(builtins, c), Warning)), UserWarning)
        warnings.warn(str(message), category, stacklevel=3)


class Session:
    """The sandbox of one step's package, with the grader's budget per call."""

    def __init__(self, sandbox: Sandbox, budget: float, package: str) -> None:
        self.sandbox, self.budget, self.package = sandbox, budget, package

    def call(self, message: dict[str, Any], label: str | Callable[[], str], key: str,
             hang: str = "a loop that never ends?", crash: str = "") -> Any:
        __tracebackhide__ = True
        try:
            reply = self.sandbox.request({**message, "package": self.package}, label=label, key=key, budget=self.budget,
                                         objects=trusted_object, encode_objects=_encode_object, hang=hang,
                                         crash=crash)
        except SandboxFailure as exc:
            raise ExerciseTimeout(str(exc)) from None
        _warn(reply.get("warnings", []))
        if "error" in reply:
            _raise(reply["error"], label() if callable(label) else label)
        return reply.get("ok")


#: The newest calls of the student's functions, as they came: worded (numpy's printing costs more than a round trip)
#: only for a failed test's sentence, by :func:`flush_calls`.
_calls: list[tuple[str, tuple[Any, ...], dict[str, Any], Any]] = []
_KEPT_CALLS = 8


def flush_calls() -> None:
    """Hand the newest calls to :func:`feedback.record_call` (which words them), oldest first."""
    for name, args, kwargs, result in _calls:
        feedback.record_call(describe_call(name, args, kwargs), result)
    _calls.clear()


def forget_calls() -> None:
    """A new test starts."""
    _calls.clear()


class RemoteFunction:
    def __init__(self, session: Session, target: str) -> None:
        self.session, self.target = session, target
        self.__name__ = self.__qualname__ = target.rsplit(".", 1)[-1]

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        __tracebackhide__ = True
        try:
            result = self.session.call({"op": "call", "target": self.target, "args": list(args), "kwargs": kwargs},
                                       lambda: describe_call(self.__name__, args, kwargs), self.target)
        except Exception as error:
            feedback.record_raise(describe_call(self.__name__, args, kwargs), error)
            raise
        _calls.append((self.__name__, args, kwargs, result))  # for a failed check's sentence (see flush_calls)
        del _calls[:-_KEPT_CALLS]
        return result

    def __repr__(self) -> str:
        return f"<the student's {self.target} (sandboxed)>"


class RemoteClass:
    """The student's class: calling it makes the sandboxed instance and returns its trusted stand-in."""

    def __init__(self, session: Session, target: str, bases: list[str]) -> None:
        self.session, self.target, self.bases = session, target, bases
        self.__name__ = self.__qualname__ = target.rsplit(".", 1)[-1]

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        __tracebackhide__ = True
        label = describe_call(self.__name__, args, kwargs)
        info = self.session.call({"op": "new", "target": self.target, "args": list(args), "kwargs": kwargs},
                                 label, self.target)
        return system_class(self.__name__, self.bases)(self.session, self.target, info)


def _component_type(name: str) -> type:
    module, _, qualname = name.partition(":")
    from gandalf_core import Component

    if not _ALLOWED_MODULE.match(module) or module not in sys.modules:
        raise StudentError(f"a system over {qualname}: not a component type of the engine or the step")
    cls: Any = sys.modules[module]
    for part in qualname.split("."):
        cls = getattr(cls, part, None)
    if not (isinstance(cls, type) and issubclass(cls, Component)):
        raise StudentError(f"a system over {qualname}: not a component type")
    return cls


def apply_fields(component: Any, before: dict[str, Any], after: dict[str, Any]) -> None:
    """Set on ``component`` the fields whose value changed from ``before`` to ``after``, each only when the new
    value has the old one's kind (a number for a number, an array of the same shape, a string, a bool) and through
    the component's own setter (its checks)."""
    for name, old in before.items():
        new = after.get(name, old)
        if isinstance(old, np.ndarray):
            array = np.asarray(new, dtype=np.float64) if isinstance(new, (np.ndarray, list, tuple)) else None
            if array is None or array.shape != old.shape:
                raise StudentError(f"{type(component).__name__}.{name}: expected an array of shape {old.shape}, "
                                   f"got {type(new).__name__}")
            if not np.array_equal(array, old, equal_nan=True):
                setattr(component, name, array)
            continue
        if isinstance(old, bool) or isinstance(old, str) or old is None:
            ok = type(new) is type(old)
        elif isinstance(old, (int, float)):
            ok = type(new) in (int, float)
            new = float(new) if ok and isinstance(old, float) else new
        else:
            ok = type(new) is type(old)
        if not ok:
            raise StudentError(f"{type(component).__name__}.{name}: expected {type(old).__name__}, "
                               f"got {type(new).__name__}")
        if not _same(new, old):
            setattr(component, name, new)


def _same(a: Any, b: Any) -> bool:
    try:
        return bool(np.array_equal(np.asarray(a, dtype=object), np.asarray(b, dtype=object)))
    except Exception:  # noqa: BLE001
        return False


_HOOKS = ("on_create_system", "on_create_entity", "on_remove_entity", "on_update_system", "on_destroy_system")


def system_class(name: str, bases: list[str]) -> type:
    """A trusted System subclass standing in for the student's class ``name`` (a LightSystem's stand-in forwards
    ``pack``; the core's packing code and the render system stay here)."""
    from gandalf_core import System
    from gandalf_core.systems.light_system import LightSystem

    base: type = LightSystem if wire.type_name(LightSystem) in bases else System
    return type(name, (RemoteSystem, base), {"__module__": __name__})


class RemoteSystem:
    """Mixin of :func:`system_class`: the instance lives in the sandbox; the hooks it overrides run there."""

    def __init__(self, session: Session, target: str, info: dict[str, Any]) -> None:
        from gandalf_core import System

        types_ = [_component_type(t) for t in info.get("component_types", [])]
        System.__init__(self, types_, name=str(info.get("name", type(self).__name__))[:100])  # type: ignore[arg-type]
        self._session, self._target, self._id = session, target, int(info["id"])
        self._generation = session.sandbox.generation
        self._hooks = set(info.get("hooks", ()))
        self.updates_each_frame = bool(info.get("updates_each_frame", True))
        from gandalf_core.systems.light_system import pack_lights

        if isinstance(self, _light_system()):
            self.data = pack_lights([])

    def _forward(self, hook: str, args: list[Any], members: list[tuple[uuid.UUID, tuple[Any, ...]]]) -> Any:
        __tracebackhide__ = True
        shown = "on_update_entity" if hook == "on_update_system" and hook not in self._hooks else hook
        label = f"{type(self).__name__}.{shown}"
        if self._session.sandbox.generation != self._generation:
            raise ExerciseTimeout(f"{label}: this {type(self).__name__} was lost when its process was ended "
                                  "(an earlier call hung or crashed)")
        before = [[wire.fields_of(c) for c in comps] for _, comps in members]
        scene = getattr(self, "scene", None)
        app = getattr(scene, "app", None)
        message = {"op": "hook", "id": self._id, "hook": hook, "args": args,
                   "members": [[str(e), list(comps)] for e, comps in members],
                   "app": {"input": app.input} if app is not None and getattr(app, "input", None) is not None else None}
        reply = self._session.call(message, label, f"{self._target}.{hook}")
        returned = {str(e): comps for e, comps in reply.get("members", [])}
        for (entity, comps), old in zip(members, before):
            new = returned.get(str(entity))
            if new is None or len(new) != len(comps):
                continue
            for component, fields_before, theirs in zip(comps, old, new):
                if type(theirs) is not type(component):
                    raise StudentError(f"{label}: a component of entity {entity} came back as {type(theirs).__name__}")
                apply_fields(component, fields_before, wire.fields_of(theirs))
        for kind, asset_name, data in reply.get("assets", []):
            if scene is not None and kind in ("mesh", "texture", "material"):
                getattr(scene.assets, kind)(str(asset_name), data)
        return reply.get("result")

    def _members_list(self) -> list[tuple[uuid.UUID, tuple[Any, ...]]]:
        return list(self._members.items())  # type: ignore[attr-defined]

    def on_create_system(self) -> None:
        __tracebackhide__ = True
        if "on_create_system" in self._hooks:
            self._forward("on_create_system", [], self._members_list())

    def on_create_entity(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        __tracebackhide__ = True
        if "on_create_entity" in self._hooks:
            self._forward("on_create_entity", [str(entity)], [(entity, components)])

    def on_remove_entity(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        __tracebackhide__ = True
        if "on_remove_entity" in self._hooks:
            self._forward("on_remove_entity", [str(entity)], [(entity, components)])

    def on_update_system(self, ts: float) -> None:
        __tracebackhide__ = True
        if self._hooks & {"on_update_system", "on_update_entity"}:
            self._forward("on_update_system", [float(ts)], self._members_list())
        elif isinstance(self, _light_system()):
            _light_system().on_update_system(self, ts)

    def on_destroy_system(self) -> None:
        __tracebackhide__ = True
        if "on_destroy_system" in self._hooks:
            self._forward("on_destroy_system", [], self._members_list())

    def pack(self, components: list[tuple[Any, ...]]) -> bytes:
        from gandalf_core.render.frame import LIGHTS_BYTES

        if "pack" not in self._hooks:
            return _light_system().pack(self, components)  # type: ignore[arg-type]
        members = {id(c): e for e, c in self._members_list()}
        pairs = [(members.get(id(c), uuid.uuid4()), tuple(c)) for c in components]
        result = self._forward("pack", [], pairs)
        if not isinstance(result, bytes) or len(result) != LIGHTS_BYTES:
            raise StudentError(f"{type(self).__name__}.pack returned {type(result).__name__} "
                               f"of {len(result) if isinstance(result, bytes) else '?'} bytes, "
                               f"expected {LIGHTS_BYTES} bytes")
        return result


def _light_system() -> type:
    from gandalf_core.systems.light_system import LightSystem

    return LightSystem


class RemoteModule(types.ModuleType):
    """A module of the student's package, as the grader sees it: names answered from the sandbox."""

    def __init__(self, name: str, session: Session, prefix: str, names: dict[str, Any], file: str) -> None:
        super().__init__(name)
        self.__file__ = file
        self._session, self._prefix, self._names = session, prefix, names
        self._cache: dict[str, Any] = {}

    def __setattr__(self, attr: str, value: Any) -> None:
        """A test's ``monkeypatch.setattr`` of one of the student's functions (by the grader's own function, or back
        to the student's): the sandboxed module gets it too, so the student's other code calls it."""
        if not attr.startswith("_") and attr in getattr(self, "_names", {}) and callable(value):
            target = f"{self._prefix}{attr}"
            own = isinstance(value, RemoteFunction) and value.target == target  # monkeypatch's undo
            self._session.call({"op": "patch", "target": target, "value": None if own else value},
                               f"patching {target}", "patch")
            self._cache[attr] = value
            return
        super().__setattr__(attr, value)

    def __delattr__(self, attr: str) -> None:
        """The undo of a patch (``monkeypatch`` deletes what it set): the student's own function again."""
        if not attr.startswith("_") and attr in getattr(self, "_names", {}):
            target = f"{self._prefix}{attr}"
            self._session.call({"op": "patch", "target": target, "value": None}, f"patching {target}", "patch")
            self._cache.pop(attr, None)
            return
        super().__delattr__(attr)

    def __getattr__(self, attr: str) -> Any:
        if attr.startswith("__") or attr in ("_session", "_prefix", "_names", "_cache"):
            raise AttributeError(attr)
        if attr in self._cache:
            return self._cache[attr]
        target = f"{self._prefix}{attr}"
        info = self._names.get(attr)
        if info is None:
            raise AttributeError(f"module {self.__name__!r} has no attribute {attr!r}")
        kind = info.get("kind")
        if kind == "function":
            value: Any = RemoteFunction(self._session, target)
        elif kind == "class":
            value = RemoteClass(self._session, target, list(info.get("bases", [])))
        elif kind == "value":
            value = info.get("value")
        elif kind == "module":
            value = sys.modules.get(f"{self.__name__.split('.exercises')[0]}.exercises.{attr}")
        else:
            raise AttributeError(f"{target}: a {info.get('type', 'value')} the grader cannot use")
        self._cache[attr] = value
        return value


class RemotePackage(RemoteModule):
    """The student's package (``<step>.exercises``) in the sandbox; its names are read on first use."""

    def __init__(self, step: str, folder: Path, session: Session) -> None:
        super().__init__(f"{step}.exercises", session, "", {}, str(Path(folder) / "__init__.py"))
        self.__path__: list[str] = []  # submodules come from sys.modules (RemoteModule), never from the folder
        self.__package__ = self.__name__
        self._loaded = False

    def __getattr__(self, attr: str) -> Any:
        if attr.startswith("__") or attr in ("_session", "_prefix", "_names", "_cache", "_loaded"):
            raise AttributeError(attr)
        if not self._loaded:
            self._load()
        return super().__getattr__(attr)

    def _load(self) -> None:
        self._loaded = True
        listing = self._session.call({"op": "import"}, f"importing {self.__name__}", "import")
        self._names = dict(listing.get("names", {}))
        for module, names in dict(listing.get("modules", {})).items():
            name = f"{self.__name__}.{module}"
            sys.modules[name] = RemoteModule(name, self._session, f"{module}.", dict(names),
                                             str(Path(self.__file__).parent / f"{module}.py"))


#: The students' folders graded in this process (resolved) -> their step package, and the sandbox of each.
_installed: dict[Path, tuple[str, Sandbox]] = {}


def student_folders() -> dict[Path, str]:
    """The folders of the students' packages this grading session runs in a sandbox -> their step package."""
    return {folder: step for folder, (step, _box) in _installed.items()}


def hidden_outputs() -> tuple[str, ...]:
    """The folders the grading session hides from the student's process (its grade files' folders)."""
    return tuple(dict.fromkeys(p for _step, box in _installed.values() for p in box.hide))


def uninstall() -> None:
    """Forget the students' packages (the grading session is over)."""
    _installed.clear()


def install(step: str, folder: Path, sandbox: Sandbox, budget: float) -> RemotePackage:
    """The stand-in of ``<step>.exercises`` for ``folder``, in ``sys.modules`` (and as the step's attribute) in
    place of any real one, so that nothing in this process imports the student's files."""
    import importlib

    package = RemotePackage(step, folder, Session(sandbox, budget, f"{step}.exercises"))
    _installed[Path(folder).resolve()] = (step, sandbox)
    for name in [k for k in sys.modules if k == package.__name__ or k.startswith(package.__name__ + ".")]:
        del sys.modules[name]
    sys.modules[package.__name__] = package
    parent = importlib.import_module(step)
    parent.exercises = package  # type: ignore[attr-defined]
    return package
