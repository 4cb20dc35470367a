"""Step 06's lights: Blinn-Phong under many lights, which reach the shaders through one uniform block.

The clay bunny stands inside a ring of sixteen coloured point lights that circle it (each drawn as a small glowing
ball), with a directional key light and an ambient light. The step's ``LightCollectionSystem`` (exercise) packs
them into the lights block each frame; ``blinn_phong`` (exercise, GLSL and WGSL) shades each light.
``python -m step06_lighting.lights.opengl`` (or ``.webgpu``). Also here: the API lesson (``lights_gl.py`` /
``lights_wgpu.py``), the benchmark (``bench_lights``) and the light-count study (``study_lights``).
"""

#: The step package whose ``exercises`` / ``solutions`` and ``shaders/`` this concept uses.
STEP = "step06_lighting"

#: The step's shaders this concept's scene uses (``step06_lighting.shaders.SHADERS``).
SHADERS = ("phong", "phong_textured", "emissive")
