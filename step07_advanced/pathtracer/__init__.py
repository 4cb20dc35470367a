"""Step 07's path tracer: a compute shader that traces spheres and triangle meshes (through a bounding volume
hierarchy built on the CPU) with Lambertian, metal and glass materials under the scene's cube-map sky, one sample
per pixel per frame, accumulated in a float storage buffer and shown by a full-screen material that reads it.
The same kernel runs as GLSL 4.30 in OpenGL and as WGSL in WebGPU, with the same random numbers in both.
"""

#: The step package whose ``exercises`` / ``solutions`` hold this technique's shader functions.
STEP = "step07_advanced"
