"""Step 06's environment mapping: a skybox, and materials that look the sky up in the reflected and refracted
view directions.

The silver bunny mirrors the sky; the ice bunny refracts it and, by Fresnel's term, reflects more of it at
grazing angles. Both call the exercise's ``reflect_direction`` / ``refract_direction`` (``shading.glsl``/``.wgsl``).
``python -m step06_lighting.environment.opengl`` (or ``.webgpu``).
"""

#: The step package whose ``exercises`` / ``solutions`` and ``shaders/`` this concept uses.
STEP = "step06_lighting"

#: The step's shaders this concept's scene uses (``step06_lighting.shaders.SHADERS``).
SHADERS = ("mirror", "glass")
