"""Mutants of step 07's shader exercises, for the mutation check.

The lists live beside the checks that kill them, in each technique's ``test_<technique>_mutants.py`` (the filter's
in ``test_filter_reference.py``): modules apart from the graded tests, since they hold the reference's own shader
text, which a student's release leaves out. Each of them also runs its mutants through the graded checks as ungraded
tests; here they are read from the files' source (only the literal tables, nothing is imported: the mutation runner
forks with no GPU library loaded) and registered with the exercise each one breaks. The terrain, filter and
parallax mutant tables build their mutants in their own formats
(function bodies in a frame, weight-table parameters, replacements in the solution's text): the same builders run
here and each mutant becomes a whole-file replacement of the copied solution, so the mutation runner grades exactly
the shader text those files' own mutant tests check (terrain_height gets two more here). The showcase's two older
exercises (``normal_map``, ``particle_step``) have their mutants written here, and so do 15 more BRDF mutants
(fresnel, ggx_distribution, smith_geometry, metallic_roughness and ggx_specular had fewer than five each).
"""

from __future__ import annotations

import ast
from pathlib import Path

from gandalf_tools.grading.mutants import Mutant, shader_mutant

STEP = "step07_advanced"
MUTANTS: list[Mutant] = []
TESTS = Path(__file__).resolve().parent.parent / STEP


def _tables(test_file: str, names: set[str]) -> dict:
    """The module-level assignments (and plain functions) of ``names`` in ``test_file``, evaluated in order in an
    empty namespace: literal tables and string-building helpers only, so nothing is imported."""
    tree = ast.parse((TESTS / test_file).read_text())
    namespace: dict = {}
    for node in tree.body:
        if isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            flat = [t for target in targets for t in (target.elts if isinstance(target, ast.Tuple) else [target])]
            wanted = any(isinstance(t, ast.Name) and t.id in names for t in flat)
        else:
            wanted = isinstance(node, ast.FunctionDef) and node.name in names
        if wanted:
            exec(compile(ast.Module([node], []), test_file, "exec"), namespace)
    return namespace


SOLUTIONS = TESTS.parent.parent / STEP / "solutions"


def _slug(text: str) -> str:
    """A mutant's name for the runner (``step:exercise:name``): the test file's description, lower case, dashes."""
    return "-".join("".join(c if c.isalnum() else " " for c in text.lower()).split())


def _whole_file(file: str, text: str) -> tuple[str, str, str]:
    """An edit that replaces the copied solution file ``file`` by ``text`` (its whole text occurs exactly once)."""
    return (file, (SOLUTIONS / file).read_text(), text)


_explode = _tables("test_explode_mutants.py", {"G", "W", "SHADER_MUTANTS"})
for name, description, edits in _explode["SHADER_MUTANTS"]:
    shader_mutant(MUTANTS, STEP, "explode_offset", name, description, edits)

_tracer = _tables("test_pathtracer_mutants.py", {"HG", "HW", "SG", "SW", "HIT_MUTANTS", "SCATTER_MUTANTS"})
for exercise, table in (("hit_sphere", _tracer["HIT_MUTANTS"]), ("scatter_dielectric", _tracer["SCATTER_MUTANTS"])):
    for name, description, edits in table:
        shader_mutant(MUTANTS, STEP, exercise, name, description, edits)

_brdf = _tables("test_pbr_model_brdf_mutants.py", {"G", "W", "SHADER_MUTANTS", "MUTANT_EXERCISE"})
for name, description, edits in _brdf["SHADER_MUTANTS"]:
    shader_mutant(MUTANTS, STEP, _brdf["MUTANT_EXERCISE"][name], name, description, edits)

