"""Correct alternatives of step 06: refraction written with the tangential part, Blinn-Phong's half vector guarded
by its squared length."""

from __future__ import annotations

import numpy as np

from gandalf_tools.grading.fairness import alternative, shader_alternative
from gandalf_tools.grading.mutants import Mutant, patch

STEP = "step06_lighting"
ALTERNATIVES: list[Mutant] = []


@alternative(ALTERNATIVES, STEP, "reflect_refract", "refract-tangential-part",
             "t = eta (i - cos_i n) - sqrt(k) n, written per case with a mask")
def _(pkg):
    def refract(i, n, eta):
        i, n = np.asarray(i, dtype=float), np.asarray(n, dtype=float)
        e = np.asarray(eta, dtype=float)[..., None] if np.ndim(eta) else float(eta)
        cos_i = (n * i).sum(axis=-1, keepdims=True)
        k = 1.0 - e**2 * (1.0 - cos_i**2)
        out = e * (i - cos_i * n) - np.sqrt(np.clip(k, 0.0, None)) * n
        return out * (k >= 0.0)

    patch(pkg, "optics.refract", refract)


@alternative(ALTERNATIVES, STEP, "reflect_refract", "reflect-projection-form",
             "i - 2 (n·i) n written as the projection on n")
def _(pkg):
    def reflect(i, n):
        i, n = np.asarray(i, dtype=float), np.asarray(n, dtype=float)
        along = np.einsum("...k,...k->...", i, n)[..., None] * n
        return (i - along) - along

    patch(pkg, "optics.reflect", reflect)


shader_alternative(ALTERNATIVES, STEP, "blinn_phong", "guard-by-squared-length",
                   "the half vector normalised when dot(h, h) > 1e-12, n otherwise",
                   [("shading.glsl", "h = h_length > 1e-6 ? h / h_length : n;",
                     "h = dot(h, h) > 1e-12 ? normalize(h) : n;"),
                    ("shading.wgsl", "let h = select(n, h_sum / max(h_length, 1e-6), h_length > 1e-6);",
                     "let h = select(n, normalize(h_sum), dot(h_sum, h_sum) > 1e-12);")])
