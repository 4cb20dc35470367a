"""Exercise ``explode_offset`` (step07 explode): the student's GLSL and WGSL function, run on the GPU through the
shader harness (a compute shader per language) and compared with the float64 numpy reference
``step07_advanced.explode.scene.explode_offset_np`` on the same float32-rounded inputs.

Tolerances (absolute, per component): random triangles and times ≤ 1e-4 · amount + 1e-6; zero offset at rest
≤ 1e-5 · amount; the peak offset ``amount · n`` ≤ 1e-4 · amount. Degenerate triangles must give exactly finite
values of size ≤ 1e-6 · amount. The reference solution measures at most about 2e-6 · amount on llvmpipe and
lavapipe. The rules are the ones the stub's comments state; every check also runs on a set of plausible wrong
implementations (mutants, in ``test_explode_mutants.py``), each of which must fail at least one of them.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from shader_checks import grade
from shader_harness import evaluate, gl_context

from step07_advanced.explode.scene import explode_offset_np, face_normals_np

EXPRESSION = {
    "glsl": "vec4(explode_offset(p0.xyz, p1.xyz, p2.xyz, t, amount, period), 0.0)",
    "wgsl": "vec4<f32>(explode_offset(p0.xyz, p1.xyz, p2.xyz, t, amount, period), 0.0)",
}
HINT = {
    "random": "offset = amount * (1 - cos(2*pi*t/period)) / 2 * normalize(cross(p1 - p0, p2 - p0)) (radians)",
    "rest": "(1 - cos(2*pi*t/period)) / 2 is 0 at t = 0 and at whole periods and 1 at half a period",
    "winding": "n = cross(p1 - p0, p2 - p0): counter-clockwise seen from the front points towards the viewer",
    "degenerate": "a zero-area triangle has no normal: return vec3(0.0), never normalize a zero vector",
    "scale": "divide both edges by their largest absolute component before the cross product",
}


def run_offsets(language: str, include_dir: Path, p0, p1, p2, t, amount, period) -> np.ndarray:
    """explode_offset(...) per row on the GPU, as an (n, 3) float32 array."""
    n = len(p0)

    def vec4(p):
        return np.c_[np.asarray(p, np.float32).reshape(n, 3), np.zeros(n, np.float32)]

    def f32(x):
        return np.broadcast_to(np.asarray(x, np.float32), (n,))

    inputs = {"p0": ("vec4", vec4(p0)), "p1": ("vec4", vec4(p1)), "p2": ("vec4", vec4(p2)),
              "t": ("f32", f32(t)), "amount": ("f32", f32(amount)), "period": ("f32", f32(period))}
    prelude = f'#include "explode.{language}"'
    if language == "glsl":
        # Another context (an app's, or the WebGPU device's) may be current on this thread: make the harness's
        # own context current for the call.
        with gl_context():
            out = evaluate(language, prelude, EXPRESSION[language], inputs, "vec4", include_dirs=[include_dir])
    else:
        out = evaluate(language, prelude, EXPRESSION[language], inputs, "vec4", include_dirs=[include_dir])
    return out[:, :3]


def _rounded(*arrays):
    """float32-rounded float64 copies: the reference sees exactly the numbers the shader sees."""
    return [np.asarray(a, np.float32).astype(np.float64) for a in arrays]


def _compare(kind: str, got: np.ndarray, expected: np.ndarray, tolerance: np.ndarray, inputs: dict) -> str | None:
    """None when ``got`` matches; else a message with the worst case's inputs, expected, got and a hint."""
    bad_finite = ~np.all(np.isfinite(got), axis=1)
    error = np.where(bad_finite, np.inf, np.abs(np.nan_to_num(got) - expected).max(axis=1))
    worst = int(np.argmax(error - tolerance))
    if error[worst] <= tolerance[worst]:
        return None
    case = ", ".join(f"{k}={np.round(np.asarray(v)[worst] if np.ndim(v) else v, 6).tolist()}" for k, v in
                     inputs.items())
    return (f"{kind}: {int(np.sum(error > tolerance))} of {len(got)} cases wrong; e.g. {case}: expected "
            f"{np.round(expected[worst], 6).tolist()}, got {got[worst].tolist()} (tolerance {tolerance[worst]:.2g})."
            f" Hint: {HINT[kind]}")


