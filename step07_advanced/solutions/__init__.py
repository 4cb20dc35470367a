"""Step 07 reference solutions: the shader functions ``brdf``, ``normal_map`` and ``particle_step`` (GLSL and WGSL)
live beside this file; the step's shaders include them from here."""
