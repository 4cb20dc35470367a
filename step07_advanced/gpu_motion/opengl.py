"""Step 07 GPU-driven motion, OpenGL variant: ``python -m step07_advanced.gpu_motion.opengl``.

The technique's compute pass (GLSL 4.30, ``shaders/motion_spin.comp``, :mod:`.motion_gl`) turns the instance
rows; the draws read their instance rows from the result.
"""

from __future__ import annotations

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
