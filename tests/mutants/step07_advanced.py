"""Mutants of step 07's shader exercises, for the mutation check.

The lists live beside the checks that kill them, in the technique's test files (each of those files also runs
its mutants through the shader harness as ungraded tests); here they are read from the files' source (only the
literal tables, nothing is imported: the mutation runner forks with no GPU library loaded) and registered with
the exercise each one breaks. The terrain, filter and parallax mutants use other formats and are checked by
their own test files only. The showcase's two older exercises (``normal_map``, ``particle_step``) have their
mutants written here.
"""

from __future__ import annotations

import ast
from pathlib import Path

from gandalf_core.grading.mutants import Mutant, shader_mutant

STEP = "step07_advanced"
MUTANTS: list[Mutant] = []
TESTS = Path(__file__).resolve().parent.parent / STEP


def _tables(test_file: str, names: set[str]) -> dict:
    """The module-level assignments of ``names`` in ``test_file``, evaluated in order in an empty namespace."""
    tree = ast.parse((TESTS / test_file).read_text())
    namespace: dict = {}
    for node in tree.body:
        if isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            flat = [t for target in targets for t in (target.elts if isinstance(target, ast.Tuple) else [target])]
            if any(isinstance(t, ast.Name) and t.id in names for t in flat):
                exec(compile(ast.Module([node], []), test_file, "exec"), {}, namespace)  # literal tables only
    return namespace


_explode = _tables("test_explode.py", {"G", "W", "SHADER_MUTANTS"})
for name, description, edits in _explode["SHADER_MUTANTS"]:
    shader_mutant(MUTANTS, STEP, "explode_offset", name, description, edits)

_tracer = _tables("test_pathtracer.py", {"HG", "HW", "SG", "SW", "HIT_MUTANTS", "SCATTER_MUTANTS"})
for exercise, table in (("hit_sphere", _tracer["HIT_MUTANTS"]), ("scatter_dielectric", _tracer["SCATTER_MUTANTS"])):
    for name, description, edits in table:
        shader_mutant(MUTANTS, STEP, exercise, name, description, edits)

_brdf = _tables("test_pbr_model_brdf.py", {"G", "W", "SHADER_MUTANTS", "MUTANT_EXERCISE"})
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
]
PG, PW = "particle_step.glsl", "particle_step.wgsl"
PARTICLE_STEP = [
    ("explicit-euler", "moves with the old velocity (explicit instead of semi-implicit Euler)",
     [(PG, "vec3 position = p.position.xyz + velocity * s.dt;",
       "vec3 position = p.position.xyz + p.velocity.xyz * s.dt;"),
      (PW, "var position = p.position.xyz + velocity * s.dt;",
       "var position = p.position.xyz + p.velocity.xyz * s.dt;")]),
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
    ("gravity-sign", "subtracts gravity (which already points down)",
     [(PG, "p.velocity.xyz + s.gravity.xyz * s.dt;", "p.velocity.xyz - s.gravity.xyz * s.dt;"),
      (PW, "p.velocity.xyz + s.gravity.xyz * s.dt;", "p.velocity.xyz - s.gravity.xyz * s.dt;")]),
]
for name, description, edits in NORMAL_MAP:
    shader_mutant(MUTANTS, STEP, "normal_map", name, description, edits)
for name, description, edits in PARTICLE_STEP:
    shader_mutant(MUTANTS, STEP, "particle_step", name, description, edits)
