"""A student's shaders are compiled and run in a process of their own, never in the grader's.

A test's GPU helper (a function of the tests that builds a program or an app from the student's shader files, runs
it and reads back numbers or pixels) carries :func:`on_shader_box`. When one of its arguments is a sandboxed
student's package (the ``impl`` stand-in of :mod:`.remote`) or a folder inside one, the call runs in the *shader
process*: a :class:`~.sandbox.Sandbox` of its own, under the same isolation and limits as the student's Python, that
holds a copy of the student's folders, the engine, the step packages (no ``solutions/``), the grader's tools and the
tests, read-only. It never imports the student's Python: the helper gets a stand-in of the package that has only its
folder's ``__file__`` (the shader files are read from there), so the only student input in that process is shader
text, which the driver compiles. Its reply is plain data (arrays, numbers: :mod:`.wire`), and the test compares it
here, where the grade is made.

Where Mesa's software drivers are installed the shader process draws with them, whatever GPU the machine has
(:data:`MESA_EGL_VENDOR`): the grades are proven on them, and they bound what a shader costs.

Each call has a wall-clock budget (:data:`SHADER_BUDGET`, kept by this process): a shader that never ends, or that
takes the driver down, fails that call with a sentence saying so; its process is ended, the next call starts a fresh
one, and the same call (the helper and its text arguments: the API, the include, the expression) fails at once
afterwards instead of costing the budget again. Where no student's package is involved (the reference solutions,
the mutation check's in-process mutants) the helper runs here as before.
"""

from __future__ import annotations

import functools
import os
import sys
import tempfile
import threading
import types
from collections.abc import Callable
from pathlib import Path
from typing import Any

from . import remote, sandbox

#: Seconds one shader helper call may take in the shader process (the slowest graded one takes under 1 s on a
#: 2-core machine with llvmpipe/lavapipe; the first call also starts the process and its GPU devices).
SHADER_BUDGET = 20.0
#: Address space for the shader process: llvmpipe and lavapipe reserve far more than they use.
SHADER_MEMORY = 8 * 2**30
#: Mesa's software drivers. Where they are installed the shader process draws with them (llvmpipe through EGL,
#: lavapipe through Vulkan), whatever GPU the machine has: they are the implementations the grades are proven on in
#: CI, and they bound what a shader costs (a loop's iterations are capped). A GPU without a watchdog does not: on an
#: NVIDIA H200 an endless-loop shader, killed when its budget ran out, left the GPU so that the reference's own
#: shaders stalled and read back zeros in every later process for as long as it was watched
#: (``benchmarks/results/h200-2026-12-03b/``).
MESA_EGL_VENDOR = Path("/usr/share/glvnd/egl_vendor.d/50_mesa.json")
MESA_VULKAN_ICDS = Path("/usr/share/vulkan/icd.d")
NO_SOFTWARE_DRIVERS = ("gandalf grade: Mesa's software drivers (llvmpipe, lavapipe) are not installed here, so the "
                       "students' shaders run on this machine's GPU, where a shader that never ends can stall it for "
                       "the rest of the run. To grade a class here, install them first: "
                       "apt-get install libegl-mesa0 libgl1-mesa-dri mesa-vulkan-drivers")
_boxes: list[sandbox.Sandbox] = []
#: (process generation, API) pairs warmed up: before the first call of an API in a fresh process, the process starts
#: that API's context or device (``warm_up`` of the tests' ``shader_harness``: a few seconds on a loaded machine) with
#: ``sandbox.STARTUP_BUDGET`` seconds, so that the student's shader gets its whole budget.
_warm: set[tuple[int, str]] = set()
_API_WORDS = ("glsl", "wgsl", "opengl", "webgpu")
_starting: list[threading.Thread] = []  # the thread plan() started, until it is joined
budget = [SHADER_BUDGET]  # the run's (``--grade-shader-budget``)