# --- the showcase's normal mapping and particle step (edits of the solution files) --------------------------------
NG, NW = "normal_map.glsl", "normal_map.wgsl"
NORMAL_MAP = [
    ("no-decode", "uses the texel as it is (forgets * 2 - 1)",
     [(NG, "vec3 m = map_rgb * 2.0 - 1.0;", "vec3 m = map_rgb;"),
      (NW, "let m = map_rgb * 2.0 - 1.0;", "let m = map_rgb;")]),
    ("no-gram-schmidt", "keeps the interpolated tangent off the normal's plane",
     [(NG, "vec3 t = tangent.xyz - n * dot(n, tangent.xyz);", "vec3 t = tangent.xyz;"),
      (NW, "var t = tangent.xyz - n * dot(n, tangent.xyz);", "var t = tangent.xyz;")]),
    ("handedness-ignored", "ignores tangent.w (mirrored UVs bend the normal the wrong way)",
     [(NG, "vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);", "vec3 b = cross(n, t);"),
      (NW, "let b = cross(n, t) * select(1.0, -1.0, tangent.w < 0.0);", "let b = cross(n, t);")]),
    ("bitangent-swapped", "cross(t, n): the bitangent points down the image",
     [(NG, "vec3 b = cross(n, t) *", "vec3 b = cross(t, n) *"),
      (NW, "let b = cross(n, t) *", "let b = cross(t, n) *")]),
    ("not-normalised", "returns the unnormalised TBN product",
     [(NG, "return r_length > 1e-6 ? r / r_length : n;", "return r;"),
      (NW, "return select(n, r / max(r_length, 1e-6), r_length > 1e-6);", "return r;")]),
    ("xy-swapped", "m.y along the tangent and m.x along the bitangent",
     [(NG, "vec3 r = t * m.x + b * m.y + n * m.z;", "vec3 r = t * m.y + b * m.x + n * m.z;"),
      (NW, "let r = t * m.x + b * m.y + n * m.z;", "let r = t * m.y + b * m.x + n * m.z;")]),
    ("no-tangent-fallback", "divides by the tangent's length even when it is zero (a zero or parallel tangent: NaN)",
     [(NG, "if (t_length > 1e-6) {", "if (true) {"), (NW, "if (t_length > 1e-6) {", "if (true) {")]),
    ("no-result-fallback", "normalises the result even when it has no length (texel (0.5, 0.5, 0.5): NaN)",
     [(NG, "return r_length > 1e-6 ? r / r_length : n;", "return r / r_length;"),
      (NW, "return select(n, r / max(r_length, 1e-6), r_length > 1e-6);", "return r / r_length;")]),
]
PG, PW = "particle_step.glsl", "particle_step.wgsl"
PARTICLE_STEP = [
    ("semi-implicit-euler", "moves with the new velocity and no g dt^2 / 2 (semi-implicit Euler: depends on dt)",
     [(PG, "p.velocity.xyz * s.dt + 0.5 * s.gravity.xyz * (s.dt * s.dt);",
       "(p.velocity.xyz + s.gravity.xyz * s.dt) * s.dt;"),
      (PW, "p.velocity.xyz * s.dt + 0.5 * s.gravity.xyz * (s.dt * s.dt);",
       "(p.velocity.xyz + s.gravity.xyz * s.dt) * s.dt;")]),
    ("explicit-euler", "forgets the g dt^2 / 2 term (explicit Euler: depends on dt)",
     [(PG, " + 0.5 * s.gravity.xyz * (s.dt * s.dt);", ";"),
      (PW, " + 0.5 * s.gravity.xyz * (s.dt * s.dt);", ";")]),
    ("no-restitution", "bounces without losing speed",
     [(PG, "velocity.y = -velocity.y * s.restitution;", "velocity.y = -velocity.y;"),
      (PW, "velocity.y = -velocity.y * s.restitution;", "velocity.y = -velocity.y;")]),
    ("bounce-moving-up", "bounces whenever below the floor, also while already moving up",
     [(PG, "if (position.y < s.floor_y && velocity.y < 0.0) {", "if (position.y < s.floor_y) {"),
      (PW, "if (position.y < s.floor_y && velocity.y < 0.0) {", "if (position.y < s.floor_y) {")]),
    ("clamp-to-floor", "puts the particle on the floor instead of mirroring the overshoot",
     [(PG, "position.y = s.floor_y + (s.floor_y - position.y) * s.restitution;", "position.y = s.floor_y;"),
      (PW, "position.y = s.floor_y + (s.floor_y - position.y) * s.restitution;", "position.y = s.floor_y;")]),
    ("life-not-decreased", "forgets life -= dt",
     [(PG, "vec4(position, p.position.w - s.dt)", "vec4(position, p.position.w)"),
      (PW, "vec4<f32>(position, p.position.w - s.dt)", "vec4<f32>(position, p.position.w)")]),
    ("velocity-w-zeroed", "writes velocity.w = 0 instead of keeping it",
     [(PG, "vec4(velocity, p.velocity.w)", "vec4(velocity, 0.0)"),
      (PW, "vec4<f32>(velocity, p.velocity.w)", "vec4<f32>(velocity, 0.0)")]),
    ("gravity-sign", "subtracts gravity (which already points down)",
     [(PG, "velocity = p.velocity.xyz + s.gravity.xyz * s.dt;", "velocity = p.velocity.xyz - s.gravity.xyz * s.dt;"),
      (PW, "velocity = p.velocity.xyz + s.gravity.xyz * s.dt;", "velocity = p.velocity.xyz - s.gravity.xyz * s.dt;")]),
]
for name, description, edits in NORMAL_MAP:
    shader_mutant(MUTANTS, STEP, "normal_map", name, description, edits)
