"""The step's launcher: ``python -m step07_advanced.opengl --technique terrain`` runs one technique's variant.

Each technique is a sub-package with its own ``opengl.py`` / ``webgpu.py``; this only picks one and hands the
remaining options (``--student``, ``--headless``, ``--frames``, ``--out``, ...) to it.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from . import TECHNIQUES


def available() -> list[str]:
    """The techniques whose sub-package is present (all of :data:`TECHNIQUES` in a full checkout)."""
    found = []
    for name in TECHNIQUES:
        try:
            importlib.import_module(f"{__package__}.{name}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{__package__}.{name}":
                raise
            continue
        found.append(name)
    return found


def launch(backend: str, argv: list[str] | None = None) -> int:
    """Run ``--technique``'s ``backend`` variant with the other options."""
    names = available()
    parser = argparse.ArgumentParser(
        prog=f"python -m {__package__}.{backend}", add_help=False,
        description=f"Step 07 in {backend}: one technique at a time ({', '.join(names)}).",
    )
    parser.add_argument("--technique", default=names[0], choices=names, help=f"which technique (default {names[0]})")
    parser.add_argument("-h", "--help", action="store_true", help="show this help and the technique's options")
    args, rest = parser.parse_known_args(sys.argv[1:] if argv is None else argv)
    variant = importlib.import_module(f"{__package__}.{args.technique}.{backend}")
    if args.help:
        parser.print_help()
        print()
        rest = ["--help"]
    return variant.main(rest)
