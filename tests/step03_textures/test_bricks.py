"""Grades exercise 1, ``brick_texture``: mortar and brick texels, the half-brick offset, per-brick colour,
seamless tiling, argument checks, and the texture drawn on a quad in both APIs."""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core import Scene, TransformComponent
from gandalf_core.components import MaterialComponent, MeshComponent
from gandalf_core.resources import MaterialData, TextureData, quad
from step03_textures.scene import SHADER

BRICK = (0.62, 0.27, 0.18)
MORTAR = (0.80, 0.78, 0.72)
# Colours are stored as round(255 * c): one 8-bit step of rounding.
BYTE = 1


def _bytes(colour) -> np.ndarray:
    return np.round(np.asarray(colour) * 255).astype(int)


def _mortar_mask(w: int, h: int, bw: int, bh: int, m: int) -> np.ndarray:
    """The mortar texels by the rules of the exercise, written as plain loops (independent of the solution)."""
    mask = np.zeros((h, w), dtype=bool)
    for y in range(h):
        shift = bw // 2 if (y // bh) % 2 else 0
        for x in range(w):
            mask[y, x] = y % bh < m or (x - shift) % bw < m
    return mask


def _texels(tex: TextureData) -> np.ndarray:
    return tex.pixels[..., :3].astype(int)


@pytest.mark.exercise("brick_texture")
@pytest.mark.parametrize(
    "size,brick,mortar", [((64, 32), (16, 8), 1), ((128, 64), (32, 16), 2), ((50, 30), (12, 7), 3)]
)
def test_mortar_and_bricks_are_where_the_rules_put_them(impl, size, brick, mortar):
    w, h = size
    tex = impl.brick_texture(w, h, brick_size=brick, mortar=mortar, brick_color=BRICK, mortar_color=MORTAR,
                             variation=0.0, seed=1)
    assert isinstance(tex, TextureData)
    assert (tex.width, tex.height) == (w, h)
    mask = _mortar_mask(w, h, *brick, mortar)
    texels = _texels(tex)
    assert np.abs(texels[mask] - _bytes(MORTAR)).max() <= BYTE
    assert np.abs(texels[~mask] - _bytes(BRICK)).max() <= BYTE  # variation 0: every brick is brick_color
    assert (tex.pixels[..., 3] == 255).all()


@pytest.mark.exercise("brick_texture")
def test_odd_courses_are_offset_by_half_a_brick(impl):
    tex = impl.brick_texture(64, 32, brick_size=(16, 8), mortar=2, brick_color=BRICK, mortar_color=MORTAR,
                             variation=0.0)
    texels = _texels(tex)
    is_mortar = np.all(np.abs(texels - _bytes(MORTAR)) <= BYTE, axis=-1)
    mid_even, mid_odd = 5, 13  # a texel row inside course 0 and one inside course 1
    assert np.flatnonzero(is_mortar[mid_even]).tolist() == [x for x in range(64) if x % 16 < 2]
    assert np.flatnonzero(is_mortar[mid_odd]).tolist() == [x for x in range(64) if (x - 8) % 16 < 2]
    assert is_mortar[0].all() and is_mortar[9].all() and not is_mortar[2].all()  # bed joints on top of courses


