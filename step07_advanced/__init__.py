"""Step 07 — advanced techniques, one runnable sub-package each (the same layout for all of them), and the
complete framework: the editor and USD scenes, the step's last concepts.

Every technique folder holds ``scene.py`` (the backend-neutral scene), ``opengl.py`` and ``webgpu.py`` (the
runnable variants: ``python -m step07_advanced.<technique>.opengl``) and its ``shaders/``. The exercises of all
techniques live in the step's ``exercises/`` folder (the references in ``solutions/``), one file per exercise.
``python -m step07_advanced.opengl --technique NAME`` runs one technique too; the course tour renders them all.

``editor/`` (the ImGui editor: panels as entities and systems, the generated inspector, undo) and ``usd/`` (saving
and loading scenes) come last, once every part they show has been built. The engine reaches them only through
its hooks (:mod:`gandalf_core.app.extensions`), so every step opens the editor with ``--editor`` and saves with
``--save FILE.usda``. ``saved.py`` lists what this step's scenes may hold in a USD file.
"""

#: The techniques, in the order the step page teaches them (each is a sub-package of this step).
TECHNIQUES = ("showcase", "terrain", "explode", "filter", "pbr_model", "parallax", "pathtracer", "gpu_motion")