def on_shader_box(fn: Callable[..., Any]) -> Callable[..., Any]:
    """Route ``fn`` (a module-level function of a file under the course's ``tests/``) to the shader process when a
    student's sandboxed package, or a folder inside one, is among its arguments."""

    @functools.wraps(fn)
    def route(*args: Any, **kwargs: Any) -> Any:
        folders = remote.student_folders()
        if not folders or not _mentions((args, kwargs), folders):
            return fn(*args, **kwargs)
        return _call(fn, args, kwargs, folders)

    return route


def shader_cache() -> Path:
    """Where the shader processes' GPU driver keeps compiled programs across runs: a folder of the grader's in the
    temporary folder, seen only by shader processes (the student's Python never runs there; its process does not
    see this folder), so that the course's own programs and a student's repeated ones compile once."""
    uid = os.getuid() if hasattr(os, "getuid") else "user"
    return Path(tempfile.gettempdir()) / f"gandalf-shader-cache-{uid}"


def software_drivers() -> dict[str, str]:
    """The environment that points the shader process at Mesa's software drivers (see :data:`MESA_EGL_VENDOR`);
    empty where they are not both installed."""
    lavapipe = sorted(MESA_VULKAN_ICDS.glob("lvp_icd*.json"))
    if not MESA_EGL_VENDOR.is_file() or not lavapipe:
        return {}
    return {"__EGL_VENDOR_LIBRARY_FILENAMES": str(MESA_EGL_VENDOR), "LIBGL_ALWAYS_SOFTWARE": "1",
            "VK_DRIVER_FILES": str(lavapipe[0]), "VK_ICD_FILENAMES": str(lavapipe[0])}  # the loader's new and old name


def routes(*values: Any) -> bool:
    """Whether a helper called with ``values`` among its arguments runs in the shader process."""
    folders = remote.student_folders()
    return bool(folders) and _mentions(values, folders)


def stop() -> None:
    """End the shader process (the grading session is over)."""
    while _starting:
        _starting.pop().join()
    for box in _boxes:
        box.stop()
    _boxes.clear()
    _warm.clear()


def _folder_of(value: Any, folders: dict[Path, str]) -> tuple[str, Path] | None:
    if isinstance(value, remote.RemotePackage):
        folder = Path(value.__file__).resolve().parent
        return (folders[folder], folder) if folder in folders else None
    if isinstance(value, Path):
        path = value.resolve()
        for folder, step in folders.items():
            if path == folder or folder in path.parents:
                return step, folder
    return None


def _loose_shaders(value: Any) -> Path | None:
    """The folder of a stand-in package outside the course that holds shader files (a test's copy of the student's
    files with some of the reference's: it travels by value), else None."""
    if isinstance(value, (remote.RemotePackage, types.ModuleType)) or not isinstance(getattr(value, "__file__", None),
                                                                                       str):
        return None
    folder = Path(value.__file__).resolve().parent
    if sandbox.ROOT in folder.parents or not any(folder.glob("*.glsl")) and not any(folder.glob("*.wgsl")):
        return None
    return folder


def _mentions(value: Any, folders: dict[Path, str]) -> bool:
    if _folder_of(value, folders) is not None or _loose_shaders(value) is not None:
        return True
    if isinstance(value, (list, tuple)):
        return any(_mentions(v, folders) for v in value)
    if isinstance(value, dict):
        return any(_mentions(v, folders) for v in value.values())
    return False


def _encode(value: Any, folders: dict[Path, str]) -> Any:
    """``value`` with the student's package and paths in its folders named by step (the shader process has its own
    copy of each folder); other paths as they are."""
    found = _folder_of(value, folders)
    if isinstance(value, remote.RemotePackage) and found is not None:
        return {"gandalf_impl": found[0]}
    loose = _loose_shaders(value)
    if loose is not None:
        return {"gandalf_files": {p.name: p.read_text() for p in sorted(loose.iterdir())
                                  if p.suffix in (".glsl", ".wgsl") and p.is_file()}}
    if isinstance(value, Path):
        if found is not None:
            return {"gandalf_path": [found[0], str(value.resolve().relative_to(found[1]))]}
        return {"gandalf_path": [None, str(value)]}
    if isinstance(value, (list, tuple)):
        return type(value)(_encode(v, folders) for v in value)
    if isinstance(value, dict):
        return {k: _encode(v, folders) for k, v in value.items()}
    return value


