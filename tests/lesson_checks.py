"""The check every plain-API lesson's tests share: its command line writes one PNG of the asked size, and
``--help`` only prints help."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

import pytest
from PIL import Image


def check_main_writes_a_png_and_help_only_helps(module: ModuleType, tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    """``module.main`` writes ``--out`` at ``--size`` 32x24 and nothing else; ``--help`` exits 0 naming ``--out``."""
    out = tmp_path / "frame.png"
    assert module.main(["--out", str(out), "--size", "32x24"]) == 0
    assert Image.open(out).size == (32, 24)
    with pytest.raises(SystemExit) as exit_info:
        module.main(["--help"])
    assert exit_info.value.code == 0
    assert "--out" in capsys.readouterr().out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frame.png"]