for name, description, edits in PARTICLE_STEP:
    shader_mutant(MUTANTS, STEP, "particle_step", name, description, edits)

# --- terrain: the test file's function bodies in its frame (tess_level, terrain_height, terrain_normal) -------------
TERRAIN_EXERCISE = {"tess_level": "terrain_lod", "terrain_height": "terrain_height", "terrain_normal": "terrain_normal"}
_terrain = _tables("test_terrain_mutants.py", {"_GLSL", "_WGSL", "_BILINEAR", "_BILINEAR_WGSL", "_REFERENCE",
                                                "MUTANTS"})


def _terrain_file(language: str, function: str, body: str) -> str:
    """``terrain.<language>`` as the test file's ``_write_mutant`` writes it: ``function`` with ``body``, the
    other two functions with the reference bodies."""
    heads = _terrain["_GLSL"] if language == "glsl" else _terrain["_WGSL"]
    column = 0 if language == "glsl" else 1
    return "\n".join(head.format(body=body if name == function else _terrain["_REFERENCE"][name][column])
                     for name, head in heads.items()) + "\n"


for description, (function, glsl, wgsl) in _terrain["MUTANTS"].items():
    shader_mutant(MUTANTS, STEP, TERRAIN_EXERCISE[function], _slug(description), description,
                  [_whole_file("terrain.glsl", _terrain_file("glsl", function, glsl)),
                   _whole_file("terrain.wgsl", _terrain_file("wgsl", function, wgsl))])

TG, TW = "terrain.glsl", "terrain.wgsl"
shader_mutant(MUTANTS, STEP, "terrain_height", "height-weights-reversed",
              "mixes towards the texel behind: mix(h10, h00, f.x) (the fraction measured from the wrong side)",
              [(TG, "return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);",
                "return mix(mix(h10, h00, f.x), mix(h11, h01, f.x), f.y);"),
               (TW, "return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);",
                "return mix(mix(h10, h00, f.x), mix(h11, h01, f.x), f.y);")])
shader_mutant(MUTANTS, STEP, "terrain_height", "height-trunc-for-floor",
              "trunc(st) instead of floor(st): within half a texel of u = 0 or v = 0 it extrapolates",
              [(TG, "vec2 base = floor(st);", "vec2 base = trunc(st);"),
               (TW, "let base = floor(st);", "let base = trunc(st);")])

# --- filter: the Gaussian weights (blur_kernel) and the blur pass (convolve) -----------------------------------------
_filter = _tables("test_filter_reference.py", {"_W_GLSL", "_W_WGSL", "_weights_body", "WEIGHT_MUTANTS",
                                               "CONVOLVE_MUTANTS", "_C_GLSL", "_C_WGSL"})
