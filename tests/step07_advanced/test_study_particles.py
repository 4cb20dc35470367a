"""The particle time-step study (``step07_advanced.showcase.study_particles``): not graded.

The error of the numpy twin and of the OpenGL and WebGPU kernels (reference solution) against the exact projectile
is float32 rounding only (under 1e-3 m, under 1 % of semi-implicit Euler's ``|g| dt t / 2``) at every step.
"""

from __future__ import annotations

import pytest
from cli_checks import check_help_only_prints_help, run_study

from step07_advanced.showcase import study_particles as study


@pytest.mark.parametrize("backend", study.BACKENDS)
def test_the_error_is_rounding_only_at_every_step(backend):
    state = study.launch_state(64)
    runner = study.open_runner(backend, state)
    try:
        rows = [study.measure(runner, state, dt, 1.0, repeats=1) for dt in (1 / 15, 1 / 60)]
    finally:
        runner.release()
    for row in rows:
        assert row["max_error_m"] <= min(1e-3, 0.01 * row["semi_implicit_error_m"]), row


def test_main_writes_json_table_and_plot(tmp_path):
    args = ["--out", str(tmp_path), "--quick", "--backends", "numpy", "--particles", "16", "--repeats", "1"]
    result, table = run_study(study.main, args, tmp_path, study.STEM)
    assert [r["backend"] for r in result["rows"]] == ["numpy"] * len(study.QUICK_DTS)
    assert "| backend |" in table


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    check_help_only_prints_help(study.main, tmp_path, capsys, monkeypatch)