# --- the checks (each returns None or a failure message; the graded tests and the mutant test share them) ---
def check_random(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(7)
    n = 512
    scale = 10.0 ** rng.uniform(-1.5, 1.5, (n, 1))
    centre = rng.normal(0.0, 3.0, (n, 3))
    p0, p1, p2 = (centre + scale * rng.normal(0.0, 1.0, (n, 3)) for _ in range(3))
    period = rng.uniform(0.5, 5.0, n)
    t = rng.uniform(-2.0, 3.0, n) * period
    amount = rng.uniform(0.1, 2.0, n)
    p0, p1, p2, t, amount, period = _rounded(p0, p1, p2, t, amount, period)
    # Keep well-shaped triangles: the float32 normal of a sliver is not precise enough to grade at 1e-4.
    e1, e2 = p1 - p0, p2 - p0
    sine = np.linalg.norm(np.cross(e1, e2), axis=1) / (np.linalg.norm(e1, axis=1) * np.linalg.norm(e2, axis=1))
    keep = sine > 0.05
    p0, p1, p2, t, amount, period = (a[keep] for a in (p0, p1, p2, t, amount, period))
    got = run_offsets(language, include_dir, p0, p1, p2, t, amount, period)
    expected = explode_offset_np(p0, p1, p2, t, amount, period)
    return _compare("random", got, expected, 1e-4 * amount + 1e-6,
                    {"p0": p0, "p1": p1, "p2": p2, "t": t, "amount": amount, "period": period})


def _unit_triangles() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(3)
    p0 = rng.normal(0.0, 1.0, (6, 3))
    return p0, p0 + rng.normal(0.0, 1.0, (6, 3)), p0 + rng.normal(0.0, 1.0, (6, 3))


def check_rest_and_peak(language: str, include_dir: Path) -> str | None:
    base = _unit_triangles()
    period = 2.5
    amount = 0.75
    rest = np.array([0.0, period, -period, 3.0 * period])
    peak = np.array([0.5 * period, -0.5 * period, 1.5 * period, -2.5 * period])
    times = np.concatenate([rest, peak])
    p0, p1, p2 = (np.repeat(p, len(times), axis=0) for p in base)
    t = np.tile(times, len(base[0]))
    p0, p1, p2, t = _rounded(p0, p1, p2, t)
    got = run_offsets(language, include_dir, p0, p1, p2, t, amount, period)
    at_rest = np.isin(t, rest.astype(np.float32))
    expected = np.where(at_rest[:, None], 0.0, amount * face_normals_np(p0, p1, p2))
    tolerance = np.where(at_rest, 1e-5, 1e-4) * amount
    return _compare("rest", got, expected, tolerance, {"p0": p0, "p1": p1, "p2": p2, "t": t, "amount":
                                                        np.full(len(t), amount), "period": np.full(len(t), period)})


def check_periodic(language: str, include_dir: Path) -> str | None:
    base = _unit_triangles()
    period = 1.6
    times = np.array([0.13, 0.41, 0.77, 1.1])
    shifted = np.concatenate([times, times + period, times - period, -times, times - 3.0 * period])
    p0, p1, p2 = (np.repeat(p, len(shifted), axis=0) for p in base)
    t = np.tile(shifted, len(base[0]))
    p0, p1, p2, t = _rounded(p0, p1, p2, t)
    amount = 1.3
    got = run_offsets(language, include_dir, p0, p1, p2, t, amount, period)
    expected = explode_offset_np(p0, p1, p2, t, amount, period)
    return _compare("rest", got, expected, np.full(len(t), 1e-4 * amount + 1e-6),
                    {"p0": p0, "p1": p1, "p2": p2, "t": t, "period": np.full(len(t), period)})


def check_winding(language: str, include_dir: Path) -> str | None:
    # Counter-clockwise seen from +z, +x and +y, then the same corners clockwise (p1 and p2 swapped).
    p0 = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1.0, 2.0, 3.0]])
    p1 = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [2.0, 2.0, 3.0]])
    p2 = np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [1.0, 3.0, 3.0]])
    normals = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    a0, a1, a2 = np.r_[p0, p0], np.r_[p1, p2], np.r_[p2, p1]
    expected_n = np.r_[normals, -normals]
    amount, period = 0.5, 2.0
    got = run_offsets(language, include_dir, a0, a1, a2, 1.0, amount, period)
    return _compare("winding", got, amount * expected_n, np.full(len(a0), 1e-4 * amount),
                    {"p0": a0, "p1": a1, "p2": a2})


