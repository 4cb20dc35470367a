"""Step 07 exercises: fill in ``brdf.glsl``/``.wgsl`` (the GGX specular BRDF), ``normal_map.glsl``/``.wgsl`` (TBN
decoding) and ``particle_step.glsl``/``.wgsl`` (the compute kernel), then run ``pytest --student
tests/step07_advanced``. The step's shaders include these files from this folder.
"""
