"""Step 07 exercises: shader functions in GLSL and WGSL, one file per exercise, which the techniques' shaders
``#include`` from this folder (``--student`` runs them; the default runs ``solutions/``). Grade them with
``pytest --student tests/step07_advanced`` (add ``-k terrain`` etc. for one technique).

=============================  =========================================================================  ==========
file (``.glsl`` and ``.wgsl``)  what you write                                                              technique
=============================  =========================================================================  ==========
``brdf``                       the GGX distribution D, Smith geometry G, Schlick Fresnel F and the          showcase,
                               metallic-roughness workflow                                                  pbr_model
``normal_map``                 decoding a tangent-space normal with the TBN frame                           showcase
``particle_step``              one exact step of a particle under gravity, with a floor bounce (compute)  showcase
``terrain``                    ``tess_level`` (level of detail), ``terrain_height``, ``terrain_normal``     terrain
``explode``                    ``face_normal`` and ``explode_offset`` (how far each face moves)             explode
``blur_kernel``                ``gaussian_weight``: the normalised Gaussian weights                        filter
``convolve``                   ``blur_pass``: one clamp-to-edge blur pass (compute)                         filter
``parallax``                   simple offset, steep and occlusion parallax mapping                          parallax
``ray_sphere``                 ``hit_sphere``: the nearest ray-sphere hit, numerically stable               pathtracer
``dielectric``                 ``scatter_dielectric``: Snell, total internal reflection, Schlick            pathtracer
=============================  =========================================================================  ==========
"""
