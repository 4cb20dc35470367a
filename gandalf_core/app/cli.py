"""The launchers: a step variant's app and command line, and your own program's.

A step's ``opengl.py`` and ``webgpu.py`` hold only what differs between the APIs:
``create_app = variant("opengl", __package__, build_scene, SHADERS)`` builds the step's shader table in that API
and its scene; ``run_variant(create_app)`` is the command line (``python -m step01_window.opengl --help``).
:func:`run_scene` runs a scene of your own in either API (``--backend``), with the core's ready materials.
"""

from __future__ import annotations

import argparse
import importlib
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from types import ModuleType
from typing import Any

from ..ecs import Scene
from ..render.base import check_backend
from ..resources.layout import BlockLayout
from .application import Application
from .extensions import extension


def load_impl(step_package: str, student: bool = False) -> ModuleType:
    """A step's ``exercises`` (the student's code) or ``solutions`` (the reference) package."""
    return importlib.import_module(f"{step_package}.{'exercises' if student else 'solutions'}")


def run_variant(create_app: Callable[..., Application], argv: list[str] | None = None, *, description: str = "") -> int:
    """Parse the common options, then run the app in a window or headless."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--headless", action="store_true", help="render offscreen even when a display exists")
    parser.add_argument("--frames", type=int, default=None, help="stop after this many frames")
    parser.add_argument("--out", default=None, help="save the last frame to this PNG file")
    parser.add_argument("--student", action="store_true", help="run your exercises/ instead of solutions/")
    parser.add_argument("--size", default="640x480", help="WIDTHxHEIGHT (default 640x480)")
    parser.add_argument("--editor", action="store_true", help="turn on the editor (hierarchy, inspector, USD)")
    parser.add_argument("--save", default=None, metavar="FILE",
                        help="after the last frame, save the scene to this USD file (.usda or .usdc)")
    args = parser.parse_args(argv)
    width, height = (int(x) for x in args.size.lower().split("x"))
    app = create_app(headless=True if args.headless else None, student=args.student, width=width, height=height)
    if args.editor:
        extension("editor")(app)
    frames = args.frames if args.frames is not None else (60 if app.headless else None)
    with app:
        app.run(frames=frames)
        if args.out:
            print(f"saved {app.save_png(args.out)}")
        if args.save:
            print(f"saved {extension('save_scene')(app.scene, args.save)}")
    return 0


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


def variant(backend: str, package: str, build: Callable[[ModuleType], Scene | Iterable[Scene]],
            shaders: ShaderTable = (), *, include_impl: bool = False) -> Callable[..., Application]:
    """A step variant's ``create_app``: everything but the API is the same for both variants of a step.

    ``build(impl)`` returns the step's scene (or scenes) for its ``solutions`` or, with ``student``, its
    ``exercises`` package; ``shaders`` is the step's shader table (files in the step's ``shaders/`` folder);
    ``include_impl`` lets the shaders ``#include`` files of the implementation's folder (shader exercises).
    """
    backend = check_backend(backend)
    folder = Path(importlib.import_module(package).__file__).resolve().parent / "shaders"
    title = f"{package.split('_')[0]} · {'OpenGL' if backend == 'opengl' else 'WebGPU'}"

    def create_app(headless: bool | None = None, student: bool = False, width: int = 640,
                   height: int = 480) -> Application:
        impl = load_impl(package, student)
        app = Application(backend, width, height, title=title, headless=headless, fixed_dt=1 / 60)
        build_shaders(app, shaders, folder, [Path(impl.__file__).resolve().parent] if include_impl else [])
        scenes = build(impl)
        for scene in [scenes] if isinstance(scenes, Scene) else scenes:
            app.add_scene(scene)
        return app

    create_app.__doc__ = f"The {package} app in {title.split(' · ')[1]} (``headless``, ``student``, size)."
    return create_app


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
    import sys

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
