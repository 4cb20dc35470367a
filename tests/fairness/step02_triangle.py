"""Correct alternatives of step 02: the interleaved buffer stacked column-wise, the n-gon's corners by repeated
rotation."""

from __future__ import annotations

import numpy as np

from gandalf_tools.grading.fairness import alternative
from gandalf_tools.grading.mutants import Mutant, patch

STEP = "step02_triangle"
ALTERNATIVES: list[Mutant] = []


@alternative(ALTERNATIVES, STEP, "interleave", "hstack", "np.hstack of the two arrays, cast to float32 at the end")
def _(pkg):
    original = pkg.vertex_data.interleave

    def interleave(positions, colors):
        _, layout = original(positions, colors)  # the argument checks and the layout, as the reference makes them
        data = np.hstack([np.asarray(positions, dtype=np.float64), np.asarray(colors, dtype=np.float64)])
        return np.ascontiguousarray(data.astype(np.float32)), layout

    patch(pkg, "vertex_data.interleave", interleave)


@alternative(ALTERNATIVES, STEP, "ngon_mesh", "rotated-corners",
             "each corner is the previous one turned by 2 pi / n (a 2x2 rotation), the centre last in the loop")
def _(pkg):
    original = pkg.ngon.ngon_mesh
    from gandalf_core.resources import MeshData

    def ngon_mesh(sides, radius):
        mesh = original(sides, radius)  # checks and colours as the reference
        n = int(sides)
        turn = 2.0 * np.pi / n
        rotation = np.array([[np.cos(turn), -np.sin(turn)], [np.sin(turn), np.cos(turn)]])
        corner, corners = np.array([float(radius), 0.0]), []
        for _ in range(n):
            corners.append(corner)
            corner = rotation @ corner
        positions = np.zeros((n + 1, 3))
        positions[1:, :2] = corners
        return MeshData(positions=positions, colors=mesh.colors, indices=mesh.indices, name=mesh.name)

    patch(pkg, "ngon.ngon_mesh", ngon_mesh)
