"""Step 07 — advanced techniques, one runnable sub-package each (the same layout for all of them).

Every technique folder holds ``scene.py`` (the backend-neutral scene), ``opengl.py`` and ``webgpu.py`` (the
runnable variants: ``python -m step07_advanced.<technique>.opengl``) and its ``shaders/``. The exercises of all
techniques live in the step's ``exercises/`` folder (the references in ``solutions/``), one file per exercise.
``python -m step07_advanced.opengl --technique NAME`` runs one technique too; the course tour renders them all.
"""

#: The techniques, in the order the step page teaches them (each is a sub-package of this step).
TECHNIQUES = ("showcase", "terrain", "explode", "filter", "pbr_model", "parallax", "pathtracer")
