"""Step 07 GPU-driven motion, OpenGL variant: ``python -m step07_advanced.gpu_motion.opengl``.

The engine's compute pass (GLSL 4.30, ``render/shaders/motion_spin.comp``) turns the instance rows; the draws
read the result as their instance attributes.
"""

from __future__ import annotations

from gandalf_core.app.cli import launcher

from .scene import PART

create_app, main = launcher(PART, "opengl", __doc__)


if __name__ == "__main__":
    raise SystemExit(main())