for description, spec in _filter["WEIGHT_MUTANTS"].items():
    shader_mutant(MUTANTS, STEP, "blur_kernel", _slug(description), f"the weights: {description}",
                  [_whole_file(f"blur_kernel.{lang}",
                               _filter[template].format(body=_filter["_weights_body"](*spec, lang)))
                   for lang, template in (("glsl", "_W_GLSL"), ("wgsl", "_W_WGSL"))])
for description, (glsl, wgsl) in _filter["CONVOLVE_MUTANTS"].items():
    shader_mutant(MUTANTS, STEP, "convolve", _slug(description), f"the blur pass: {description}",
                  [_whole_file("convolve.glsl", _filter["_C_GLSL"].format(body=glsl)),
                   _whole_file("convolve.wgsl", _filter["_C_WGSL"].format(body=wgsl))])

# --- parallax: replacements in the solution's text (every occurrence, as the test file applies them) ----------------
_parallax = _tables("test_parallax_mutants.py", {"_SAME", "MUTANTS"})


def _parallax_file(language: str, edits: list[tuple[str, str]]) -> str:
    text = (SOLUTIONS / f"parallax.{language}").read_text()
    for old, new in edits:
        if old not in text:
            raise ValueError(f"parallax mutant edit {old!r} is not in the {language} solution (update the mutant)")
        text = text.replace(old, new)
    return text


for description, (function, glsl, wgsl) in _parallax["MUTANTS"].items():
    wgsl_edits = glsl if wgsl == _parallax["_SAME"] else wgsl
    shader_mutant(MUTANTS, STEP, "parallax", _slug(description), f"{function}: {description}",
                  [_whole_file("parallax.glsl", _parallax_file("glsl", glsl)),
                   _whole_file("parallax.wgsl", _parallax_file("wgsl", wgsl_edits))])

# --- more BRDF mutants (the test file's 15 gave fresnel, ggx_distribution, smith_geometry, metallic_roughness and
# ggx_specular fewer than five each): edits of the solution, one rule broken each -----------------------------------
BG, BW = "brdf.glsl", "brdf.wgsl"


def _both(glsl_old: str, glsl_new: str, wgsl_old: str | None = None, wgsl_new: str | None = None) -> list:
    """The same edit in both languages (WGSL spelled out where it differs)."""
    return [(BG, glsl_old, glsl_new), (BW, glsl_old if wgsl_old is None else wgsl_old,
                                       glsl_new if wgsl_new is None else wgsl_new)]


