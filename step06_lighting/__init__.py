"""Step 06 — lighting: one runnable sub-package per concept (the layout of step 05's concepts).

* ``meshes``       meshes from files: the bunny's five glTF parts placed by their node transforms, and how many
                   triangles a sphere needs (the mesh-resolution study);
* ``lights``       Blinn-Phong under many lights: the clay bunny inside a ring of sixteen coloured lights, packed
                   into one uniform block by a system; the API lesson (a uniform block of lights in plain moderngl
                   and plain wgpu), the benchmark and the light-count study;
* ``environment``  a skybox and environment mapping: the silver bunny mirrors the sky, the ice bunny refracts it.

Each runs on its own (``python -m step06_lighting.lights.opengl``); ``python -m step06_lighting.opengl --concept
NAME`` runs one too (by default ``lights``). Every concept folder holds ``scene.py`` (the backend-neutral scene)
and ``opengl.py`` / ``webgpu.py``; the step's shaders, the bunny (``models/bunny.glb``), its ``exercises/``
(``shading.glsl``/``.wgsl``, ``lights.py``, ``optics.py``) and ``solutions/`` are shared by the concepts and stay
at the step's top. ``scene.py`` here puts the three together: the step's whole scene (three bunnies under the sky
and seventeen lights).
"""

#: The concepts, in the order the step page teaches them (each is a sub-package of this step).
CONCEPTS = ("meshes", "lights", "environment")

#: What ``python -m step06_lighting.opengl`` runs without ``--concept``.
DEFAULT_CONCEPT = "lights"
