"""Step 05's custom systems: your own component (data) and system (behaviour), the paper's gravity done right.

A GravityComponent holds a body's velocity and its floor; the GravitySystem integrates it on a fixed time step
(``fixed_step.py``), so the balls fall the same at 30 or 300 frames per second and lose height at each bounce.
``python -m step05_scenegraph.custom_systems.opengl`` (or ``.webgpu``).
"""

#: The step package whose ``exercises`` / ``solutions`` and ``shaders/`` this concept uses.
STEP = "step05_scenegraph"
