"""The sandboxed side: a server that imports the student's package and answers the grader's requests.

Run by :mod:`gandalf_tools.grading.sandbox` as a script copied into a private folder (``python -I child.py FD_IN
FD_OUT``), as an unprivileged user where the grader can drop to one. It reads requests from FD_IN and writes replies
to FD_OUT in the wire format (``gandalf_wire``, a copy of :mod:`gandalf_tools.grading.wire`); each names the
package (``<step>.exercises``) it is about:

* ``import``: import the package; reply with what its public names are (function, class, module, value);
* ``call``: call one of its functions with plain data; reply with the result (plain data, or an engine object by
  its fields) and the warnings it raised;
* ``new`` / ``hook``: make an instance of one of its classes (a system) and run one of its hooks on copies of the
  components the grader sends, replying with the components' new field values and the assets it registered.

A callable argument travels as ``{"$cb": n}``: calling it asks the grader to run its own function and waits for
the answer. Nothing here is trusted: the grader checks every reply.
"""

from __future__ import annotations

import builtins
import importlib
import importlib.util
import marshal
import os
import sys
import traceback
import types
import uuid
import warnings
from typing import Any

import gandalf_wire as wire  # the copy of wire.py beside this file

HOOKS = ("on_create_system", "on_create_entity", "on_remove_entity", "on_update_system", "on_update_entity",
         "on_destroy_system", "pack")
_MESSAGE_LIMIT = 2000


class Channel:
    def __init__(self, fd_in: int, fd_out: int) -> None:
        self.fd_in, self.fd_out = fd_in, fd_out

    def send(self, message: Any) -> None:
        try:
            frame = wire.pack(message, objects=_object_fields)
        except Exception as exc:  # noqa: BLE001 - a result that cannot travel is the student's error
            frame = wire.pack({"error": {"types": ["TypeError"], "message": f"returned a value that cannot be "
                                         f"graded: {_text(exc)}"}})
        wire.write_frame(self.fd_out, frame)

    def receive(self) -> Any:
        data, blobs = wire.read_frame(self.fd_in)
        return wire.decode_value(data, blobs, objects=_rebuild, callbacks=_callback)


_channel: Channel
_functions: dict[int, Any] = {}  # the course's functions rebuilt from recipes, by number


def _callback(index: Any) -> Any:
    """The grader's callable ``index`` (an argument such as an acceleration function): each call asks the grader;
    or a recipe: a function of the course's own code rebuilt here (see ``sandbox.recipe``)."""
    if isinstance(index, dict):  # a recipe: whole the first time, then by its number
        if "code" in index:
            _functions[int(index["id"])] = _rebuild_function(index)
        return _functions[int(index["id"])]

    def call(*args: Any) -> Any:
        _channel.send({"callback": index, "args": list(args)})
        reply = _channel.receive()
        if "error" in reply:
            raise RuntimeError(f"the grader's function failed: {reply['error']}")
        return reply["ok"]

    return call


def _rebuild_function(recipe: dict[str, Any]) -> Any:
    """A function of the course's own code that the grader sent (its code, globals and captured values)."""
    names = {k: importlib.import_module(v["module"]) if isinstance(v, dict) and set(v) == {"module"} else v
             for k, v in recipe["globals"].items()}
    code = marshal.loads(recipe["code"])
    cells = tuple(types.CellType(v) for v in recipe["cells"])
    defaults = tuple(recipe["defaults"]) if recipe["defaults"] is not None else None
    return types.FunctionType(code, {"__builtins__": builtins, **names}, recipe["name"], defaults, cells or None)


def _rebuild(name: str, fields: dict[str, Any]) -> Any:
    module, _, qualname = name.partition(":")
    cls: Any = importlib.import_module(module)
    for part in qualname.split("."):
        cls = getattr(cls, part)
    return wire.build_object(cls, fields)


def _object_fields(value: Any) -> tuple[str, dict[str, Any]]:
    if isinstance(value, type) or callable(value) and not hasattr(value, "__dict__"):
        raise wire.WireError(f"a {type(value).__name__}")
    return wire.type_name(type(value)), wire.fields_of(value)


def _text(value: Any) -> str:
    try:
        text = str(value)
    except Exception:  # noqa: BLE001
        text = f"<a {type(value).__name__}>"
    return text if len(text) <= _MESSAGE_LIMIT else text[: _MESSAGE_LIMIT - 1] + "…"


def _error(exc: BaseException) -> dict[str, Any]:
    frames = [f for f in traceback.extract_tb(exc.__traceback__) if os.path.abspath(f.filename).startswith(ROOT)]
    where = f"{os.path.relpath(frames[-1].filename, ROOT)}:{frames[-1].lineno}" if frames else ""
    return {"types": [c.__name__ for c in type(exc).__mro__ if c.__module__ == "builtins"],
            "name": type(exc).__name__, "message": _text(exc), "where": where}


