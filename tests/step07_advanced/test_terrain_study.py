"""The terrain study's figures of merit (not graded): the vertices WebGPU's indirect draw takes, the error · √triangles
that uniform tessellation keeps about constant, and the LOD set against uniform tessellation with as many
triangles."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from gandalf_core.math import look_at, perspective
from step07_advanced.terrain import scene, study
from step07_advanced.terrain.heightfield import quantize
from step07_advanced.terrain.patches import patch_levels


def _error(params):
    eye = np.asarray(scene.EYE, dtype=np.float64)
    view_projection = perspective(scene.FOV, 4 / 3, 0.1, 100.0) @ look_at(eye, scene.TARGET)
    return study.geometric_error(quantize(scene.terrain_heights()), params, eye, view_projection, (160, 120))


def test_the_lod_draws_its_own_vertices_and_is_set_against_uniform_levels():
    params = replace(scene.PARAMS, patches=8, max_level=8.0, lod_scale=12.0)
    _outer, inner = patch_levels(quantize(scene.terrain_heights()), params, np.asarray(scene.EYE, np.float64))
    lod = {"levels": "LOD", **_error(params)}
    assert lod["vertices_drawn"] == int((6 * np.ceil(inner) ** 2).sum()) < 8 * 8 * 6 * 64
    uniform = [{"levels": f"uniform {level}", **_error(replace(params, min_level=level, max_level=level))}
               for level in (1.0, 2.0, 4.0, 8.0)]
    products = [r["pixels_sqrt_triangles"] for r in uniform]
    assert max(products) < 1.5 * min(products), "error · √triangles is about constant for uniform levels"
    table = study.markdown({"backends": [], "rows": [*uniform, lod]})
    assert "| LOD |" in table and "uniform tessellation with as many triangles" in table


def test_the_uniform_error_is_interpolated_log_log():
    rows = [{"triangles": 100, "max_error_pixels": 4.0}, {"triangles": 400, "max_error_pixels": 2.0}]
    assert study.uniform_error_at(rows, 200) == pytest.approx(2.0 * np.sqrt(2.0))
    assert study.uniform_error_at(rows, 50) is None
