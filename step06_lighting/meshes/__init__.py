"""Step 06's meshes: a model read from a file, and how many triangles a sphere needs.

The bunny (``models/bunny.glb``, five parts placed by their glTF node transforms) is loaded part by part and each
part drawn in its own colour under one parent entity; beside it a coarse and a fine ``uv_sphere``.
``python -m step06_lighting.meshes.opengl`` (or ``.webgpu``); ``make_bunny`` writes the model,
``study_mesh_resolution`` measures the sphere's error against its cost.
"""

#: The step package whose ``exercises`` / ``solutions`` and ``shaders/`` this concept uses.
STEP = "step06_lighting"

#: The step's shaders this concept's scene uses (``step06_lighting.shaders.SHADERS``).
SHADERS = ("phong", "phong_textured")