class _Assets:
    """Records what a system registers in ``self.scene.assets`` (the grader registers it in the real scene)."""

    def __init__(self) -> None:
        self.added: list[tuple[str, str, Any]] = []
        self.meshes: dict[str, Any] = {}
        self.textures: dict[str, Any] = {}
        self.materials: dict[str, Any] = {}

    def _add(self, kind: str, store: dict[str, Any], name: str, data: Any) -> Any:
        store[name] = data
        self.added.append((kind, name, data))
        return data

    def mesh(self, name: str, data: Any) -> Any:
        return self._add("mesh", self.meshes, name, data)

    def texture(self, name: str, data: Any) -> Any:
        return self._add("texture", self.textures, name, data)

    def material(self, name: str, data: Any) -> Any:
        return self._add("material", self.materials, name, data)


def _no_student_python() -> None:
    """Put a stand-in of each graded folder in ``sys.modules`` as ``<step>.exercises``: its ``__file__`` (the shader
    files beside it are read) and no submodules, so that no import in this process runs the student's Python."""
    for step in sorted(os.listdir(PKGS)):
        name, init = f"{step}.exercises", os.path.join(PKGS, step, "exercises", "__init__.py")
        if name not in sys.modules and os.path.isfile(init):
            stand_in = types.ModuleType(name, "the student's folder: its shader files, never its Python")
            stand_in.__file__, stand_in.__path__ = init, []
            sys.modules[name] = stand_in


def _folders(value: Any) -> Any:
    """``value`` with each ``{"gandalf_impl": step}`` made the stand-in of the step's graded folder (its ``__file__``
    only: shader files are read from it, its Python is never imported here) and ``{"gandalf_path": p}`` a Path."""
    if isinstance(value, dict) and len(value) == 1 and "gandalf_impl" in value:
        return sys.modules.get(f"{value['gandalf_impl']}.exercises")
    if isinstance(value, dict) and len(value) == 1 and "gandalf_files" in value:  # shader files sent by value
        import tempfile

        folder = tempfile.mkdtemp(prefix="shaders-")
        for name, text in dict(value["gandalf_files"]).items():
            if os.path.basename(str(name)) == name and name.endswith((".glsl", ".wgsl")):
                with open(os.path.join(folder, name), "w") as f:
                    f.write(str(text))
        return types.SimpleNamespace(__name__="shaders", __file__=os.path.join(folder, "__init__.py"))
    if isinstance(value, dict) and len(value) == 1 and "gandalf_path" in value:
        import pathlib

        step, path = value["gandalf_path"]
        return pathlib.Path(PKGS, str(step), "exercises", str(path)) if step is not None else pathlib.Path(str(path))
    if isinstance(value, (list, tuple)):
        return type(value)(_folders(v) for v in value)
    if isinstance(value, dict):
        return {k: _folders(v) for k, v in value.items()}
    return value


