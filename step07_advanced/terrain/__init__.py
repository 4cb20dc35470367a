"""Step 07's tessellated terrain: a fractal heightmap drawn as quad patches whose detail follows the camera.

OpenGL tessellates the patches in hardware (a tessellation control and evaluation shader); WebGPU has no such
stage, so a compute pass builds the same triangles into a storage buffer that the vertex shader pulls from.
"""

#: The step package whose ``exercises`` / ``solutions`` hold this technique's shader functions.
STEP = "step07_advanced"
