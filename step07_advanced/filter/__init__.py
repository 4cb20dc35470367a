"""Step 07's image filter: a separable Gaussian blur, a Sobel edge filter, the naive 2-D convolution and a
workgroup-tiled blur as compute shaders (GLSL image load/store in OpenGL, WGSL storage textures in WebGPU), checked
against a float64 numpy reference and shown on screen as original | blur / edges | edges of the blur.
"""

#: The step package whose ``exercises`` / ``solutions`` hold this technique's shader functions.
STEP = "step07_advanced"