class Server:
    def __init__(self) -> None:
        self.helpers: dict[str, types.ModuleType] = {}
        self.packages: dict[str, types.ModuleType] = {}
        self.instances: dict[int, Any] = {}
        self.mirrors: dict[int, dict[uuid.UUID, tuple[Any, ...]]] = {}
        self.originals: dict[str, Any] = {}

    def resolve(self, package: str, target: str) -> Any:
        value: Any = self.packages[package]
        for part in target.split(".") if target else ():
            value = getattr(value, part)
        return value

    def op_import(self, package: str) -> dict[str, Any]:
        module = self.packages[package] = importlib.import_module(package)
        folder = os.path.dirname(module.__file__ or "")
        modules = sorted(n[:-3] for n in os.listdir(folder) if n.endswith(".py") and n != "__init__.py")
        return {"names": {name: self.describe(package, name) for name in dir(module) if not name.startswith("_")},
                "modules": {m: {n: self.describe(package, f"{m}.{n}") for n in dir(self.resolve(package, m))
                                if not n.startswith("_")} for m in modules if hasattr(module, m)}}

    def describe(self, package: str, target: str) -> Any:
        value = self.resolve(package, target)
        if isinstance(value, types.ModuleType):
            return {"kind": "module"}
        if isinstance(value, type):
            return {"kind": "class", "bases": [wire.type_name(c) for c in value.__mro__]}
        if callable(value):
            return {"kind": "function"}
        try:
            wire.pack(value)
        except Exception:  # noqa: BLE001
            return {"kind": "other", "type": type(value).__name__}
        return {"kind": "value", "value": value}

    def op_call(self, package: str, target: str, args: list[Any], kwargs: dict[str, Any]) -> Any:
        return self.resolve(package, target)(*args, **kwargs)

    def op_patch(self, package: str, target: str, value: Any) -> None:
        """The grader replaces a function of the package by its own (a test grading a system on its own)."""
        module, _, name = target.rpartition(".")
        owner = self.resolve(package, module)
        target = f"{package}:{target}"
        if value is None:  # back to the student's own
            setattr(owner, name, self.originals.pop(target, getattr(owner, name)))
        else:
            self.originals.setdefault(target, getattr(owner, name))
            setattr(owner, name, value)

    def op_new(self, package: str, target: str, args: list[Any], kwargs: dict[str, Any]) -> Any:
        obj = self.resolve(package, target)(*args, **kwargs)
        index = len(self.instances) + 1
        self.instances[index] = obj
        self.mirrors[index] = {}
        types_ = [wire.type_name(t) for t in getattr(obj, "component_types", ())]
        return {"id": index, "component_types": types_, "name": _text(getattr(obj, "name", type(obj).__name__)),
                "updates_each_frame": bool(getattr(obj, "updates_each_frame", True)),
                "hooks": [h for h in HOOKS if _overrides(type(obj), h)]}

    def op_hook(self, package: str, id: int, hook: str, members: list[Any], args: list[Any], app: Any) -> Any:
        obj, mirror = self.instances[id], self.mirrors[id]
        live: dict[uuid.UUID, tuple[Any, ...]] = {}
        for entity, components in members:
            key = uuid.UUID(entity)
            old = mirror.get(key)
            same = old is not None and len(old) == len(components)
            if same and all(type(a) is type(b) for a, b in zip(old, components)):
                for mine, theirs in zip(old, components):
                    for name, value in wire.fields_of(theirs).items():
                        setattr(mine, name, value)
                live[key] = old
            else:
                live[key] = tuple(components)
        mirror.clear()
        mirror.update(live)
        assets = _Assets()
        app = types.SimpleNamespace(**app) if isinstance(app, dict) else None
        obj.scene = types.SimpleNamespace(app=app, assets=assets)
        obj._members = dict(live)
        obj._lists = None
        if hook in ("on_create_entity", "on_remove_entity"):
            key = uuid.UUID(args[0])
            result = getattr(obj, hook)(key, live.get(key, ()))
        elif hook == "pack":
            result = obj.pack([live[uuid.UUID(e)] for e, _ in members])
        else:
            result = getattr(obj, hook)(*args)
        if hook == "on_remove_entity":
            mirror.pop(uuid.UUID(args[0]), None)
        return {"members": [[str(k), list(v)] for k, v in live.items()], "assets": assets.added, "result": result}

    def op_helper(self, package: None, file: str, function: str, args: list[Any], kwargs: dict[str, Any]) -> Any:
        """A function of the course's tests (its module read from ``file``) that renders with the student's shaders,
        called with ``{"gandalf_impl": step}`` standing for the step's graded folder (its files, never imported)."""
        _no_student_python()
        module = self.helpers.get(file)
        if module is None:
            for folder in (os.path.dirname(os.path.dirname(file)), os.path.dirname(file)):  # tests/, its step's folder
                if folder not in sys.path:
                    sys.path.insert(0, folder)
            name = os.path.splitext(os.path.basename(file))[0]
            spec = importlib.util.spec_from_file_location(name, file)
            module = importlib.util.module_from_spec(spec)
            sys.modules[name] = module
            spec.loader.exec_module(module)
            self.helpers[file] = module
        fn = module
        for part in function.split("."):
            fn = getattr(fn, part)
        fn = getattr(fn, "__wrapped__", fn)  # the function itself, not the grader's router around it
        return fn(*[_folders(a) for a in args], **{k: _folders(v) for k, v in kwargs.items()})

    def handle(self, request: dict[str, Any]) -> Any:
        op = request.pop("op")
        if op not in ("import", "helper") and request.get("package") not in self.packages:
            self.op_import(request["package"])
        return getattr(self, f"op_{op}")(**request)


def _overrides(cls: type, hook: str) -> bool:
    defined = next((c for c in cls.__mro__ if hook in vars(c)), None)
    return defined is not None and not defined.__module__.startswith("gandalf_core")


ROOT = os.path.dirname(os.path.abspath(__file__))
PKGS = os.path.join(ROOT, "pkgs")


def main() -> None:
    global _channel
    fd_in, fd_out = int(sys.argv[1]), int(sys.argv[2])
    _channel = Channel(fd_in, fd_out)
    server = Server()
    while True:
        try:
            request = _channel.receive()
        except EOFError:
            os._exit(0)
        except Exception as exc:  # noqa: BLE001 - a request this side cannot rebuild: say so, keep serving
            _channel.send({"error": _error(exc), "warnings": []})
            continue
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                reply = {"ok": server.handle(request)}
            except BaseException as exc:  # noqa: BLE001 - SystemExit and KeyboardInterrupt fail the call too
                reply = {"error": _error(exc)}
        reply["warnings"] = [[[c.__name__ for c in w.category.__mro__ if c.__module__ == "builtins"],
                              _text(w.message)] for w in caught] if isinstance(caught, list) else []
        _channel.send(reply)


if __name__ == "__main__":
    main()
