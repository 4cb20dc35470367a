"""Step 07 reference solutions: the shader functions of every exercise (``brdf``, ``normal_map``, ``particle_step``,
``terrain``, ``explode``, ``blur_kernel``, ``convolve``, ``parallax``, ``ray_sphere``, ``dielectric``; GLSL and WGSL)
live beside this file, with the same names as the stubs in ``exercises/``; the techniques' shaders include them."""
