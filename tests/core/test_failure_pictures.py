"""A failed picture comparison saves what the student needs to see it: the picture drawn, the expected one, their
difference (amplified) and the three side by side, in the folder its message names.

The comparisons are forced to fail on small made-up pictures (a red square where a blue one was expected); the
pictures are read back and checked pixel by pixel.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from light_reference import assert_near_reference
from PIL import Image

from gandalf_tools import testing


def _pictures() -> tuple[np.ndarray, np.ndarray]:
    expected = np.zeros((16, 24, 4), np.uint8)
    expected[..., 2:] = 255  # blue
    got = expected.copy()
    got[4:12, 6:18] = (255, 0, 0, 255)  # a red square
    return got, expected


def _saved(message: str, folder: Path) -> dict[str, np.ndarray]:
    shown = re.search(r"(\S+)-\*\.png", message)
    assert shown, f"the message names no pictures: {message}"
    prefix = Path(shown.group(1))
    assert prefix.parent == folder, message
    return {kind: np.asarray(Image.open(f"{prefix}-{kind}.png").convert("RGBA"))
            for kind in ("actual", "expected", "diff", "side-by-side")}


def test_a_failed_comparison_writes_got_expected_diff_and_side_by_side(tmp_path, monkeypatch):
    monkeypatch.setattr(testing, "FAILURE_DIR", tmp_path)
    got, expected = _pictures()
    with pytest.raises(AssertionError) as failure:
        testing.compare_images(got, expected, "forced", min_psnr=40.0)
    pictures = _saved(str(failure.value), tmp_path)
    assert (pictures["actual"] == got).all() and (pictures["expected"] == expected).all()
    diff = pictures["diff"][..., :3]
    assert (diff[4:12, 6:18] == (255, 0, 255)).all() and not diff[:4].any()  # where they differ, and only there
    side = pictures["side-by-side"]
    assert side.shape == (16, 3 * 24 + 8, 4)
    assert (side[:, :24, :3] == expected[..., :3]).all() and (side[:, 28:52, :3] == got[..., :3]).all()


def test_an_agreeing_comparison_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.setattr(testing, "FAILURE_DIR", tmp_path)
    got, _ = _pictures()
    testing.compare_images(got, got.copy(), "same")
    assert not list(tmp_path.iterdir())


def test_a_reference_check_names_the_case_and_saves_its_pictures(tmp_path, monkeypatch):
    """The shading exercises' check (a picture against a numpy reference over a mask), named after the test."""
    monkeypatch.setattr(testing, "FAILURE_DIR", tmp_path)
    got, expected = _pictures()
    with pytest.raises(AssertionError) as failure:
        assert_near_reference(got, expected[..., :3].astype(np.float64), np.ones(got.shape[:2], bool), "a forced case")
    message = str(failure.value)
    assert message.startswith("for a forced case: worst pixel (x 6, y 4) got [255, 0, 0], expected [0, 0, 255]")
    assert f"; pictures in {tmp_path}/; " in message  # the files are named after the test
    name = "test_a_reference_check_names_the_case_and_saves_its_pictures"
    pictures = _saved(f"{tmp_path / name}-*.png", tmp_path)
    assert (pictures["actual"] == got).all() and (pictures["expected"] == expected).all()
