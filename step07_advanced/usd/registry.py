"""What a USD file may name: the allow-lists of component classes, system classes and functions.

A file names classes, never code: ``register_component(Spin, fields=["speed", "axis"])`` saves each listed field
of every ``Spin`` as a ``gandalf:Spin:<field>`` attribute; ``register_system(SpinSystem)`` saves the system by
its import path (``gandalf_core.systems.spin.SpinSystem``) and builds it again on load, with the constructor
settings it declares; ``register_function(look_at)`` lets a system setting hold that one function. Only
registered classes and functions are ever built or called on load.

A course step declares what it saves once, in its ``saved.py`` (plain data beside its lessons: ``COMPONENTS``
maps a component class to its saved fields, ``SYSTEMS`` a system class to its constructor settings,
``UNSAVEABLE`` a system class to why a file cannot hold it, ``FUNCTIONS`` lists the functions a setting may
name); this module reads that declaration the first time it meets a class of that step, so no lesson file
imports the persistence layer and the engine never imports a step. A program registers its own classes with
the functions below. A file may name a class whose module the loading program has not imported yet: the loader
imports that module (and its package's ``saved.py``) only when it lies in an allowed package (gandalf_core, the
course's ``stepNN_*`` folders, or one added with :func:`allow_package`), and then uses the class only if it is
declared or registered.

Field and setting values must be simple: bool, int, float, str, or a fixed-length sequence of floats (tuple,
list or 1-D numpy array). A component is rebuilt as ``cls()`` with each saved field assigned (the default
value's type, and sequence length, is the field's schema); a component class whose constructor needs arguments
is built as ``cls(**{the saved fields that are its parameters})`` (they must cover every required one), and
then every saved field is assigned. Nothing here imports USD.
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import re
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from gandalf_core.ecs import Component, System


@dataclass(frozen=True)
class Registration:
    """A registered component class and the names of its saved fields."""

    cls: type[Component]
    fields: tuple[str, ...]
    #: ``cls()`` works; else the loader calls ``cls(**{the fields that are constructor parameters})``.
    default_constructible: bool = True
    constructor_fields: tuple[str, ...] = ()

    @property
    def key(self) -> str:
        return class_key(self.cls)


@dataclass(frozen=True)
class SystemRegistration:
    """A registered system class: its constructor settings, or why it cannot be saved at all."""

    cls: type[System]
    settings: tuple[str, ...]
    unsaveable: str | None = None

    @property
    def key(self) -> str:
        return class_key(self.cls)


_COMPONENTS: dict[str, Registration] = {}
_SYSTEMS: dict[str, SystemRegistration] = {}
_FUNCTIONS: dict[str, Callable[..., Any]] = {}
_PACKAGES: set[str] = {"gandalf_core"}
_STEP_PACKAGE = re.compile(r"step\d\d_[A-Za-z0-9_]+")
_DOTTED = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)+")


def _core() -> None:
    """Put the core's own classes on the allow-list (once, on first use, from :mod:`.core_types`)."""
    global _CORE_DONE
    if not _CORE_DONE:
        _CORE_DONE = True
        from . import core_types

        _declare(core_types)


_CORE_DONE = False


def class_key(obj: Any) -> str:
    """A class's (or function's) name in a file: its import path, ``module.QualName``."""
    return f"{obj.__module__}.{obj.__qualname__}"


def _builtin_names() -> frozenset[str]:
    from . import mapping

    return frozenset(t.__name__ for t in mapping.BUILTIN_TYPES)


def _names(owner: str, kind: str, names: Sequence[str]) -> tuple[str, ...]:
    if isinstance(names, str):
        raise TypeError(f"{owner}: {kind} must be a list of names, got the string {names!r}")
    names = tuple(names)
    for f in names:
        if not isinstance(f, str) or not f.isidentifier() or not f.isascii():
            raise ValueError(f"{owner}: {kind[:-1]} {f!r} is not an ASCII identifier")
    return names


def _check_same_class(table: dict[str, Any], key: str, cls: type, what: str) -> None:
    old = table.get(key)
    if old is not None and old.cls is not cls and (old.cls.__module__, old.cls.__qualname__) != (
            cls.__module__, cls.__qualname__):
        raise ValueError(f"{what}: another class is registered as {key}")


