"""The clamp study (``step07_advanced.showcase.study_clamps``, not graded): its reference and its claims.

The float64 reference energy does not depend on the roughness for narrow lobes (∫ D dω = 1) and a broad lobe's
one-sample image matches it (roughness 0.3: within 1e-3); a lobe narrower than a pixel loses its energy at one
sample unless a clamp or supersampling widens it; without the cosine clamp bent normals make NaN or negative
pixels, with it none.
"""

from __future__ import annotations

import json

import pytest

from step07_advanced.showcase import study_clamps as study


def test_the_reference_and_the_one_sample_image_agree_where_the_lobe_is_wide():
    wide = study.reference_energy(0.3)
    assert study.reference_energy(0.005) == pytest.approx(study.reference_energy(0.02), rel=1e-3)
    assert study.rendered_energy(0.3, 0.045)[0] == pytest.approx(wide, rel=1e-3)
    narrow = study.reference_energy(0.005)
    assert study.rendered_energy(0.005, 0.0)[0] < 0.1 * narrow  # missed between the pixel centres
    assert study.rendered_energy(0.005, 0.12)[0] == pytest.approx(narrow, rel=0.02)  # widened: energy kept


def test_the_cosine_clamp_removes_the_bad_pixels():
    rows = {r["cosine_clamp"]: r for r in study.cosine_rows((0.0, 1e-4))}
    assert rows[0.0]["bad_pixels"] > 100 and rows[1e-4]["bad_pixels"] == 0
    assert rows[1e-4]["error"] < 0.01


def test_main_writes_the_tables_with_the_machine(tmp_path):
    study.main(["--out", str(tmp_path), "--quick", "--repeats", "1"])
    result = json.loads((tmp_path / f"{study.STEM}.json").read_text())
    assert len(result["roughness_rows"]) == 3 * (2 + 1) and "cores" in result["machine"]
    assert "Measured on" in (tmp_path / f"{study.STEM}.md").read_text()