def check_degenerate(language: str, include_dir: Path) -> str | None:
    p0 = np.array([[1.0, 2.0, 3.0], [1.0, 2.0, 3.0], [0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [-4.0, 8.0, 2.0],
                   [0.0, 0.0, 0.0]])
    p1 = np.array([[1.0, 2.0, 3.0], [1.0, 2.0, 3.0], [1.0, 1.0, 1.0], [3.0, 2.0, 5.0], [0.0, 8.0, 2.0],
                   [1.0, 0.0, 0.0]])
    p2 = np.array([[1.0, 2.0, 3.0], [5.0, 0.0, 1.0], [2.0, 2.0, 2.0], [5.0, 3.0, 9.0], [-4.0, 8.0, 2.0],
                   [0.0, 1.0, 0.0]])
    # all corners equal, two equal, collinear, collinear, two equal; the last one is a proper triangle
    amount, period = 0.8, 2.0
    got = run_offsets(language, include_dir, p0, p1, p2, 1.0, amount, period)
    expected = np.zeros((len(p0), 3))
    expected[-1] = (0.0, 0.0, amount)
    return _compare("degenerate", got, expected, np.full(len(p0), 1e-6 * amount), {"p0": p0, "p1": p1, "p2": p2})


def check_extreme_scales(language: str, include_dir: Path) -> str | None:
    rng = np.random.default_rng(11)
    shape = rng.normal(0.0, 1.0, (3, 3))
    scales = np.array([1e30, 1e20, 1e19, 1e-19, 1e-20, 1e-30, 1.0])
    p0, p1, p2 = (np.outer(scales, shape[k]) for k in range(3))
    p0, p1, p2 = _rounded(p0, p1, p2)
    amount, period = 1.5, 3.0
    got = run_offsets(language, include_dir, p0, p1, p2, 1.5, amount, period)
    expected = amount * face_normals_np(p0, p1, p2)
    return _compare("scale", got, expected, np.full(len(p0), 1e-4 * amount), {"p0": p0, "p1": p1, "p2": p2})


CHECKS: dict[str, Callable[[str, Path], str | None]] = {
    "random": check_random,
    "rest_and_peak": check_rest_and_peak,
    "periodic": check_periodic,
    "winding": check_winding,
    "degenerate": check_degenerate,
    "extreme_scales": check_extreme_scales,
}


def _grade(name: str, impl, backend: str) -> None:
    grade(CHECKS[name], impl, backend, "explode")


@pytest.mark.exercise("explode_offset")
def test_offset_matches_numpy_on_random_triangles(impl, backend):
    _grade("random", impl, backend)


@pytest.mark.exercise("explode_offset")
def test_offset_is_zero_at_rest_and_amount_at_the_peak(impl, backend):
    _grade("rest_and_peak", impl, backend)


@pytest.mark.exercise("explode_offset")
def test_offset_is_periodic_and_even_in_time(impl, backend):
    _grade("periodic", impl, backend)


@pytest.mark.exercise("explode_offset")
def test_normal_follows_the_winding(impl, backend):
    _grade("winding", impl, backend)


@pytest.mark.exercise("explode_offset")
def test_degenerate_triangles_stay_put(impl, backend):
    _grade("degenerate", impl, backend)


@pytest.mark.exercise("explode_offset")
def test_huge_and_tiny_triangles_neither_overflow_nor_underflow(impl, backend):
    _grade("extreme_scales", impl, backend)