def register_component(cls: type[Component], fields: Sequence[str] = ()) -> type[Component]:
    """Save and load ``cls`` components by their ``fields`` (see the module docstring); returns ``cls``.

    Registering the same class (or a reloaded class of the same module and name) again replaces its fields;
    a built-in component, a class the loader could not rebuild (its constructor needs arguments that are not
    its saved fields) or a field name that is not an identifier raises ValueError/TypeError naming it.
    """
    if not (isinstance(cls, type) and issubclass(cls, Component)):
        raise TypeError(f"register_component: {cls!r} is not a Component subclass")
    name = cls.__name__
    if name in _builtin_names() and cls.__module__.startswith("gandalf_core."):
        raise ValueError(f"register_component: {name} is a built-in component and is saved already")
    fields = _names(f"register_component({name})", "fields", fields)
    signature = inspect.signature(cls)
    params = signature.parameters
    constructor_fields = tuple(f for f in fields if f in params and params[f].kind in (
        inspect.Parameter.POSITIONAL_OR_KEYWORD, inspect.Parameter.KEYWORD_ONLY))
    try:
        signature.bind()
        default_constructible = True
    except TypeError:
        try:
            signature.bind(**{f: None for f in constructor_fields})
        except TypeError:
            raise TypeError(f"register_component({name}): the loader needs {name}() to work without arguments, "
                            f"or {name}(**fields) with the saved fields that are its parameters "
                            f"{list(constructor_fields)}") from None
        default_constructible = False
    _check_same_class(_COMPONENTS, class_key(cls), cls, "register_component")
    _COMPONENTS[class_key(cls)] = Registration(cls, fields, default_constructible, constructor_fields)
    return cls


def unregister_component(cls: type[Component]) -> None:
    """Forget ``cls`` (nothing happens when it is not registered)."""
    reg = _COMPONENTS.get(class_key(cls))
    if reg is not None and reg.cls is cls:
        del _COMPONENTS[class_key(cls)]


def register_system(cls: type[System], settings: Sequence[str] = (), *, unsaveable: str | None = None) -> type[System]:
    """Allow ``cls`` in saved scenes: a scene's ``cls`` system is saved by its import path and rebuilt on load as
    ``cls(**{s: saved value for s in settings})``, each setting read from the system's attribute of that name
    (a simple value or a function registered with :func:`register_function`). Returns ``cls``.

    ``unsaveable="why"`` registers a system whose state a file cannot hold (a GPU buffer a compute shader
    writes, a backend object): saving a scene that has one raises USDSceneError with that reason.
    """
    if not (isinstance(cls, type) and issubclass(cls, System)):
        raise TypeError(f"register_system: {cls!r} is not a System subclass")
    name = cls.__name__
    settings = _names(f"register_system({name})", "settings", settings)
    if unsaveable is None:
        try:
            inspect.signature(cls).bind(**{s: None for s in settings})
        except TypeError:
            raise TypeError(f"register_system({name}): the loader builds {name}(**settings) with the settings "
                            f"{list(settings)}, and {name}'s constructor does not take exactly those") from None
    elif not isinstance(unsaveable, str) or not unsaveable:
        raise TypeError(f"register_system({name}): unsaveable must be a sentence saying why")
    _check_same_class(_SYSTEMS, class_key(cls), cls, "register_system")
    _SYSTEMS[class_key(cls)] = SystemRegistration(cls, settings, unsaveable)
    return cls


def unregister_system(cls: type[System]) -> None:
    """Forget ``cls`` (nothing happens when it is not registered)."""
    reg = _SYSTEMS.get(class_key(cls))
    if reg is not None and reg.cls is cls:
        del _SYSTEMS[class_key(cls)]


def register_function(fn: Callable[..., Any]) -> Callable[..., Any]:
    """Allow ``fn`` (a module-level function) as a system setting, saved by its import path; returns ``fn``."""
    if not inspect.isfunction(fn) or "<" in fn.__qualname__:
        raise TypeError(f"register_function: {fn!r} is not a module-level function")
    _FUNCTIONS[class_key(fn)] = fn
    return fn


def unregister_function(fn: Callable[..., Any]) -> None:
    """Forget ``fn`` (nothing happens when it is not registered)."""
    if _FUNCTIONS.get(class_key(fn)) is fn:
        del _FUNCTIONS[class_key(fn)]


def allow_package(package: str) -> None:
    """Let the loader import modules of ``package`` (a top-level package name) to find registered classes."""
    if not isinstance(package, str) or not package.isidentifier():
        raise ValueError(f"allow_package: {package!r} is not a top-level package name")
    _PACKAGES.add(package)


_DECLARED: set[str] = set()


# --8<-- [start:declare]
def _declarations(module: str) -> None:
    """Register what the ``saved.py`` of ``module``'s top-level package declares (once per package)."""
    package = module.split(".")[0]
    if package in _DECLARED or not _allowed_module(package):
        return
    _DECLARED.add(package)
    try:
        spec = importlib.util.find_spec(f"{package}.saved")
    except (ImportError, ValueError):
        spec = None
    if spec is None:
        return
    _declare(importlib.import_module(f"{package}.saved"))


