"""The step's launcher: ``python -m step07_advanced.opengl --technique terrain`` runs one technique's variant.

Each technique is a sub-package with its own ``opengl.py`` / ``webgpu.py``; :data:`PART` (handed to
:func:`gandalf_core.app.cli.launcher`, as step 05's concepts are) picks one with ``--technique`` and hands the
remaining options (``--student``, ``--headless``, ``--frames``, ``--out``, ...) to it.
"""

from __future__ import annotations

from gandalf_core.app.cli import Part, available_parts, launcher

from . import TECHNIQUES

#: The step of seven techniques: ``--technique NAME`` (default: the first, the showcase).
PART = Part(__package__, parts=TECHNIQUES, option="technique")


def available() -> list[str]:
    """The techniques whose sub-package is present (all of :data:`TECHNIQUES` in a full checkout)."""
    return available_parts(__package__, TECHNIQUES)


def launch(backend: str, argv: list[str] | None = None) -> int:
    """Run ``--technique``'s ``backend`` variant with the other options."""
    return launcher(PART, backend)[1](argv)
