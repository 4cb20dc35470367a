"""Exercises ``hit_sphere`` and ``scatter_dielectric`` (step07 path tracer): the student's GLSL and WGSL functions,
run on the GPU through the shader harness (one compute invocation per case) and compared with float64 numpy
references on the same float32-rounded inputs.

Tolerances. ``hit_sphere``: a miss must return exactly -1.0; a hit must match the exact root within
``2e-5 · (|origin - centre| + radius) / |dir| + 1e-5 · |t|`` (a few float32 ulps of the numbers involved: 0.2 for
a sphere 10 000 units away, where the naive discriminant ``half_b² - a·c`` is off by whole units). Cases within
1e-3 (relative) of a range bound or of tangency are left out of the random set, where float32 may rightly decide
either way. ``scatter_dielectric``: every component within 1e-4 of the reference unit direction; random cases
within 1e-4 of a branch decision (``u`` against Schlick's R, ``sin²θt`` against 1) are left out. NaN fails
everywhere. The reference solutions measure at most 0.7 % of the hit tolerance and 8.3e-7 per direction
component on llvmpipe and lavapipe.
The rules are the ones the stubs' comments state; every check also runs on a set of plausible wrong
implementations (mutants, in ``test_pathtracer_mutants.py``), each of which must fail at least one of them.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
import shader_harness
from shader_checks import grade

SPHERE_EXPR = "hit_sphere(o.xyz, d.xyz, c.xyz, c.w, r.x, r.y)"
SCATTER_EXPR = {"glsl": "vec4(scatter_dielectric(d.xyz, n.xyz, p.x, p.y), 0.0)",
                "wgsl": "vec4<f32>(scatter_dielectric(d.xyz, n.xyz, p.x, p.y), 0.0)"}
HINT = {
    "random": "t is the smallest root in (t_min, t_max) of |o + t d - c|^2 = r^2 with a = dot(d, d) (d is not unit "
              "length); -1.0 when there is none",
    "edges": "tangent rays hit (discriminant 0), a ray from inside returns the far root, a sphere behind the ray or "
             "roots outside (t_min, t_max) give -1.0",
    "far": "for a far sphere half_b^2 - a*c subtracts two huge numbers: use a * (r^2 - |oc - (half_b/a) d|^2)",
    "huge": "keep every intermediate finite: q = -(half_b + sign(half_b) sqrt(disc)), roots c / q and q / a",
    "scatter": "entering: eta = 1/ior, n = normal; leaving: eta = ior, n = -normal; reflect when sin_t^2 > 1 or u < "
               "Schlick's R, else refract; normalise dir first",
    "tir": "leaving glass beyond the critical angle (eta^2 (1 - cos_i^2) > 1) always reflects, whatever u",
    "grazing": "at grazing incidence Schlick's R is nearly 1: reflect d - 2 dot(d, n) n (never NaN)",
    "ior1": "ior = 1: r0 = 0 and eta = 1, so a ray with u >= R goes straight through unchanged",
}


def evaluate(language: str, *args, **kwargs) -> np.ndarray:
    """The harness's ``evaluate``, with its GL context made current first: creating the harness's wgpu device
    (lavapipe) leaves the EGL context un-current here, and GL then cannot create programs."""
    if language == "glsl":
        shader_harness.gl_context().__enter__()
    return shader_harness.evaluate(language, *args, **kwargs)


def _f32(a) -> np.ndarray:
    return np.asarray(a, np.float32).astype(np.float64)


# --- references (float64) --------------------------------------------------------------------------------------
def hit_sphere_np(o, d, c, r, t_min, t_max) -> tuple[np.ndarray, np.ndarray]:
    """(t, margin): the exact nearest root in range or -1, and how far the case is from a decision boundary
    (relative: tangency, a root at a bound), for leaving out ambiguous random cases."""
    oc = o - c
    a = np.sum(d * d, axis=1)
    hb = np.sum(oc * d, axis=1)
    to_line = oc - (hb / a)[:, None] * d
    disc = a * (r * r - np.sum(to_line * to_line, axis=1))
    sq = np.sqrt(np.maximum(disc, 0.0))
    q = -(hb + np.where(hb >= 0, 1.0, -1.0) * sq)
    length = np.linalg.norm(oc, axis=1)
    cc = (length - r) * (length + r)
    with np.errstate(divide="ignore", invalid="ignore"):
        r1, r2 = np.where(q != 0, cc / q, 0.0), np.where(q != 0, q / a, 0.0)
    t0, t1 = np.minimum(r1, r2), np.maximum(r1, r2)
    ok = disc >= 0
    t = np.where(ok & (t0 > t_min) & (t0 < t_max), t0, np.where(ok & (t1 > t_min) & (t1 < t_max), t1, -1.0))
    scale = (length + r) / np.sqrt(a)
    margin = np.min(np.stack([np.abs(disc) / (a * r * r), np.abs(t0 - t_min) / scale, np.abs(t1 - t_min) / scale,
                              np.abs(t0 - t_max) / scale, np.abs(t1 - t_max) / scale]), axis=0)
    return t, margin


def scatter_np(d, normal, ior, u) -> tuple[np.ndarray, np.ndarray]:
    """(direction, margin) of the reference scatter_dielectric; margin: distance to a branch decision."""
    d = d / np.linalg.norm(d, axis=1, keepdims=True)
    dn = np.sum(d * normal, axis=1)
    entering = dn < 0
    n = np.where(entering[:, None], normal, -normal)
    eta = np.where(entering, 1.0 / ior, ior)
    cos_i = np.minimum(np.sum(-d * n, axis=1), 1.0)
    sin2 = eta * eta * (1.0 - cos_i * cos_i)
    r0 = ((1.0 - ior) / (1.0 + ior)) ** 2
    refl = r0 + (1.0 - r0) * (1.0 - cos_i) ** 5
    reflect = (sin2 > 1.0) | (u < refl)
    reflected = d - 2.0 * np.sum(d * n, axis=1)[:, None] * n
    t_perp = eta[:, None] * (d + cos_i[:, None] * n)
    t_par = -np.sqrt(np.maximum(0.0, 1.0 - np.sum(t_perp * t_perp, axis=1)))[:, None] * n
    refracted = t_perp + t_par
    out = np.where(reflect[:, None], reflected, refracted)
    out /= np.linalg.norm(out, axis=1, keepdims=True)
    margin = np.minimum(np.abs(sin2 - 1.0), np.where(sin2 > 1.0, np.inf, np.abs(u - refl)))
    return out, margin


# --- running the student's functions ---------------------------------------------------------------------------
def run_hit(language: str, include_dir: Path, o, d, c, r, t_min, t_max) -> np.ndarray:
    n = len(o)

    def vec4(v, w=0.0):
        fourth = np.broadcast_to(np.float32(w), (n,)) if np.ndim(w) == 0 else np.asarray(w, np.float32)
        return np.c_[np.asarray(v, np.float32).reshape(n, 3), fourth]

    inputs = {"o": ("vec4", vec4(o)), "d": ("vec4", vec4(d)), "c": ("vec4", vec4(c, r)),
              "r": ("vec2", np.c_[np.broadcast_to(t_min, (n,)), np.broadcast_to(t_max, (n,))].astype(np.float32))}
    return evaluate(language, f'#include "ray_sphere.{language}"', SPHERE_EXPR, inputs, "f32",
                    include_dirs=[include_dir]).astype(np.float64)


def run_scatter(language: str, include_dir: Path, d, normal, ior, u) -> np.ndarray:
    n = len(d)
    inputs = {"d": ("vec4", np.c_[np.asarray(d, np.float32), np.zeros(n, np.float32)]),
              "n": ("vec4", np.c_[np.asarray(normal, np.float32), np.zeros(n, np.float32)]),
              "p": ("vec2", np.c_[np.broadcast_to(ior, (n,)), np.broadcast_to(u, (n,))].astype(np.float32))}
    out = evaluate(language, f'#include "dielectric.{language}"', SCATTER_EXPR[language], inputs, "vec4",
                   include_dirs=[include_dir])
    return out[:, :3].astype(np.float64)


def _fmt(v) -> str:
    return str(np.round(np.asarray(v, np.float64), 6).tolist())


def _compare_hits(kind: str, got, expected, o, d, c, r, t_min, t_max) -> str | None:
    scale = (np.linalg.norm(o - c, axis=1) + r) / np.linalg.norm(d, axis=1)
    tol = 2e-5 * scale + 1e-5 * np.abs(expected)
    miss = expected == -1.0
    bad = np.where(miss, got != -1.0, ~(np.abs(got - expected) <= tol))
    if not bad.any():
        return None
    i = int(np.flatnonzero(bad)[0])
    return (f"{kind}: {int(bad.sum())} of {len(got)} cases wrong; e.g. origin={_fmt(o[i])}, dir={_fmt(d[i])}, "
            f"center={_fmt(c[i])}, radius={r[i]:.6g}, t_min={np.broadcast_to(t_min, got.shape)[i]:.6g}, "
            f"t_max={np.broadcast_to(t_max, got.shape)[i]:.6g}: expected {expected[i]:.7g}, got {got[i]!r}"
            f"{'' if miss[i] else f' (tolerance {tol[i]:.2g})'}. Hint: {HINT[kind]}")


def _compare_dirs(kind: str, got, expected, d, normal, ior, u) -> str | None:
    err = np.where(np.all(np.isfinite(got), axis=1), np.abs(np.nan_to_num(got) - expected).max(axis=1), np.inf)
    bad = ~(err <= 1e-4)
    if not bad.any():
        return None
    i = int(np.argmax(err))
    return (f"{kind}: {int(bad.sum())} of {len(got)} cases wrong; e.g. dir={_fmt(d[i])}, normal={_fmt(normal[i])}, "
            f"ior={np.broadcast_to(ior, (len(d),))[i]:.6g}, u={np.broadcast_to(u, (len(d),))[i]:.6g}: expected "
            f"{_fmt(expected[i])}, got {got[i].tolist()} (tolerance 1e-4). Hint: {HINT[kind]}")


# --- hit_sphere checks ---------------------------------------------------------------------------------------
def check_hit_random(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(17)
    n = 600
    c = rng.normal(0.0, 3.0, (n, 3))
    r = rng.uniform(0.2, 2.0, n)
    inside = rng.random(n) < 0.25
    o = np.where(inside[:, None], c + 0.6 * r[:, None] * rng.uniform(-1, 1, (n, 3)) / np.sqrt(3),
                 rng.normal(0.0, 4.0, (n, 3)))
    aim = c + 1.4 * r[:, None] * rng.uniform(-1, 1, (n, 3)) / np.sqrt(3)
    d = (aim - o) * 10.0 ** rng.uniform(-1.0, 1.0, (n, 1))
    flip = rng.random(n) < 0.15  # some spheres behind the ray
    d = np.where(flip[:, None], -d, d)
    t_min = np.where(rng.random(n) < 0.5, 1e-4, rng.uniform(0.0, 0.6, n))
    t_max = np.where(rng.random(n) < 0.5, 1e30, rng.uniform(0.3, 2.0, n))
    o, d, c, r, t_min, t_max = _f32(o), _f32(d), _f32(c), _f32(r), _f32(t_min), _f32(t_max)
    expected, margin = hit_sphere_np(o, d, c, r, t_min, t_max)
    keep = margin > 1e-3
    o, d, c, r, t_min, t_max, expected = (x[keep] for x in (o, d, c, r, t_min, t_max, expected))
    got = run_hit(language, include_dir, o, d, c, r, t_min, t_max)
    return _compare_hits("random", got, expected, o, d, c, r, t_min, t_max)


def check_hit_edges(language: str, include_dir: Path) -> str | None:
    # (origin, dir, centre, radius, t_min, t_max, expected t)
    cases = [
        ((0, 1, -5), (0, 0, 1), (0, 0, 0), 1, 1e-4, 1e30, 5.0),      # tangent: discriminant exactly 0
        ((0, 1, -5), (0, 0, 2), (0, 0, 0), 1, 1e-4, 1e30, 2.5),      # tangent, dir of length 2
        ((0, 1.01, -5), (0, 0, 1), (0, 0, 0), 1, 1e-4, 1e30, -1.0),  # just misses
        ((0, 0, 0), (1, 0, 0), (0, 0, 0), 1, 1e-4, 1e30, 1.0),       # from the centre: the far root
        ((0.3, 0, 0), (-1, 0, 0), (0, 0, 0), 1, 1e-4, 1e30, 1.3),    # from inside
        ((0.3, 0, 0), (-4, 0, 0), (0, 0, 0), 1, 1e-4, 1e30, 0.325),  # from inside, dir of length 4
        ((0, 0, 0), (0, 0, 1), (0, 0, -5), 1, 1e-4, 1e30, -1.0),     # sphere behind the ray
        ((0, 0, 0), (0, 0, -1), (0, 0, -5), 1, 1e-4, 3.0, -1.0),     # both roots beyond t_max
        ((0, 0, 0), (0, 0, -1), (0, 0, -5), 1, 1e-4, 4.5, 4.0),      # near root below t_max
        ((0, 0, 0), (0, 0, -1), (0, 0, -5), 1, 4.5, 1e30, 6.0),      # near root below t_min: the far one
        ((0, 0, 0), (0, 0, -1), (0, 0, -5), 1, 6.5, 1e30, -1.0),     # both roots below t_min
        ((0, 0, 0), (0, 0, -1), (0, 0, -5), 1, 4.5, 5.5, -1.0),      # roots either side of the range
        ((1, 0, 0), (1, 0, 0), (0, 0, 0), 1, 1e-4, 1e30, -1.0),      # on the surface, leaving
        ((1, 0, 0), (-1, 0, 0), (0, 0, 0), 1, 1e-4, 1e30, 2.0),      # on the surface, entering
        ((0, 0, 0), (0, 0, -1), (0, 0, -5), 2, 1e-4, 1e30, 3.0),     # a bigger sphere
        # Both bounds strict, with roots that every stable formula computes exactly (powers of two; sqrt of 1, 4, 16):
        ((1, 0, 0), (1, 0, 0), (0, 0, 0), 1, 0.0, 1e30, -1.0),       # on the surface, leaving: root 0 is not > t_min 0
        ((1, 0, 0), (-1, 0, 0), (0, 0, 0), 1, 0.0, 1e30, 2.0),       # on the surface, entering: not 0, the far root
        ((0, 0, 0), (0, 0, -1), (0, 0, -4), 2, 3.0, 6.0, -1.0),      # the far root 6 exactly on t_max: no hit
        ((0, 0, 0), (0, 0, -1), (0, 0, -4), 2, 3.0, 6.5, 6.0),       # ... and just inside it
    ]
    o, d, c = (_f32([case[k] for case in cases]) for k in range(3))
    r, t_min, t_max, expected = (_f32([case[k] for case in cases]) for k in range(3, 7))
    got = run_hit(language, include_dir, o, d, c, r, t_min, t_max)
    return _compare_hits("edges", got, expected, o, d, c, r, t_min, t_max)


def check_hit_far(language: str, include_dir: Path) -> str | None:
    rows = []
    for distance in (1e4, 3e4):
        for radius in (1.0, 0.5):
            for offset in (0.0, 0.3, 0.6, 0.9, 1.1):  # × radius, perpendicular to the ray
                for length in (1.0, 7.0):
                    rows.append((distance, radius, offset, length))
    dist, rad, off, length = (np.array(col, np.float64) for col in zip(*rows, strict=True))
    axis = np.array([0.48, 0.6, -0.64])  # unit
    side = np.array([0.8, -0.6, 0.0])    # unit, perpendicular to axis
    c = dist[:, None] * axis + (off * rad)[:, None] * side
    o = np.zeros_like(c)
    d = length[:, None] * axis
    o, d, c, r = _f32(o), _f32(d), _f32(c), _f32(rad)
    t_min, t_max = np.full(len(o), 1e-4), np.full(len(o), 1e30)
    expected, _ = hit_sphere_np(o, d, c, r, t_min, t_max)
    got = run_hit(language, include_dir, o, d, c, r, t_min, t_max)
    return _compare_hits("far", got, expected, o, d, c, r, t_min, t_max)


def check_hit_huge(language: str, include_dir: Path) -> str | None:
    rows = []
    for radius in (1e3, 1e4, 1e5):
        for height in (0.5, 2.0):
            for angle in (-90.0, -60.0, -30.0, -10.0, 10.0):  # degrees below (< 0) or above the horizon
                rows.append((radius, height, angle))
    rad, h, ang = (np.array(col, np.float64) for col in zip(*rows, strict=True))
    c = np.c_[np.zeros(len(rad)), -(rad + h), np.zeros(len(rad))]
    a = np.radians(ang)
    d = np.c_[np.cos(a) * 0.6, np.sin(a), np.cos(a) * 0.8]
    o = np.zeros_like(c)
    o, d, c, r = _f32(o), _f32(d), _f32(c), _f32(rad)
    t_min, t_max = np.full(len(o), 1e-4), np.full(len(o), 1e30)
    expected, _ = hit_sphere_np(o, d, c, r, t_min, t_max)
    got = run_hit(language, include_dir, o, d, c, r, t_min, t_max)
    return _compare_hits("huge", got, expected, o, d, c, r, t_min, t_max)


# --- scatter_dielectric checks ---------------------------------------------------------------------------------
def _unit(v):
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def check_scatter_random(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(29)
    n = 800
    normal = _unit(rng.normal(size=(n, 3)))
    d = _unit(rng.normal(size=(n, 3))) * 10.0 ** rng.uniform(-3.0, 3.0, (n, 1))
    ior = rng.uniform(1.05, 2.5, n)
    u = rng.random(n)
    d, normal, ior, u = _f32(d), _f32(normal), _f32(ior), _f32(u)
    expected, margin = scatter_np(d, normal, ior, u)
    keep = (margin > 1e-4) & (np.abs(np.sum(_unit(d) * normal, axis=1)) > 1e-3)
    d, normal, ior, u, expected = (x[keep] for x in (d, normal, ior, u, expected))
    got = run_scatter(language, include_dir, d, normal, ior, u)
    return _compare_dirs("scatter", got, expected, d, normal, ior, u)


def _tilted(cos_angles, rng, entering: bool):
    """Unit directions making angle arccos(cos) with -normal (entering) or +normal (leaving), random normals."""
    k = len(cos_angles)
    normal = _unit(rng.normal(size=(k, 3)))
    side = _unit(np.cross(normal, rng.normal(size=(k, 3))))
    sin = np.sqrt(1.0 - cos_angles ** 2)
    along = -normal if entering else normal
    return cos_angles[:, None] * along + sin[:, None] * side, normal


def check_scatter_tir(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(31)
    cos = np.repeat([0.05, 0.3, 0.6, 0.7], 3)  # ior 1.5: the critical angle has cos 0.745
    d, normal = _tilted(cos, rng, entering=False)
    u = np.tile([0.0, 0.5, 0.9999], 4)
    d, normal, u = _f32(d), _f32(normal), _f32(u)
    expected, _ = scatter_np(d, normal, 1.5, u)
    got = run_scatter(language, include_dir, d, normal, 1.5, u)
    return _compare_dirs("tir", got, expected, d, normal, 1.5, u)


def check_scatter_grazing(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(37)
    cos = np.array([0.0, 1e-4, 1e-3, 1e-2, 0.0, 1e-3])
    d, normal = _tilted(cos, rng, entering=True)
    d[4:] *= 250.0  # not unit length
    ior = np.array([1.5, 1.5, 1.33, 2.4, 1.5, 1.5])
    u = np.full(len(d), 0.5)
    d, normal, ior, u = _f32(d), _f32(normal), _f32(ior), _f32(u)
    expected, _ = scatter_np(d, normal, ior, u)
    got = run_scatter(language, include_dir, d, normal, ior, u)
    return _compare_dirs("grazing", got, expected, d, normal, ior, u)


def check_scatter_ior1(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(41)
    cos = np.tile([1.0, 0.9, 0.6, 0.35], 2)
    d_in, n_in = _tilted(cos, rng, entering=True)
    d_out, n_out = _tilted(cos, rng, entering=False)
    d, normal = np.r_[d_in, d_out] * 3.0, np.r_[n_in, n_out]
    u = np.tile([0.5, 0.99], 8)
    d, normal, u = _f32(d), _f32(normal), _f32(u)
    expected = _unit(d)  # straight through
    got = run_scatter(language, include_dir, d, normal, 1.0, u)
    return _compare_dirs("ior1", got, expected, d, normal, 1.0, u)


HIT_CHECKS: dict[str, Callable[[str, Path], str | None]] = {
    "random": check_hit_random, "edges": check_hit_edges, "far": check_hit_far, "huge": check_hit_huge}
SCATTER_CHECKS: dict[str, Callable[[str, Path], str | None]] = {
    "random": check_scatter_random, "tir": check_scatter_tir, "grazing": check_scatter_grazing,
    "ior1": check_scatter_ior1}


def _grade(checks: dict, name: str, impl, backend: str, file: str) -> None:
    grade(checks[name], impl, backend, file)


@pytest.mark.exercise("hit_sphere")
def test_hit_sphere_matches_numpy_on_random_rays(impl, backend):
    _grade(HIT_CHECKS, "random", impl, backend, "ray_sphere")


@pytest.mark.exercise("hit_sphere")
def test_hit_sphere_tangent_inside_behind_and_range(impl, backend):
    _grade(HIT_CHECKS, "edges", impl, backend, "ray_sphere")


@pytest.mark.exercise("hit_sphere")
def test_hit_sphere_far_sphere_is_stable(impl, backend):
    _grade(HIT_CHECKS, "far", impl, backend, "ray_sphere")


@pytest.mark.exercise("hit_sphere")
def test_hit_sphere_huge_sphere(impl, backend):
    _grade(HIT_CHECKS, "huge", impl, backend, "ray_sphere")


@pytest.mark.exercise("scatter_dielectric")
def test_scatter_matches_numpy_on_random_rays(impl, backend):
    _grade(SCATTER_CHECKS, "random", impl, backend, "dielectric")


@pytest.mark.exercise("scatter_dielectric")
def test_scatter_total_internal_reflection(impl, backend):
    _grade(SCATTER_CHECKS, "tir", impl, backend, "dielectric")


@pytest.mark.exercise("scatter_dielectric")
def test_scatter_grazing_incidence_reflects(impl, backend):
    _grade(SCATTER_CHECKS, "grazing", impl, backend, "dielectric")


@pytest.mark.exercise("scatter_dielectric")
def test_scatter_ior_one_goes_straight_through(impl, backend):
    _grade(SCATTER_CHECKS, "ior1", impl, backend, "dielectric")
