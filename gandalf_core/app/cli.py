"""The launchers: every step, concept and technique's app and command line, and your own program's.

A variant file (``opengl.py`` / ``webgpu.py``) has one shape: a docstring that teaches what is API-specific, the
API's backend, and one line handing the part's description and the backend to :func:`launcher`::

    create_app, main = launcher(PART, "opengl", __doc__)        # nothing but the API differs
    create_app, main = launcher(PART, "opengl", __doc__, shaders=register_shaders)   # the API's own programs
    create_app, main = launcher(PART, OpenGL(), __doc__)        # a Backend subclass: the API's own stages

``PART`` (a :class:`Part`, in the part's ``scene.py``) is what both variants share: the package, its scene and
its shader table. ``create_app(headless, student, width, height, **options)`` builds the app;
``main(argv)`` is the command line (``python -m step01_window.opengl --help``).
:func:`run_scene` runs a scene of your own in either API (``--backend``), with the core's ready materials.
"""

from __future__ import annotations

import argparse
import importlib
import importlib.util
import sys
import traceback
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

from ..ecs import Scene
from ..render.base import check_backend
from ..render.capabilities import FLOOR, CapabilityError, Needs
from ..resources.layout import BlockLayout
from .application import Application
from .extensions import extension


def has_solutions(step_package: str) -> bool:
    """Whether ``step_package`` holds its reference ``solutions`` (a student's release does not)."""
    try:
        return importlib.util.find_spec(f"{step_package}.solutions") is not None
    except ModuleNotFoundError:  # not a step package
        return False


def load_impl(step_package: str, student: bool = False) -> ModuleType:
    """A step's ``exercises`` (the student's code) or ``solutions`` (the reference) package.

    Where the step has no ``solutions`` (a student's release), the reference is the student's ``exercises``.
    """
    if not student and has_solutions(step_package):
        return importlib.import_module(f"{step_package}.solutions")
    return importlib.import_module(f"{step_package}.exercises")


def stop_on_stub(prog: str, run: Callable[[], int]) -> int:
    """``run()``; where it stops on an untouched exercise stub, print one sentence naming the exercise and its file
    (no traceback) and return 1: a command line's way to say which exercise to write first."""
    try:
        return run()
    except NotImplementedError as error:
        sentence = unfinished_exercise(error)
        if sentence is None:
            raise
        print(f"{prog}: {sentence}", file=sys.stderr)
        return 1


def unfinished_exercise(error: BaseException) -> str | None:
    """One sentence naming the exercise and its file when ``error`` is an untouched stub's ``NotImplementedError``
    (raised in a step's ``exercises/`` folder); None for any other error."""
    if not isinstance(error, NotImplementedError):
        return None
    stub = None
    for frame, _ in traceback.walk_tb(error.__traceback__):
        path = Path(frame.f_code.co_filename)
        if "exercises" in path.parts[:-1]:
            stub = (path, frame.f_code.co_name)
    if stub is None:
        return None
    path, function = stub
    parts = path.parts
    step = next((i for i in range(parts.index("exercises") - 1, -1, -1) if parts[i].startswith("step")), None)
    shown = "/".join(parts[step:]) if step is not None else str(path)
    name = str(error).removeprefix("exercise:").strip() or function
    tests = f"tests/{parts[step]}" if step is not None else "tests"
    return (f"the exercise {name} is still a stub: write it in {shown} (its docstring says what it must do), "
            f"then run this again; 'python -m gandalf_tools.grading {tests}' grades it.")


#: A launcher's exit status when this machine lacks what the part needs (it printed what to run instead).
CAPABILITY_EXIT = 3