BRDF_MORE = [
    ("fresnel", "brdf-f-fourth-power", "Schlick with the 4th power of (1 - cos) instead of the 5th",
     _both("return f0 + (1.0 - f0) * (m2 * m2 * m);", "return f0 + (1.0 - f0) * (m2 * m2);")),
    ("fresnel", "brdf-f-no-one-minus-f0", "F0 + (1 - cos)^5, forgetting the (1 - F0) factor",
     _both("return f0 + (1.0 - f0) * (m2 * m2 * m);", "return f0 + (m2 * m2 * m);")),
    ("fresnel", "brdf-f-cos-not-complemented", "the 5th power of cos instead of (1 - cos)",
     _both("float m = 1.0 - clamp(cos_theta, 0.0, 1.0);\n    float m2 = m * m;\n    return f0 + (1.0 - f0)",
           "float m = clamp(cos_theta, 0.0, 1.0);\n    float m2 = m * m;\n    return f0 + (1.0 - f0)",
           "let m = 1.0 - clamp(cos_theta, 0.0, 1.0);\n    let m2 = m * m;\n    return f0 + (1.0 - f0)",
           "let m = clamp(cos_theta, 0.0, 1.0);\n    let m2 = m * m;\n    return f0 + (1.0 - f0)")),
    ("fresnel", "brdf-f-roughness-no-max", "the IBL Fresnel's limit 1 - roughness without max(.., F0)",
     _both("max(vec3(1.0 - clamp(roughness, 0.0, 1.0)), f0)", "vec3(1.0 - clamp(roughness, 0.0, 1.0))",
           "max(vec3<f32>(1.0 - clamp(roughness, 0.0, 1.0)), f0)", "vec3<f32>(1.0 - clamp(roughness, 0.0, 1.0))")),
    ("ggx_distribution", "brdf-d-cos-not-squared", "D with n·h where (n·h)² belongs",
     _both("float d = c * c * (a2 - 1.0) + 1.0;", "float d = c * (a2 - 1.0) + 1.0;",
           "let d = c * c * (a2 - 1.0) + 1.0;", "let d = c * (a2 - 1.0) + 1.0;")),
    ("ggx_distribution", "brdf-d-denominator-not-squared", "D = a² / (pi d) instead of a² / (pi d²)",
     _both("return a2 / (BRDF_PI * d * d);", "return a2 / (BRDF_PI * d);")),
    ("ggx_distribution", "brdf-d-min-roughness-zero", "roughness clamped to [0, 1], not [0.045, 1]",
     _both("float r = clamp(roughness, BRDF_MIN_ROUGHNESS, 1.0);", "float r = clamp(roughness, 0.0, 1.0);",
           "let r = clamp(roughness, BRDF_MIN_ROUGHNESS, 1.0);", "let r = clamp(roughness, 0.0, 1.0);")),
    ("smith_geometry", "brdf-g-view-only", "G1 of the view direction only (the light's factor left out)",
     _both("return v / (v * (1.0 - k) + k) * (l / (l * (1.0 - k) + k));", "return v / (v * (1.0 - k) + k);")),
    ("smith_geometry", "brdf-g-no-one-minus-k", "G1 = n·x / (n·x + k)",
     _both("return v / (v * (1.0 - k) + k) * (l / (l * (1.0 - k) + k));", "return v / (v + k) * (l / (l + k));")),
    ("smith_geometry", "brdf-k-direct-no-plus-one", "k_direct = roughness² / 8 (Karis' + 1 left out)",
     _both("return (r + 1.0) * (r + 1.0) / 8.0;", "return r * r / 8.0;")),
    ("metallic_roughness", "brdf-f0-mix-swapped", "mix(base, 0.04, metallic): metals get F0 = 0.04",
     _both("return mix(vec3(0.04), base, clamp(metallic, 0.0, 1.0));",
           "return mix(base, vec3(0.04), clamp(metallic, 0.0, 1.0));",
           "return mix(vec3<f32>(0.04), base, clamp(metallic, 0.0, 1.0));",
           "return mix(base, vec3<f32>(0.04), clamp(metallic, 0.0, 1.0));")),
    ("metallic_roughness", "brdf-diffuse-metallic-not-complemented", "diffuse scaled by metallic, not 1 - metallic",
     _both("return base * (1.0 - clamp(metallic, 0.0, 1.0)) * (1.0 - fresnel);",
           "return base * clamp(metallic, 0.0, 1.0) * (1.0 - fresnel);")),
    ("metallic_roughness", "brdf-diffuse-over-pi", "the albedo divided by pi (the lighting divides again)",
     _both("return base * (1.0 - clamp(metallic, 0.0, 1.0)) * (1.0 - fresnel);",
           "return base * (1.0 - clamp(metallic, 0.0, 1.0)) * (1.0 - fresnel) / BRDF_PI;")),
    ("ggx_specular", "brdf-specular-d-of-n-dot-l", "D of n·l instead of n·h",
     _both("float d = distribution_ggx(dot(n, h), roughness);", "float d = distribution_ggx(n_dot_l, roughness);",
           "let d = distribution_ggx(dot(n, h), roughness);", "let d = distribution_ggx(n_dot_l, roughness);")),
    ("ggx_specular", "brdf-specular-k-ibl", "the direct light's G with the IBL k",
     _both("geometry_smith(n_dot_v, n_dot_l, k_direct(roughness));",
           "geometry_smith(n_dot_v, n_dot_l, k_ibl(roughness));")),
]
for exercise, name, description, edits in BRDF_MORE:
    shader_mutant(MUTANTS, STEP, exercise, name, description, edits)