@pytest.mark.exercise("brick_texture")
def test_each_brick_has_one_colour_within_the_variation(impl):
    w, h, bw, bh, m, var = 96, 48, 24, 12, 2, 0.2
    tex = impl.brick_texture(w, h, brick_size=(bw, bh), mortar=m, brick_color=BRICK, mortar_color=MORTAR,
                             variation=var, seed=7)
    texels = _texels(tex)
    colours = set()
    for course in range(h // bh):
        shift = bw // 2 if course % 2 else 0
        for column in range(w // bw):
            # The inside of one brick (away from the wrap edge for odd courses).
            x0 = shift + column * bw + m
            xs = np.arange(x0, x0 + bw - m) % w
            block = texels[course * bh + m:(course + 1) * bh][:, xs]
            first = block[0, 0]
            assert (np.abs(block - first) <= 0).all(), f"brick ({course}, {column}) is not one colour"
            lo = _bytes(np.asarray(BRICK) * (1 - var)) - BYTE
            hi = _bytes(np.asarray(BRICK) * (1 + var)) + BYTE
            assert ((first >= lo) & (first <= hi)).all(), f"brick ({course}, {column}) = {first} outside {lo}..{hi}"
            colours.add(tuple(first))
    assert len(colours) >= 8, "bricks should vary in colour"


@pytest.mark.exercise("brick_texture")
def test_same_seed_same_texture_other_seed_other_colours(impl):
    a = impl.brick_texture(64, 32, brick_size=(16, 8), variation=0.15, seed=5)
    b = impl.brick_texture(64, 32, brick_size=(16, 8), variation=0.15, seed=5)
    c = impl.brick_texture(64, 32, brick_size=(16, 8), variation=0.15, seed=6)
    assert np.array_equal(a.pixels, b.pixels)
    assert not np.array_equal(a.pixels, c.pixels)


@pytest.mark.exercise("brick_texture")
@pytest.mark.parametrize("size,brick", [((64, 32), (16, 8)), ((96, 48), (24, 12)), ((60, 28), (15, 7))])
def test_the_texture_tiles_seamlessly(impl, size, brick):
    w, h = size
    bw, bh = brick
    tex = impl.brick_texture(w, h, brick_size=brick, mortar=2, variation=0.2, seed=2)
    tiled = np.tile(_texels(tex), (2, 2, 1))
    # The 2x2 tiling has mortar exactly where one big wall would have it ...
    is_mortar = np.all(np.abs(tiled - _bytes(MORTAR)) <= BYTE, axis=-1)
    assert np.array_equal(is_mortar, _mortar_mask(2 * w, 2 * h, bw, bh, 2))
    # ... and the brick cut by the right edge of an odd course continues at the left edge in the same colour.
    for course in range(1, h // bh, 2):
        y = course * bh + bh // 2
        left, right = tiled[y, w - 1], tiled[y, w]  # across the seam between two tiles
        assert np.array_equal(left, right), f"course {course}: {left} | {right} across the seam"


@pytest.mark.exercise("brick_texture")
def test_settings_reach_the_texture(impl):
    tex = impl.brick_texture(32, 16, brick_size=(16, 8), filter="nearest", mipmaps=False, wrap="clamp")
    assert (tex.filter, tex.mipmaps, tex.wrap, tex.name) == ("nearest", False, "clamp", "bricks")
    assert impl.brick_texture(32, 16, brick_size=(16, 8), name="wall").name == "wall"


@pytest.mark.exercise("brick_texture")
@pytest.mark.parametrize("kwargs,word", [
    ({"width": 0}, "width"), ({"height": 2.5}, "height"), ({"brick_size": (0, 8)}, "brick_size"),
    ({"mortar": -1}, "mortar"), ({"mortar": 8}, "mortar"), ({"variation": 1.5}, "variation"),
    ({"variation": -0.1}, "variation"), ({"variation": float("nan")}, "variation"),
    ({"brick_color": (1.0, 0.2)}, "brick_color"), ({"mortar_color": (2.0, 0.0, 0.0)}, "mortar_color"),
])
def test_bad_arguments_raise_value_errors_naming_them(impl, kwargs, word):
    args = {"width": 32, "height": 16, "brick_size": (16, 8), "mortar": 1, **kwargs}
    with pytest.raises(ValueError, match=word):
        impl.brick_texture(**args)


@pytest.mark.exercise("brick_texture")
def test_bricks_on_a_quad_sample_the_right_texels(impl, backend, render_scene):
    # A full-screen quad (no camera: positions are clip space) and one texel per pixel, sampled with "nearest":
    # pixel (x, y) reads texel (x, y), so the picture is the texture, the right way up, in both APIs.
    w, h, bw, bh, m = 64, 32, 16, 8, 2
    tex = impl.brick_texture(w, h, brick_size=(bw, bh), mortar=m, brick_color=BRICK, mortar_color=MORTAR,
                             variation=0.1, seed=4, filter="nearest", mipmaps=False)
    scene = Scene("bricks on a quad")
    scene.assets.texture("bricks", tex)
    scene.assets.mesh("quad", quad(2.0))
    scene.assets.material("M", MaterialData(SHADER, ["bricks"], color=(1.0, 1.0, 1.0)))
    scene.create_entity(TransformComponent(), MeshComponent("quad"), MaterialComponent("M"))
    image, _ = render_scene(backend, scene, w, h)
    rgb = image[..., :3].astype(int)
    # Chosen points: mortar at the top-left corner, inside the first brick, a head joint of the offset course.
    assert np.abs(rgb[0, 0] - _bytes(MORTAR)).max() <= BYTE
    assert np.abs(rgb[bh + bh // 2, bw // 2] - _bytes(MORTAR)).max() <= BYTE
    assert np.abs(rgb[bh + bh // 2, 0] - _bytes(MORTAR)).max() > 20  # course 1 has no joint at x = 0
    inside = rgb[m + 2, m + 2]
    assert np.all(np.abs(inside - _bytes(BRICK)) <= _bytes(np.asarray(BRICK) * 0.1) + BYTE)
    # The whole picture: decoding sRGB to linear and encoding it again may move a value by one step.
    assert np.abs(rgb - _texels(tex)).max() <= BYTE


@pytest.mark.exercise("brick_texture")
def test_bricks_come_out_both_darker_and_lighter(impl):
    """The factor is drawn "uniformly from [1 - variation, 1 + variation]": about half the bricks darker than
    brick_color and half lighter (with 512 bricks, each side must hold at least 30 %)."""
    w, h, bw, bh, m = 256, 256, 16, 8, 1
    tex = impl.brick_texture(w, h, brick_size=(bw, bh), mortar=m, brick_color=BRICK, mortar_color=MORTAR,
                             variation=0.2, seed=11)
    texels = _texels(tex).astype(int)
    base = _bytes(BRICK).astype(int)
    darker = lighter = 0
    for course in range(h // bh):
        shift = bw // 2 if course % 2 else 0
        for column in range(w // bw):
            x = (shift + column * bw + m + (bw - m) // 2) % w
            y = course * bh + m + (bh - m) // 2
            brick = texels[y, x, :3]
            darker += int((brick < base[:3]).all())
            lighter += int((brick > base[:3]).all())
    total = (h // bh) * (w // bw)
    assert darker >= 0.3 * total and lighter >= 0.3 * total, (
        f"of {total} bricks {darker} are darker and {lighter} lighter than brick_color {tuple(base[:3])}: "
        "draw the factor from [1 - variation, 1 + variation], both sides of 1")


@pytest.mark.exercise("brick_texture")
def test_bright_bricks_are_clipped_to_one(impl):
    """The stub's rule "clip to [0, 1]": a bright brick colour times a factor up to 1.5 goes past 1 in some bricks;
    those channels are 1 (255), every other texel stays within brick_color · [1 - variation, 1 + variation]."""
    bright, var = (0.95, 0.9, 0.85), 0.5
    tex = impl.brick_texture(64, 32, brick_size=(16, 8), mortar=1, brick_color=bright, mortar_color=MORTAR,
                             variation=var, seed=3)
    texels = _texels(tex)
    bricks = texels[~_mortar_mask(64, 32, 16, 8, 1)]
    lo = _bytes(np.asarray(bright) * (1 - var)) - BYTE
    hi = np.minimum(_bytes(np.asarray(bright) * (1 + var)) + BYTE, 255)
    assert ((bricks >= lo) & (bricks <= hi)).all(), f"brick texels outside {lo.tolist()}..{hi.tolist()}"
    assert (bricks == 255).any(), (
        f"brick_color {bright} with variation {var}: no brick reaches 255, but factors above 1.06 must clip to 1")
