"""The step's launcher: ``python -m step07_advanced.opengl --technique terrain`` runs one technique's variant.

Each technique is a sub-package with its own ``opengl.py`` / ``webgpu.py``; this only picks one and hands the
remaining options (``--student``, ``--headless``, ``--frames``, ``--out``, ...) to it
(:func:`gandalf_core.app.cli.launch_part`, which step 05's ``--concept`` launcher uses too).
"""

from __future__ import annotations

from gandalf_core.app.cli import available_parts, launch_part

from . import TECHNIQUES


def available() -> list[str]:
    """The techniques whose sub-package is present (all of :data:`TECHNIQUES` in a full checkout)."""
    return available_parts(__package__, TECHNIQUES)


def launch(backend: str, argv: list[str] | None = None) -> int:
    """Run ``--technique``'s ``backend`` variant with the other options."""
    return launch_part(__package__, backend, TECHNIQUES, "technique", argv)
