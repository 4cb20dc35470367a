"""Correct alternatives of step 07's shader exercises: the same formulas written in other valid orders and forms
(GGX's denominator in Horner form or as 1 - (n·h)²(1 - alpha²), pow for Schlick's fifth power, a weight table
summed by symmetric pairs, the clamp-to-edge written per axis), each the same edit in GLSL and WGSL."""

from __future__ import annotations

from gandalf_tools.grading.fairness import shader_alternative
from gandalf_tools.grading.mutants import Mutant

STEP = "step07_advanced"
ALTERNATIVES: list[Mutant] = []


def _both(file: str, old: str, new: str, wgsl_old: str | None = None, wgsl_new: str | None = None):
    """The same replacement in ``file``.glsl and ``file``.wgsl (WGSL's text where it differs)."""
    return [(f"{file}.glsl", old, new), (f"{file}.wgsl", wgsl_old or old, wgsl_new or new)]


# GGX's denominator d = (n·h)² (alpha² - 1) + 1 in algebraically equal orders: near n·h = 1 with alpha² = 4.1e-6
# each cancels differently (up to ~1.5 % apart in float32), and every one must be accepted.
_D = "c * c * (a2 - 1.0) + 1.0;"
for _exercises, _name, _text, _new in [
    (("ggx_distribution", "ggx_specular"), "d-horner", "d = (c a2 - c) c + 1 (Horner form)", "(c * a2 - c) * c + 1.0;"),
    (("ggx_distribution", "ggx_specular"), "d-one-minus", "d = 1 - c² (1 - a2)", "1.0 - c * c * (1.0 - a2);"),
    (("ggx_distribution",), "d-sine-form", "d = (1 - c²) + c² a2 (the sine form)", "(1.0 - c * c) + c * c * a2;"),
]:
    for _exercise in _exercises:
        shader_alternative(ALTERNATIVES, STEP, _exercise, _name, _text, _both("brdf", _D, _new))

shader_alternative(ALTERNATIVES, STEP, "ggx_distribution", "alpha2-by-pow", "alpha² = pow(roughness, 4.0)",
                   _both("brdf", "float a2 = r * r * r * r;", "float a2 = pow(r, 4.0);",
                         "let a2 = r * r * r * r;", "let a2 = pow(r, 4.0);"))
shader_alternative(ALTERNATIVES, STEP, "fresnel", "pow-five", "Schlick's (1 - cos)^5 with pow(m, 5.0)",
                   _both("brdf", "return f0 + (1.0 - f0) * (m2 * m2 * m);", "return mix(f0, vec3(1.0), pow(m, 5.0));",
                         wgsl_new="return mix(f0, vec3<f32>(1.0), pow(m, 5.0));"))
shader_alternative(ALTERNATIVES, STEP, "metallic_roughness", "written-out-mix", "F0 = 0.04 (1 - m) + base m",
                   _both("brdf", "return mix(vec3(0.04), base, clamp(metallic, 0.0, 1.0));",
                         "float m = clamp(metallic, 0.0, 1.0);\n    return vec3(0.04) * (1.0 - m) + base * m;",
                         "return mix(vec3<f32>(0.04), base, clamp(metallic, 0.0, 1.0));",
                         "let m = clamp(metallic, 0.0, 1.0);\n    return vec3<f32>(0.04) * (1.0 - m) + base * m;"))
shader_alternative(ALTERNATIVES, STEP, "smith_geometry", "g1-divided-out", "G1 = 1 / (1 - k + k / x)",
                   _both("brdf", "return v / (v * (1.0 - k) + k) * (l / (l * (1.0 - k) + k));",
                         "return 1.0 / ((1.0 - k + k / v) * (1.0 - k + k / l));"))

# The blur: the clamp written per axis with min/max, and the weights summed as the centre plus symmetric pairs.
shader_alternative(ALTERNATIVES, STEP, "convolve", "clamp-per-axis", "clamp-to-edge with max and min per axis",
                   _both("convolve", "load_texel(clamp(p + i * dir, ivec2(0), last))",
                         "load_texel(min(max(p + i * dir, ivec2(0)), last))",
                         "load_texel(clamp(p + i * dir, vec2<i32>(0), last))",
                         "load_texel(min(max(p + i * dir, vec2<i32>(0)), last))"))
