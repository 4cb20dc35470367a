"""The tour's verdict on each OpenGL/WebGPU pair: within the part's stated bound, or a named difference.

CI runs the tour headless; it exits with 1 when a pair differs beyond its bound (``gandalf_tools.tour``'s
``AGREEMENT`` and ``AGREEMENT_BY_PART``). Here the verdict itself is checked on made pictures: identical, a
scattering of one-pixel differences (within), and one wrong square (named, with where it is).
"""

from __future__ import annotations

import numpy as np
from PIL import Image

from gandalf_tools import tour


def _pair(tmp_path, change):
    rng = np.random.default_rng(7)
    a = rng.integers(0, 256, size=(120, 160, 4), dtype=np.uint8)
    a[..., 3] = 255
    b = a.copy()
    change(b)
    paths = tmp_path / "a.png", tmp_path / "b.png"
    for path, image in zip(paths, (a, b)):
        Image.fromarray(image, "RGBA").save(path)
    return paths


def test_identical_pictures_agree(tmp_path):
    assert tour._agreement("step01_window", *_pair(tmp_path, lambda b: None)) == ("identical", [])


def test_a_few_stray_pixels_are_within_the_bound(tmp_path):
    def stray(b):
        b[10, 20, :3] = 255 - b[10, 20, :3]  # one pixel far off, as an edge covered differently

    verdict, problems = tour._agreement("step01_window", *_pair(tmp_path, stray))
    assert not problems and "within the bound" in verdict


def test_a_wrong_region_is_named(tmp_path):
    def wrong(b):
        b[40:56, 64:96, :3] = 0  # a face drawn black

    verdict, problems = tour._agreement("step01_window", *_pair(tmp_path, wrong))
    assert problems and verdict.split(": ", 1)[1].startswith("DIFFERENT") and "square at pixel" in verdict


def test_at_another_size_the_difference_is_reported_not_judged(tmp_path):
    """The bounds are stated for the tour's default size; a smaller picture reads coarser mip levels, where
    implementations legally differ more: the figures are printed, and the tour does not fail on them."""
    def wrong(b):
        b[40:56, 64:96, :3] = 0

    verdict, problems = tour._agreement("step01_window", *_pair(tmp_path, wrong), judged=False)
    assert problems and "not judged at this size" in verdict and "DIFFERENT" not in verdict
    assert tour.main(["--headless", "--out", str(tmp_path / "out"), "--steps", "step01_window", "--size", "64x48",
                      "--frames", "1"]) == 0


def test_the_terrain_has_its_own_bound():
    assert tour.AGREEMENT_BY_PART["step07_advanced.terrain"].share < tour.AGREEMENT.share
