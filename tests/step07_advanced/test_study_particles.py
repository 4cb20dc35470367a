"""The particle time-step study (``step07_advanced.showcase.study_particles``): not graded.

The error of the numpy twin and of the OpenGL and WebGPU kernels (reference solution) against the exact projectile
must follow semi-implicit Euler's ``|g| dt t / 2`` within 5 %, and fall as the step shrinks.
"""

from __future__ import annotations

import json

import pytest

from step07_advanced.showcase import study_particles as study


@pytest.mark.parametrize("backend", study.BACKENDS)
def test_error_follows_the_euler_bound_and_falls_with_the_step(backend):
    state = study.launch_state(64)
    runner = study.open_runner(backend, state)
    try:
        rows = [study.measure(runner, state, dt, 1.0, repeats=1) for dt in (1 / 15, 1 / 60)]
    finally:
        runner.release()
    for row in rows:
        assert row["max_error_m"] == pytest.approx(row["predicted_error_m"], rel=0.05), row
    assert rows[0]["max_error_m"] > 3.5 * rows[1]["max_error_m"], rows


def test_main_writes_json_table_and_plot(tmp_path):
    assert study.main(["--out", str(tmp_path), "--quick", "--backends", "numpy", "--particles", "16",
                       "--repeats", "1"]) == 0
    result = json.loads((tmp_path / f"{study.STEM}.json").read_text())
    assert [r["backend"] for r in result["rows"]] == ["numpy"] * len(study.QUICK_DTS)
    assert "| backend |" in (tmp_path / f"{study.STEM}.md").read_text()
    assert (tmp_path / f"{study.STEM}.png").stat().st_size > 1000


def test_help_only_prints_help(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stop:
        study.main(["--help"])
    assert stop.value.code == 0 and "usage:" in capsys.readouterr().out
    assert not any(tmp_path.iterdir()), "--help wrote files"
