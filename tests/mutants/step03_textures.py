"""Mutants of step 03: ``brick_texture`` and ``cube_cross_uvs``."""

from __future__ import annotations

import numpy as np

from gandalf_core.resources import TextureData
from gandalf_tools.grading.mutants import Mutant, mutant, patch

STEP = "step03_textures"
MUTANTS: list[Mutant] = []


# --- brick_texture ---------------------------------------------------------------------------------


def _bricks(pkg, **slips):
    """Replace brick_texture by the rules of the exercise with one slip; the solution checks the arguments."""
    original = pkg.bricks.brick_texture

    def brick_texture(
        width=128,
        height=128,
        brick_size=(32, 16),
        mortar=2,
        brick_color=(0.62, 0.27, 0.18),
        mortar_color=(0.80, 0.78, 0.72),
        variation=0.1,
        seed=0,
        **settings,
    ):
        original(width, height, brick_size, mortar, brick_color, mortar_color, variation, seed, **settings)
        w, h, (bw, bh), m = int(width), int(height), (int(brick_size[0]), int(brick_size[1])), int(mortar)
        brick, joint = np.asarray(brick_color, float), np.asarray(mortar_color, float)
        if not slips.get("drop_settings"):
            settings.setdefault("name", "bricks")
        else:
            settings = {}
        ys, xs = np.arange(h)[:, None], np.arange(w)[None, :]
        course = ys // bh
        odd = (course + 1) % 2 if slips.get("even_shift") else course % 2
        shift = 0 if slips.get("no_shift") else odd * (bw // 2)
        along = xs - shift
        bed = (ys % bh >= bh - m) if slips.get("bed_at_bottom") else (ys % bh < m)
        is_mortar = bed | (along % bw < m)
        columns = -(-w // bw)
        column = along // bw if slips.get("no_wrap") else (along // bw) % columns
        rng = np.random.default_rng(seed)
        if slips.get("per_texel"):
            factors = 1.0 + variation * (2.0 * rng.random((h, w)) - 1.0)
            factor = factors
        else:
            grid = rng.random((-(-h // bh), columns + 2))
            factors = 1.0 + variation * (grid if slips.get("only_brighter") else 2.0 * grid - 1.0)
            factor = factors[course, column % (columns + 2)]
        shade = brick[None, None, :] * factor[..., None]
        if not slips.get("no_clip"):
            shade = np.clip(shade, 0.0, 1.0)
        rgb = np.where(is_mortar[..., None], joint, shade)
        return TextureData.from_array(rgb, **settings)

    patch(pkg, "bricks.brick_texture", brick_texture)


for _name, _text, _slips in [
    ("no-offset", "every course starts at x = 0 (stack bond, no half-brick shift)", {"no_shift": True}),
    ("even-shifted", "shifts the even courses instead of the odd ones", {"even_shift": True}),
    ("bed-at-bottom", "the bed joint along the bottom of each course", {"bed_at_bottom": True}),
    ("per-texel", "a random factor per texel instead of per brick (noise)", {"per_texel": True}),
    ("no-wrap", "bricks not numbered modulo the bricks per course (seam)", {"no_wrap": True}),
    ("only-brighter", "factors from [1, 1 + variation] instead of 1 ± variation", {"only_brighter": True}),
    ("drops-settings", "ignores the extra settings (name, wrap, filter)", {"drop_settings": True}),
    ("no-clip", "brick_color x factor not clipped to [0, 1] (a bright brick goes past 1)", {"no_clip": True}),
]:
    mutant(MUTANTS, STEP, "brick_texture", _name, _text)(lambda pkg, _s=_slips: _bricks(pkg, **_s))


@mutant(MUTANTS, STEP, "brick_texture", "mortar-unchecked", "accepts a mortar as wide as the brick")
def _(pkg):
    original = pkg.bricks.brick_texture

    def brick_texture(*args, **kwargs):
        try:
            return original(*args, **kwargs)
        except ValueError as error:
            if "leaves no brick" not in str(error):
                raise
            kwargs["mortar"] = 0
            return original(*args, **kwargs)

    patch(pkg, "bricks.brick_texture", brick_texture)


@mutant(MUTANTS, STEP, "brick_texture", "variation-upper-only", "checks variation <= 1 only: a negative one passes")
def _(pkg):
    original = pkg.bricks.brick_texture

    def brick_texture(*args, variation=0.1, **kwargs):
        if not variation <= 1.0:
            raise ValueError(f"variation must be at most 1, got {variation}")
        return original(*args, variation=abs(variation), **kwargs)

    patch(pkg, "bricks.brick_texture", brick_texture)


# --- cube_cross_uvs --------------------------------------------------------------------------------


def _uvs(pkg, **slips):
    original = pkg.uvs.cube_cross_uvs
    from step03_textures.atlas import CROSS_CELLS, CROSS_GRID, FACE_FRAMES

    def cube_cross_uvs(positions, normals):
        original(positions, normals)  # the solution's checks
        p, n = np.asarray(positions, float), np.asarray(normals, float)
        lo, hi = p.min(axis=0), p.max(axis=0)
        centred = p - (lo + hi) / 2.0 if slips.get("unit_box") else (p - (lo + hi) / 2.0) / (hi - lo)
        axis = np.argmax(n if slips.get("signed_axis") else np.abs(n), axis=1)
        positive = n[np.arange(len(n)), axis] > 0.0
        uv = np.zeros((len(p), 2))
        cols, rows = CROSS_GRID
        for face, (normal, right, up) in FACE_FRAMES.items():
            k = int(np.flatnonzero(normal)[0])
            mask = (axis == k) & (positive == (normal[k] > 0))
            s = 0.5 + (-1 if slips.get("mirror_u") else 1) * (centred[mask] @ np.array(right, float))
            t = 0.5 + (1 if slips.get("v_up") else -1) * (centred[mask] @ np.array(up, float))
            col, row = CROSS_CELLS[face]
            if slips.get("swap_cell"):
                col, row = row, col
            uv[mask] = np.stack([(col + s) / cols, (row + t) / rows], axis=1)
        return uv

    patch(pkg, "uvs.cube_cross_uvs", cube_cross_uvs)


for _name, _text, _slips in [
    ("v-up", "v grows up the image (forgets that row 0 is the top)", {"v_up": True}),
    ("mirrored-u", "u runs against the face's right direction (mirrored)", {"mirror_u": True}),
    ("unit-box", "assumes a unit cube (no division by the box size)", {"unit_box": True}),
    ("signed-axis", "picks the face by the largest signed component, not |n|", {"signed_axis": True}),
    ("swapped-cell", "column and row of the cell swapped", {"swap_cell": True}),
]:
    mutant(MUTANTS, STEP, "cube_cross_uvs", _name, _text)(lambda pkg, _s=_slips: _uvs(pkg, **_s))


@mutant(MUTANTS, STEP, "cube_cross_uvs", "zero-normal", "a zero normal goes through (no error)")
def _(pkg):
    original = pkg.uvs.cube_cross_uvs

    def cube_cross_uvs(positions, normals):
        n = np.asarray(normals, dtype=np.float64)
        if n.ndim == 2 and n.shape[1] == 3 and len(n) and np.any(np.abs(n).max(axis=1) <= 0.0):
            n = n.copy()
            n[np.abs(n).max(axis=1) <= 0.0] = (0.0, 0.0, 1.0)
        return original(positions, n)

    patch(pkg, "uvs.cube_cross_uvs", cube_cross_uvs)


@mutant(MUTANTS, STEP, "cube_cross_uvs", "nan-only-check", "rejects NaN but lets an infinite position or normal pass")
def _(pkg):
    original = pkg.uvs.cube_cross_uvs

    def cube_cross_uvs(positions, normals):
        def finite(a):
            return np.nan_to_num(np.asarray(a, dtype=np.float64), nan=np.nan, posinf=1e300, neginf=-1e300)

        return original(finite(positions), finite(normals))

    patch(pkg, "uvs.cube_cross_uvs", cube_cross_uvs)


@mutant(MUTANTS, STEP, "cube_cross_uvs", "empty-accepted", "no vertices give an empty (0, 2) array instead of an error")
def _(pkg):
    original = pkg.uvs.cube_cross_uvs

    def cube_cross_uvs(positions, normals):
        if np.shape(positions) == (0, 3) and np.shape(normals) == (0, 3):
            return np.zeros((0, 2))
        return original(positions, normals)

    patch(pkg, "uvs.cube_cross_uvs", cube_cross_uvs)
