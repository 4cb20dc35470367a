"""Step 05 — the scene graph: one runnable sub-package per concept (the layout of step 07's techniques).

* ``hierarchy``       parent links: a solar system whose bodies hang from turning pivots; re-parenting;
* ``custom_systems``  your own component and system: falling, bouncing balls on a fixed time step;
* ``integrators``     four integrators for damped springs side by side, and the two studies;
* ``several_scenes``  one app holding all the scenes, switched with keys 1-4 or TAB;
* ``house``           the capstone of the paper's user study (the exercise), and the 38-line version.

Each runs on its own (``python -m step05_scenegraph.hierarchy.opengl``); ``python -m step05_scenegraph.opengl
--concept NAME`` runs one too (by default ``several_scenes``). Every concept folder holds ``scene.py`` (the
backend-neutral scene) and ``opengl.py`` / ``webgpu.py``; the step's shaders, its ``exercises/`` (``house.py``,
``integrators.py``) and ``solutions/`` are shared by the concepts and stay at the step's top.
"""

#: The concepts, in the order the step page teaches them (each is a sub-package of this step).
CONCEPTS = ("hierarchy", "custom_systems", "integrators", "several_scenes", "house")

#: What ``python -m step05_scenegraph.opengl`` runs without ``--concept``: the app that holds every scene.
DEFAULT_CONCEPT = "several_scenes"

#: The shaders the concepts' variants register from this step's ``shaders/`` folder (GLSL ``<name>.vert/.frag``,
#: WGSL ``<name>.wgsl``).
SHADERS = ("unlit_textured", "shaded", "shaded_textured")
