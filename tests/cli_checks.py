"""Checks the command lines of the plain-API lessons and of the studies share: what they write, and that
``--help`` only prints help."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest
from PIL import Image

Main = Callable[[list[str]], int]


def check_main_writes_a_png_and_help_only_helps(module: ModuleType, tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    """A lesson's ``main`` writes ``--out`` at ``--size`` 32x24, nothing else; ``--help`` exits 0 naming ``--out``."""
    out = tmp_path / "frame.png"
    assert module.main(["--out", str(out), "--size", "32x24"]) == 0
    assert Image.open(out).size == (32, 24)
    with pytest.raises(SystemExit) as exit_info:
        module.main(["--help"])
    assert exit_info.value.code == 0
    assert "--out" in capsys.readouterr().out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frame.png"]


def run_study(main: Main, args: list[str], out: Path, stem: str) -> tuple[dict[str, Any], str]:
    """Run a study's ``main(args)`` (which writes into ``out``): it returns 0 and writes ``stem``.json, .md and a
    plot ``stem``.png of more than 1000 bytes. Returns the JSON and the table."""
    assert main(args) == 0
    assert (out / f"{stem}.png").stat().st_size > 1000
    return json.loads((out / f"{stem}.json").read_text()), (out / f"{stem}.md").read_text()


def check_help_only_prints_help(main: Main, tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                monkeypatch: pytest.MonkeyPatch) -> None:
    """``main(["--help"])`` exits 0 printing the usage, and writes no file into the current folder."""
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stop:
        main(["--help"])
    assert stop.value.code == 0 and "usage:" in capsys.readouterr().out
    assert not any(tmp_path.iterdir()), "--help wrote files"
