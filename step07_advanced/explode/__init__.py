"""Step 07 technique: an exploding mesh — a geometry shader in OpenGL, vertex pulling in WebGPU.

Every triangle of the bunny flies out along its face normal and back. OpenGL moves the triangles in a geometry
shader; WebGPU has no geometry stage, so its vertex shader reads each triangle's corners from storage buffers
(vertex pulling). ``python -m step07_advanced.explode.opengl`` / ``.webgpu``; the exercise is ``explode_offset``.
"""

#: The step package whose ``exercises`` / ``solutions`` hold this technique's shader functions.
STEP = "step07_advanced"