shader_alternative(ALTERNATIVES, STEP, "blur_kernel", "symmetric-pairs", "the sum as 1 + 2 × the taps j = 1..radius",
                   [("blur_kernel.glsl",
                     "    float sum = 0.0;  // the sum of the unnormalised taps -radius..radius\n"
                     "    for (int j = -radius; j <= radius; ++j) {\n        sum += exp(-float(j * j) * k);\n    }",
                     "    float sum = 1.0;\n"
                     "    for (int j = 1; j <= radius; ++j) {\n        sum += 2.0 * exp(-float(j * j) * k);\n    }"),
                    ("blur_kernel.wgsl",
                     "    var sum = 0.0;  // the sum of the unnormalised taps -radius..radius\n"
                     "    for (var j = -radius; j <= radius; j++) {\n        sum += exp(-f32(j * j) * k);\n    }",
                     "    var sum = 1.0;\n"
                     "    for (var j = 1; j <= radius; j++) {\n        sum += 2.0 * exp(-f32(j * j) * k);\n    }")])

# hit_sphere: the two roots ordered with a comparison instead of min / max.
shader_alternative(ALTERNATIVES, STEP, "hit_sphere", "roots-by-comparison", "near and far root ordered by a comparison",
                   _both("ray_sphere", "t0 = min(c / q, q / a);\n        t1 = max(c / q, q / a);",
                         "t0 = c / q < q / a ? c / q : q / a;\n        t1 = c / q < q / a ? q / a : c / q;",
                         wgsl_new="t0 = select(q / a, c / q, c / q < q / a);\n"
                                  "        t1 = select(c / q, q / a, c / q < q / a);"))

# The exploding triangle: the raised cosine as sin².
shader_alternative(ALTERNATIVES, STEP, "explode_offset", "sine-squared", "(1 - cos(2 pi t / T)) / 2 as sin²(pi t / T)",
                   [("explode.glsl", "float w = 0.5 - 0.5 * cos(6.283185307179586 * t / period);",
                     "float sn = sin(3.141592653589793 * t / period);\n    float w = sn * sn;"),
                    ("explode.wgsl", "let w = 0.5 - 0.5 * cos(6.283185307179586 * t / period);",
                     "let sn = sin(3.141592653589793 * t / period);\n    let w = sn * sn;")])

# Normal mapping with the TBN matrix; Schlick's fifth power multiplied out in the dielectric; the bounce with abs.
shader_alternative(ALTERNATIVES, STEP, "normal_map", "tbn-matrix", "r = mat3(T, B, N) m",
                   _both("normal_map", "vec3 r = t * m.x + b * m.y + n * m.z;", "vec3 r = mat3(t, b, n) * m;",
                         "let r = t * m.x + b * m.y + n * m.z;", "let r = mat3x3<f32>(t, b, n) * m;"))
shader_alternative(ALTERNATIVES, STEP, "scatter_dielectric", "fifth-power-multiplied", "(1 - cos_i)^5 as x²·x²·x",
                   _both("dielectric", "pow(1.0 - cos_i, 5.0)",
                         "((1.0 - cos_i) * (1.0 - cos_i) * (1.0 - cos_i) * (1.0 - cos_i) * (1.0 - cos_i))"))
shader_alternative(ALTERNATIVES, STEP, "particle_step", "bounce-with-abs",
                   "in the bounce (velocity.y < 0): abs(velocity.y) restitution; the overshoot mirrored",
                   _both("particle_step", "velocity.y = -velocity.y * s.restitution;",
                         "velocity.y = abs(velocity.y) * s.restitution;")
                   + _both("particle_step", "position.y = s.floor_y + (s.floor_y - position.y) * s.restitution;",
                           "position.y = s.floor_y - (position.y - s.floor_y) * s.restitution;"))