def _label(fn: Callable[..., Any], args: tuple[Any, ...]) -> str:
    texts = [repr(a if len(a) <= 60 else a[:59] + "…") for a in args if isinstance(a, str)]
    return f"{fn.__name__}({', '.join([*texts, '…'])}) with your shaders"


def plan(folders: dict[Path, str], hide: tuple[str, ...], start: bool) -> None:
    """Lay out every student's folder the session may grade in the shader process at once (adding one later would
    start it again); with ``start``, start it now and its OpenGL context and WebGPU device in a thread of this
    process, so that they are ready when the first shader test comes (the tests before it go on meanwhile)."""
    if _boxes:
        return
    _box(folders, hide)
    if start:
        thread = threading.Thread(target=_warm_up_both, name="gandalf-shader-process", daemon=True)
        _starting.append(thread)
        thread.start()


def _warm_up_both() -> None:
    box = _boxes[0]
    for api in ("glsl", "wgsl"):
        try:
            _warm_up(box, api)
        except Exception:  # noqa: BLE001 - the first shader call starts it again and says what failed
            return


def _warm_up(box: sandbox.Sandbox, api: str) -> None:
    remote.Session(box, sandbox.STARTUP_BUDGET, None).call(  # type: ignore[arg-type]
        {"op": "helper", "file": str(sandbox.ROOT / "tests" / "shader_harness.py"), "function": "warm_up",
         "args": [api], "kwargs": {}}, f"starting {api} in the shader process", f"warm_up:{api}")
    _warm.add((box.generation, api))


def _box(folders: dict[Path, str], hide: tuple[str, ...] | None = None) -> sandbox.Sandbox:
    while _starting:  # a start begun by plan(): the box is its thread's until it is done
        _starting.pop().join()
    if not _boxes:
        step, folder = next((s, f) for f, s in folders.items())
        drivers = software_drivers()
        if not drivers and sys.platform.startswith("linux"):  # macOS and Windows reset a hung GPU themselves
            print(NO_SOFTWARE_DRIVERS, file=sys.stderr)
        _boxes.append(sandbox.Sandbox(step, folder, hide=remote.hidden_outputs() if hide is None else hide,
                                      memory=SHADER_MEMORY, shader_cache=shader_cache(), env=drivers,
                                      shown=(sandbox.ROOT / "tests", sandbox.ROOT / "gandalf_tools")))
    for folder, step in folders.items():
        _boxes[0].add(step, folder)
    return _boxes[0]


def _call(fn: Callable[..., Any], args: tuple[Any, ...], kwargs: dict[str, Any], folders: dict[Path, str]) -> Any:
    file = Path(fn.__code__.co_filename).resolve()
    tests = (sandbox.ROOT / "tests").resolve()
    if tests not in file.parents or "<locals>" in fn.__qualname__:
        raise TypeError(f"{fn.__qualname__}: a shader helper must be a module-level function of a file under {tests}")
    texts = [a for a in args if isinstance(a, str)]
    box = _box(folders)
    api = next((a for a in texts if a in _API_WORDS), "")
    key = f"{file.name}:{fn.__qualname__}:{texts}"
    if api and f"{None}:{key}" not in box.failed and (box.proc is None or (box.generation, api) not in _warm):
        _warm_up(box, api)
    message = {"op": "helper", "file": str(file), "function": fn.__qualname__,
               "args": _encode(list(args), folders), "kwargs": _encode(kwargs, folders)}
    copies = str(box.private / "pkgs") + "/" if box.private is not None else None
    try:
        return remote.Session(box, budget[0], None).call(  # type: ignore[arg-type]
            message, _label(fn, args), key, hang="a shader loop that never ends, or one too big to run?",
            crash=" (the shader compiler or the driver crashed on your shader?)")
    except Exception as exc:  # a compile error names the shader process's copy: name the student's file instead
        if copies and exc.args and isinstance(exc.args[0], str) and copies in exc.args[0]:
            exc.args = (exc.args[0].replace(copies, ""), *exc.args[1:])
        raise
