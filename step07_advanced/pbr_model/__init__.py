"""Step 07's PBR model: a textured glTF model (base colour, metallic-roughness, normal, occlusion and emissive
maps) lit by the scene's lights and by image-based light (irradiance map, GGX-prefiltered environment, split-sum
BRDF lookup table), the same in OpenGL and WebGPU."""

#: The step package whose ``exercises`` / ``solutions`` hold this technique's shader functions.
STEP = "step07_advanced"