def _declare(saved: Any) -> None:
    """Register a declaration module's ``COMPONENTS``, ``SYSTEMS``, ``UNSAVEABLE`` and ``FUNCTIONS``."""
    for cls, fields in getattr(saved, "COMPONENTS", {}).items():
        register_component(cls, fields)
    for cls, settings in getattr(saved, "SYSTEMS", {}).items():
        register_system(cls, settings)
    for cls, why in getattr(saved, "UNSAVEABLE", {}).items():
        register_system(cls, unsaveable=why)
    for fn in getattr(saved, "FUNCTIONS", ()):
        register_function(fn)
# --8<-- [end:declare]


def _declarations_of_imported_packages() -> None:
    for module in [m for m in sys.modules if "." not in m]:
        if _STEP_PACKAGE.fullmatch(module) or module in _PACKAGES:
            _declarations(module)


def registration_for(cls: type) -> Registration | None:
    """The registration of exactly this component class, or None."""
    _core()
    _declarations(cls.__module__)
    reg = _COMPONENTS.get(class_key(cls))
    return reg if reg is not None and reg.cls is cls else None


def system_registration_for(cls: type) -> SystemRegistration | None:
    """The registration of exactly this system class, or None."""
    _core()
    _declarations(cls.__module__)
    reg = _SYSTEMS.get(class_key(cls))
    return reg if reg is not None and reg.cls is cls else None


def function_key(fn: Any) -> str | None:
    """The saved name of a registered function, or None."""
    key = class_key(fn) if inspect.isfunction(fn) else None
    if key is not None:
        _declarations(fn.__module__)
    return key if key is not None and _FUNCTIONS.get(key) is fn else None


# --8<-- [start:allowed]
def _allowed_module(module: str) -> bool:
    parts = module.split(".")
    if any(p.startswith("_") for p in parts):  # no __main__ (it would run a program), no private modules
        return False
    return parts[0] in _PACKAGES or bool(_STEP_PACKAGE.fullmatch(parts[0]))
# --8<-- [end:allowed]


def _lookup(table: dict[str, Any], key: str, kind: str) -> tuple[Any, str]:
    """``table[key]``, importing its module first when that is allowed; (entry or None, why not)."""
    _core()
    if key in table:
        return table[key], ""
    if key.isidentifier():  # a file from before names were import paths: the bare class name
        _declarations_of_imported_packages()
        found = [v for k, v in table.items() if k.rsplit(".", 1)[-1] == key]
        if len(found) == 1:
            return found[0], ""
        why = "several registered classes have that name" if found else "nothing registered has that name"
        return None, why
    if not _DOTTED.fullmatch(key):
        return None, "it is not an import path (module.Name)"
    module = key.rsplit(".", 1)[0]
    if not _allowed_module(module):
        if _allowed_module(module.split(".")[0]):
            return None, f"the module {module} is private or a program (__main__): it is never imported"
        return None, (f"its package '{module.split('.')[0]}' is not on the allow-list (gandalf_core, the course's "
                      f"stepNN_* folders, and packages added with step07_advanced.usd.allow_package)")
    try:
        spec = importlib.util.find_spec(module)
    except (ImportError, ValueError):
        spec = None
    if spec is None:
        return None, f"there is no module {module}"
    try:
        importlib.import_module(module)
        _declarations(module)
    except Exception as exc:  # noqa: BLE001 - a module that fails to import is reported, not raised
        return None, f"importing {module} failed: {type(exc).__name__}: {exc}"
    if key in table:
        return table[key], ""
    return None, (f"neither {module.split('.')[0]}.saved declares it nor a program registered it "
                  f"(register_{kind} is the allow-list)")


def resolve_component(key: str) -> tuple[Registration | None, str]:
    """The registration a file's component name stands for, or (None, why not)."""
    return _lookup(_COMPONENTS, key, "component")


def resolve_system(key: str) -> tuple[SystemRegistration | None, str]:
    """The registration a file's system name stands for, or (None, why not)."""
    return _lookup(_SYSTEMS, key, "system")


def resolve_function(key: str) -> tuple[Callable[..., Any] | None, str]:
    """The registered function a file's setting names, or (None, why not)."""
    return _lookup(_FUNCTIONS, key, "function")


def registered_components() -> list[Registration]:
    """Every registered component class (for tools, e.g. an editor's *Add component* list): the core's, those
    registered, and those declared by every course step the program has imported."""
    _core()
    _declarations_of_imported_packages()
    return list(_COMPONENTS.values())
