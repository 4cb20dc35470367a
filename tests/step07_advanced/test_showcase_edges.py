"""The showcase's shader functions on their stated rules, through the student's own GLSL and WGSL (the shader
harness), against float64 numpy:

* ``perturb_normal``: the result is a unit vector, and a tangent that interpolation left off the normal's plane is
  made perpendicular first (Gram-Schmidt), so the bent normal is the same as with the clean tangent;
* ``particle_step``: the floor bounces a particle only while it moves down (a particle below the floor already
  moving up keeps going), and otherwise the semi-implicit Euler step.

Tolerance: 2e-5 per component (the reference measures below 1e-6); non-finite values fail.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from shader_harness import evaluate

LANGUAGES = ("glsl", "wgsl")
TOLERANCE = 2e-5


def impl_dir(impl) -> list[Path]:
    return [Path(impl.__file__).resolve().parent]


def perturb_np(n, tangent, rgb):
    n = np.asarray(n, float)
    t = np.asarray(tangent[:3], float) - n * np.dot(n, tangent[:3])
    t /= np.linalg.norm(t)
    b = np.cross(n, t) * (-1.0 if tangent[3] < 0 else 1.0)
    m = np.asarray(rgb, float) * 2 - 1
    r = t * m[0] + b * m[1] + n * m[2]
    return r / np.linalg.norm(r)


@pytest.mark.exercise("normal_map")
@pytest.mark.parametrize("language", LANGUAGES)
def test_perturb_normal_is_unit_and_orthogonalises_the_tangent(impl, language):
    rng = np.random.default_rng(3)
    normals, tangents, texels = [], [], []
    for _ in range(64):
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        t = rng.normal(size=3)
        t -= n * np.dot(n, t)
        t /= np.linalg.norm(t)
        tilted = t + n * rng.uniform(-0.6, 0.6)  # interpolation leaves the tangent off the plane
        normals.append([*n, 0.0])
        tangents.append([*tilted, rng.choice([-1.0, 1.0])])
        texels.append([*rng.uniform(0.1, 0.9, 2), rng.uniform(0.6, 1.0), 0.0])  # a bent, mostly-up normal
    arrays = {"n": ("vec4", np.array(normals, np.float32)), "t": ("vec4", np.array(tangents, np.float32)),
              "c": ("vec4", np.array(texels, np.float32))}
    expr = ("vec4(perturb_normal(n.xyz, t, c.xyz), 0.0)" if language == "glsl"
            else "vec4<f32>(perturb_normal(n.xyz, t, c.xyz), 0.0)")
    got = evaluate(language, f'#include "normal_map.{language}"', expr, arrays, "vec4", impl_dir(impl))[:, :3]
    for n, t, c, out in zip(normals, tangents, texels, got):
        want = perturb_np(n[:3], t, c[:3])
        assert np.all(np.isfinite(out)) and np.allclose(out, want, atol=TOLERANCE), (
            f"{language}: perturb_normal(n={np.round(n[:3], 4).tolist()}, tangent={np.round(t, 4).tolist()}, "
            f"texel={np.round(c[:3], 4).tolist()}) = {out.tolist()}, expected {np.round(want, 6).tolist()} "
            f"(length {np.linalg.norm(out):.4f}; hint: make the tangent perpendicular to n first, and return a unit "
            "vector)")


@pytest.mark.exercise("normal_map")
@pytest.mark.parametrize("language", LANGUAGES)
def test_perturb_normal_without_a_tangent_or_a_result_stays_finite(impl, language):
    """The stub's fallbacks: a tangent of no usable length (zero, or parallel to n) takes any unit vector
    perpendicular to n, so the result is unit with the texel's share along n (m.z / |m|, whichever perpendicular
    was taken); a texel of (0.5, 0.5, 0.5) decodes to m = 0, a result of no length: n itself."""
    n = np.array([0.0, 0.6, 0.8])
    cases = [([0.0, 0.0, 0.0, 1.0], [0.7, 0.35, 0.9]), ([0.0, 1.2, 1.6, -1.0], [0.25, 0.6, 0.8]),
             ([1.0, 0.0, 0.0, 1.0], [0.5, 0.5, 0.5]), ([0.0, 0.0, 0.0, 1.0], [0.5, 0.5, 0.5])]
    arrays = {"n": ("vec4", np.array([[*n, 0.0]] * len(cases), np.float32)),
              "t": ("vec4", np.array([t for t, _ in cases], np.float32)),
              "c": ("vec4", np.array([[*c, 0.0] for _, c in cases], np.float32))}
    expr = ("vec4(perturb_normal(n.xyz, t, c.xyz), 0.0)" if language == "glsl"
            else "vec4<f32>(perturb_normal(n.xyz, t, c.xyz), 0.0)")
    got = evaluate(language, f'#include "normal_map.{language}"', expr, arrays, "vec4", impl_dir(impl))[:, :3]
    for (tangent, texel), out in zip(cases, got):
        m = np.asarray(texel) * 2.0 - 1.0
        along = m[2] / np.linalg.norm(m) if np.linalg.norm(m) > 0 else 1.0
        ok = (np.all(np.isfinite(out)) and abs(np.linalg.norm(out) - 1.0) <= TOLERANCE
              and abs(float(np.dot(out, n)) - along) <= TOLERANCE)
        assert ok, (f"{language}: perturb_normal(n={n.tolist()}, tangent={tangent}, texel={texel}) = {out.tolist()}: "
                    f"expected a unit vector with n·result = {along:.4f} (hint: with no usable tangent take any "
                    "unit vector perpendicular to n; with a result of no length return n)")


PRELUDES = {
    "glsl": "struct Particle { vec4 position; vec4 velocity; };\n"
            "struct SimParams { vec4 gravity; vec4 emitter; float dt; float restitution; float floor_y; uint seed; };\n"
            '#include "particle_step.glsl"',
    "wgsl": "struct Particle { position: vec4<f32>, velocity: vec4<f32> };\n"
            "struct SimParams { gravity: vec4<f32>, emitter: vec4<f32>, dt: f32, restitution: f32, floor_y: f32, "
            "seed: u32 };\n"
            '#include "particle_step.wgsl"',
}


@pytest.mark.exercise("particle_step")
@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("part", ["position", "velocity"])
def test_the_floor_bounces_only_particles_moving_down(impl, language, part):
    dt, restitution, floor_y, gravity = 0.1, 0.5, 0.0, np.array([0.0, -9.81, 0.0])
    cases = [  # (position, velocity): falling through the floor, below it but rising, above it, resting on it
        ([0.0, 0.05, 0.0, 2.0], [1.0, -3.0, 0.0, 0.0]),
        ([0.0, -0.5, 0.0, 2.0], [0.0, 2.0, 0.5, 0.75]),  # still below after the step, rising; velocity.w kept
        ([1.0, 2.0, 0.0, 2.0], [0.0, 1.0, 0.0, 0.0]),
        ([0.0, 0.0, 0.0, 0.5], [0.0, 0.0, 0.0, 0.0]),
    ]
    pos = np.array([c[0] for c in cases], np.float32)
    vel = np.array([c[1] for c in cases], np.float32)
    make = "SimParams(vec4({g}), vec4(0.0), {dt}, {r}, {f}, 0u)" if language == "glsl" else \
        "SimParams(vec4<f32>({g}), vec4<f32>(0.0), {dt}, {r}, {f}, 0u)"
    sim = make.format(g=", ".join(f"{x:.2f}" for x in [*gravity, 0.0]), dt=dt, r=restitution, f=floor_y)
    particle = "Particle(p, v)"
    expr = f"particle_step({particle}, {sim}).{part}"
    got = evaluate(language, PRELUDES[language], expr, {"p": ("vec4", pos), "v": ("vec4", vel)}, "vec4",
                   impl_dir(impl))
    for (p, v), out in zip(cases, got):
        velocity = np.array(v[:3]) + gravity * dt
        position = np.array(p[:3]) + velocity * dt
        if position[1] < floor_y and velocity[1] < 0.0:
            position[1] = floor_y + (floor_y - position[1]) * restitution
            velocity[1] = -velocity[1] * restitution
        want = np.array([*position, p[3] - dt]) if part == "position" else np.array([*velocity, v[3]])
        assert np.all(np.isfinite(out)) and np.allclose(out, want, atol=TOLERANCE), (
            f"{language}: particle_step(position={p}, velocity={v}) gave {part} {np.round(out, 5).tolist()}, "
            f"expected {np.round(want, 5).tolist()} (hint: bounce only below the floor AND moving down)")