def run_variant(create_app: Callable[..., Application], argv: list[str] | None = None, *, description: str = "",
                prog: str | None = None) -> int:
    """Parse the common options, then run the app in a window or headless (``prog``: the help's ``python -m ...``)."""
    parser = argparse.ArgumentParser(prog=prog, description=plain(description),
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--headless", action="store_true", help="render offscreen even when a display exists")
    parser.add_argument("--frames", type=int, default=None, help="stop after this many frames")
    parser.add_argument("--out", default=None, help="save the last frame to this PNG file")
    parser.add_argument("--student", action="store_true",
                        help="run your exercises/ instead of solutions/ (the default where there are no solutions/)")
    parser.add_argument("--size", default="640x480", help="WIDTHxHEIGHT (default 640x480)")
    parser.add_argument("--editor", action="store_true", help="turn on the editor (hierarchy, inspector, USD)")
    parser.add_argument("--save", default=None, metavar="FILE",
                        help="after the last frame, save the scene to this USD file (.usda or .usdc)")
    args = parser.parse_args(argv)
    width, height = (int(x) for x in args.size.lower().split("x"))
    try:
        app = create_app(headless=True if args.headless else None, student=args.student, width=width, height=height)
    except CapabilityError as exc:  # one sentence, no traceback: what is missing and what to run instead
        print(exc, file=sys.stderr)
        return CAPABILITY_EXIT
    if args.editor:
        extension("editor")(app)
    frames = args.frames if args.frames is not None else (60 if app.headless else None)
    with app:
        if app.headless and not args.out and not args.save:
            why = "headless" if args.headless else "no display"
            print(f"{why}: rendering {frames} frames offscreen; add --out FILE.png to keep the last one")
        app.run(frames=frames)
        if args.out:
            print(f"saved {app.save_png(args.out)}")
        if args.save:
            print(f"saved {extension('save_scene')(app.scene, args.save)}")
    return 0


def plain(docstring: str) -> str:
    """A module docstring as a command's help reads it: the reStructuredText quotes (````x````, ``:func:`x```) as
    plain ``'x'``."""
    import re

    text = re.sub(r":[a-z]+:`~?([^`]+)`", r"'\1'", docstring or "")
    return re.sub(r"``([^`]+)``", r"'\1'", text).strip()


def run_scene(build_scene: Callable[[], Scene], argv: list[str] | None = None, *, description: str = "",
              title: str = "gandalf") -> int:
    """Run the scene ``build_scene()`` returns in either API: your own program's whole command line.

    Options: ``--backend opengl|webgpu``, ``--headless``, ``--frames N`` (headless: 60 by default), ``--out
    PNG`` (the last frame), ``--size WxH``. The scene may use only the core's ready materials
    (``gandalf.unlit``, ``gandalf.blinn_phong``): no shader is built here.
    """
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--backend", default="opengl", choices=["opengl", "webgpu"], help="the API (default opengl)")
    parser.add_argument("--headless", action="store_true", help="render offscreen even when a display exists")
    parser.add_argument("--frames", type=int, default=None, help="stop after this many frames (headless: 60)")
    parser.add_argument("--out", default=None, help="save the last frame to this PNG file")
    parser.add_argument("--size", default="640x480", help="WIDTHxHEIGHT (default 640x480)")
    args = parser.parse_args(argv)
    width, height = (int(x) for x in args.size.lower().split("x"))
    with Application(args.backend, width, height, title=title, headless=True if args.headless else None) as app:
        app.add_scene(build_scene())
        app.run(frames=args.frames if args.frames is not None else (60 if app.headless else None))
        if args.out:
            print(f"saved {app.save_png(args.out)}")
    return 0


#: A step's shader table: shader names (files ``<name>.vert``/``.frag`` and ``<name>.wgsl``), or a mapping
#: name -> (GLSL vertex file, GLSL fragment file[, WGSL file][, Material block]) with the WGSL file ``<name>.wgsl``
#: when left out; the Material block (fields or a BlockLayout, see ``shaders.build(material=...)``) is the colour
#: alone when left out. An entry may also be the Material block alone (the files by the name).
ShaderTable = Mapping[str, Any] | Iterable[str]


def shader_files(table: ShaderTable) -> dict[str, tuple[str, str, str, Any]]:
    """``table`` as name -> (GLSL vertex file, GLSL fragment file, WGSL file, Material block or None)."""
    items = table.items() if isinstance(table, Mapping) else ((name, ()) for name in table)
    files = {}
    for name, entry in items:
        entry = (entry,) if isinstance(entry, (str, BlockLayout)) else tuple(entry)
        material = None
        if entry and (isinstance(entry[-1], BlockLayout) or isinstance(entry[-1], list)):
            entry, material = entry[:-1], entry[-1]
        if len(entry) == 0:
            files[name] = (f"{name}.vert", f"{name}.frag", f"{name}.wgsl", material)
        elif len(entry) in (2, 3):
            files[name] = (entry[0], entry[1], entry[2] if len(entry) == 3 else f"{name}.wgsl", material)
        else:
            raise ValueError(f"shader table: {name!r}: expected (vertex, fragment[, wgsl][, material]) file names, "
                             f"got {entry!r}")
    return files


def build_shaders(app: Application, table: ShaderTable, folder: str | Path,
                  include_dirs: Sequence[str | Path] = ()) -> None:
    """Build every shader of ``table`` from ``folder`` in ``app``'s renderer, in the app's API."""
    folder = Path(folder)
    for name, (vert, frag, wgsl, material) in shader_files(table).items():
        if app.backend == "opengl":
            app.renderer.shaders.build(name, folder / vert, folder / frag, include_dirs=include_dirs,
                                       material=material)
        else:
            app.renderer.shaders.build(name, folder / wgsl, include_dirs=include_dirs, material=material)


@dataclass(frozen=True)
class Part:
    """A runnable step, concept or technique: what its OpenGL and WebGPU variants share.

    ``package`` is the part's package (its ``__package__``); the step (its first name) holds ``exercises/``,
    ``solutions/`` and the ``shaders/`` folder of ``shaders``, the shader table the launcher builds in either API
    (``include_impl``: the shaders ``#include`` files of the implementation's folder). ``build_scene(impl,
    **options)`` returns the scene (or scenes) where the API changes nothing else. A step of several runnable
    parts (step 05's concepts, step 07's techniques) names them in ``parts``, picked with ``--<option>``
    (``default``, else the first); without ``build_scene`` its ``create_app`` is the default part's. ``needs``
    (:class:`~gandalf_core.render.capabilities.Needs`) is what the part needs beyond OpenGL 3.3 core and WebGPU's
    default limits; the app checks it before building anything and the launcher says what to run instead.
    """

    package: str
    build_scene: Callable[..., Scene | Iterable[Scene]] | None = None
    shaders: ShaderTable = ()
    include_impl: bool = False
    parts: Sequence[str] = ()
    option: str = "concept"
    default: str | None = None
    needs: Needs = FLOOR

    @property
    def step(self) -> str:
        """The step package: ``exercises``, ``solutions`` and ``shaders/``."""
        return self.package.split(".")[0]

    @property
    def title(self) -> str:
        """``step07 · terrain`` for ``step07_advanced.terrain``."""
        return " · ".join([self.step.split("_")[0], *self.package.split(".")[1:]])


class Backend:
    """What one API adds to a part where more than its name differs: subclass it in the variant file.

    ``api`` is ``"opengl"`` or ``"webgpu"``; :meth:`scene` builds what only this API needs (its shaders, stages,
    kernels, buffers) and returns the scene. Where nothing but the API differs, hand :func:`launcher` the API's
    name instead.
    """

    api: str = ""

    def scene(self, app: Application, impl: ModuleType, **options: Any) -> Scene | Iterable[Scene]:
        """The scene(s) to run in ``app``; ``impl`` is the exercises or solutions package, ``options`` the keyword
        options given to ``create_app``."""
        raise NotImplementedError(f"{type(self).__name__}.scene: build the API's part and return the scene")


def launcher(part: Part, backend: str | Backend, description: str = "", *,
             shaders: Callable[[Application, ModuleType], None] | None = None,
             ) -> tuple[Callable[..., Application], Callable[..., int]]:
    """A variant's ``create_app`` and ``main``: ``create_app, main = launcher(PART, "opengl", __doc__)``.

    ``create_app(headless=None, student=False, width=640, height=480, *, impl=None, **options)`` opens the app in
    ``backend``'s API, builds the part's shader table, then the scene: ``backend.scene(app, impl, **options)``, or
    ``part.build_scene(impl, **options)`` where ``backend`` is just the API's name (after ``shaders(app, impl)``,
    where the part's own programs are built in this API only). ``impl`` (a package like
    ``exercises``) overrides ``student``. ``main(argv)`` runs it from the command line (``description``: its help),
    or, for a step of several parts, the part ``--<option>`` names.
    """
    api = check_backend(backend if isinstance(backend, str) else backend.api)
    title = f"{part.title} · {'OpenGL' if api == 'opengl' else 'WebGPU'}"

    def create_app(headless: bool | None = None, student: bool = False, width: int = 640, height: int = 480, *,
                   impl: ModuleType | None = None, **options: Any) -> Application:
        if part.build_scene is None and part.parts:
            default = available_parts(part.package, [part.default or part.parts[0]]) or part.parts[:1]
            return importlib.import_module(f"{part.package}.{default[0]}.{api}").create_app(
                headless, student, width, height, impl=impl, **options)
        impl = impl if impl is not None else load_impl(part.step, student)
        try:
            return _build(impl, headless, width, height, options)
        except CapabilityError as exc:  # named after the part, with the other API's variant to run instead
            raise exc.naming(f"`python -m {part.package}.{api}`", f"python -m {part.package}.{_other(api)}") from None

    def _build(impl: ModuleType, headless: bool | None, width: int, height: int, options: dict[str, Any]
               ) -> Application:
        app = Application(api, width, height, title=title, headless=headless, fixed_dt=1 / 60, needs=part.needs)
        try:
            folder = Path(importlib.import_module(part.step).__file__).resolve().parent / "shaders"
            build_shaders(app, part.shaders, folder,
                          [Path(impl.__file__).resolve().parent] if part.include_impl else [])
            if shaders is not None:
                shaders(app, impl)
            scenes = (part.build_scene(impl, **options) if isinstance(backend, str)
                      else backend.scene(app, impl, **options))
            for scene in [scenes] if isinstance(scenes, Scene) else scenes:
                app.add_scene(scene)
        except BaseException:
            app.close()  # a shader or scene that fails to build leaves no window or GPU context behind
            raise
        return app

    def main(argv: list[str] | None = None) -> int:
        if part.parts:
            return launch_part(part.package, api, part.parts, part.option, argv, default=part.default)
        prog = f"python -m {part.package}.{api}"
        return stop_on_stub(prog, lambda: run_variant(create_app, argv, description=description, prog=prog))

    create_app.__doc__ = f"The {part.package} app in {title.rsplit(' · ', 1)[1]} (``headless``, ``student``, size)."
    main.__doc__ = f"Run the {part.package} app in {title.rsplit(' · ', 1)[1]} from the command line (``--help``)."
    return create_app, main


def _other(api: str) -> str:
    return "webgpu" if api == "opengl" else "opengl"


def available_parts(step_package: str, names: Sequence[str]) -> list[str]:
    """The sub-packages of ``names`` present in ``step_package`` (all of them in a full checkout)."""
    found = []
    for name in names:
        try:
            importlib.import_module(f"{step_package}.{name}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{step_package}.{name}":
                raise
            continue
        found.append(name)
    return found


def launch_part(step_package: str, backend: str, names: Sequence[str], option: str, argv: list[str] | None = None,
                *, default: str | None = None) -> int:
    """A step of several runnable sub-packages (step 05's concepts, step 07's techniques): run one of them.

    ``python -m step07_advanced.opengl --technique terrain`` picks the part with ``--<option>`` (``default``, or
    the first of ``names``) and hands the other options (``--student``, ``--headless``, ...) to its variant's
    ``main(argv)``; ``--help`` prints this and the part's options.
    """
    names = available_parts(step_package, names)
    default = default if default in names else names[0]
    parser = argparse.ArgumentParser(
        prog=f"python -m {step_package}.{backend}", add_help=False,
        description=f"{step_package} in {backend}: one {option} at a time ({', '.join(names)}).",
    )
    parser.add_argument(f"--{option}", default=default, choices=names, help=f"which {option} (default {default})")
    parser.add_argument("-h", "--help", action="store_true", help=f"show this help and the {option}'s options")
    args, rest = parser.parse_known_args(sys.argv[1:] if argv is None else argv)
    variant = importlib.import_module(f"{step_package}.{getattr(args, option)}.{backend}")
    if args.help:
        parser.print_help()
        print()
        rest = ["--help"]
    return variant.main(rest)
