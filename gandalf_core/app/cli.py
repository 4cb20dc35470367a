"""The command line shared by every step variant (``python -m step01_window.opengl --help``)."""

from __future__ import annotations

import argparse
import importlib
from collections.abc import Callable
from types import ModuleType

from ..ecs import Scene
from .application import Application


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
    args = parser.parse_args(argv)
    width, height = (int(x) for x in args.size.lower().split("x"))
    app = create_app(headless=True if args.headless else None, student=args.student, width=width, height=height)
    if args.editor:
        from ..editor import enable_editor

        enable_editor(app)
    frames = args.frames if args.frames is not None else (60 if app.headless else None)
    with app:
        app.run(frames=frames)
        if args.out:
            print(f"saved {app.save_png(args.out)}")
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
