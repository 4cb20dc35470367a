"""Mutants of step 01: ``hsv_to_rgb`` and ``HueCycleSystem``."""

from __future__ import annotations

import math

from gandalf_tools.grading.mutants import Mutant, mutant, patch

STEP = "step01_window"
MUTANTS: list[Mutant] = []


def _hsv(hue, saturation, value, *, wrap_negative=True, offset=True, chroma_uses_value=True):
    """The reference formula with switches for the usual slips."""
    h = math.fmod(hue, 360.0)
    if wrap_negative and h < 0:
        h += 360.0
    sector = h / 60.0
    chroma = value * saturation if chroma_uses_value else saturation
    x = chroma * (1.0 - abs(math.fmod(sector, 2.0) - 1.0))
    r, g, b = [
        (chroma, x, 0.0),
        (x, chroma, 0.0),
        (0.0, chroma, x),
        (0.0, x, chroma),
        (x, 0.0, chroma),
        (chroma, 0.0, x),
    ][max(0, min(int(sector), 5))]
    m = value - chroma if offset else 0.0
    return (r + m, g + m, b + m)


@mutant(MUTANTS, STEP, "hsv_to_rgb", "radians", "reads the hue as radians instead of degrees")
def _(pkg):
    original = pkg.hue.hsv_to_rgb
    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: original(math.degrees(h), s, v))


@mutant(MUTANTS, STEP, "hsv_to_rgb", "negative-hue", "leaves a negative hue negative (fmod without the wrap)")
def _(pkg):
    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: _hsv(h, s, v, wrap_negative=False))


@mutant(MUTANTS, STEP, "hsv_to_rgb", "no-offset", "forgets to add m = value - chroma to every channel")
def _(pkg):
    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: _hsv(h, s, v, offset=False))


@mutant(MUTANTS, STEP, "hsv_to_rgb", "chroma-is-saturation", "chroma = saturation (forgets to scale by value)")
def _(pkg):
    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: _hsv(h, s, v, chroma_uses_value=False))


@mutant(MUTANTS, STEP, "hsv_to_rgb", "bgr", "returns the channels in BGR order")
def _(pkg):
    original = pkg.hue.hsv_to_rgb
    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: tuple(reversed(original(h, s, v))))


@mutant(MUTANTS, STEP, "hsv_to_rgb", "no-modulo", "no wrap at all: hues of 360 and more fall off the sector table")
def _(pkg):
    def hsv_to_rgb(h, s, v):
        return _hsv(h, s, v) if 0.0 <= h < 360.0 else _hsv(min(max(h, 0.0), 359.999999), s, v)

    patch(pkg, "hue.hsv_to_rgb", hsv_to_rgb)


def _hsv_by_remainder(h, s, v, pick):
    """hue % 360 (Python's remainder, not fmod): -1e-15 % 360 rounds to 360.0, sector 6; ``pick(table, sector)``
    chooses the channels from the six sectors' table."""
    sector = (h % 360.0) / 60.0
    chroma = v * s
    x = chroma * (1.0 - abs(sector % 2.0 - 1.0))
    table = [(chroma, x, 0.0), (x, chroma, 0.0), (0.0, chroma, x), (0.0, x, chroma), (x, 0.0, chroma),
             (chroma, 0.0, x)]
    r, g, b = pick(table, sector)
    return (r + v - chroma, g + v - chroma, b + v - chroma)


@mutant(MUTANTS, STEP, "hsv_to_rgb", "tiny-negative-hue", "hue % 360 with six sectors: -1e-15 % 360 is 360.0, "
        "sector 6 is off the table")
def _(pkg):
    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: _hsv_by_remainder(h, s, v, lambda table, sector: table[int(sector)]))


@mutant(MUTANTS, STEP, "hsv_to_rgb", "tiny-negative-hue-black", "hue % 360, then a sector test per range of 60° "
        "(h' in [0, 1), ..., [5, 6)) and black otherwise: -1e-15 % 360 is 360.0, which no range holds")
def _(pkg):
    def pick(table, sector):
        return next((channels for k, channels in enumerate(table) if k <= sector < k + 1), (0.0, 0.0, 0.0))

    patch(pkg, "hue.hsv_to_rgb", lambda h, s, v: _hsv_by_remainder(h, s, v, pick))


def _system(pkg, update):
    """A HueCycleSystem whose per-entity update is ``update(system, ts, hue_cycle, clear_color)``."""
    base = pkg.hue.HueCycleSystem
    hsv = pkg.hue.hsv_to_rgb

    class HueCycleSystem(base):
        def on_update_entity(self, ts, entity, components):
            hue_cycle, clear_color = components
            update(ts, hue_cycle, clear_color, hsv)

    patch(pkg, "hue.HueCycleSystem", HueCycleSystem)


@mutant(MUTANTS, STEP, "HueCycleSystem", "no-wrap", "lets the hue grow past 360")
def _(pkg):
    def update(ts, c, clear, hsv):
        c.hue = c.hue + c.speed * ts
        clear.color = hsv(c.hue, c.saturation, c.value)

    _system(pkg, update)


@mutant(MUTANTS, STEP, "HueCycleSystem", "per-frame", "adds speed once per frame, ignoring the time step")
def _(pkg):
    def update(ts, c, clear, hsv):
        c.hue = math.fmod(c.hue + c.speed, 360.0) % 360.0
        clear.color = hsv(c.hue, c.saturation, c.value)

    _system(pkg, update)


@mutant(MUTANTS, STEP, "HueCycleSystem", "negative-hue", "fmod alone: a negative speed leaves a negative hue")
def _(pkg):
    def update(ts, c, clear, hsv):
        c.hue = math.fmod(c.hue + c.speed * ts, 360.0)
        clear.color = hsv(c.hue, c.saturation, c.value)

    _system(pkg, update)


@mutant(MUTANTS, STEP, "HueCycleSystem", "swapped-sv", "passes value and saturation in the wrong order")
def _(pkg):
    def update(ts, c, clear, hsv):
        c.hue = (c.hue + c.speed * ts) % 360.0
        clear.color = hsv(c.hue, c.value, c.saturation)

    _system(pkg, update)


@mutant(MUTANTS, STEP, "HueCycleSystem", "colour-lags", "writes the colour of the previous hue (before advancing)")
def _(pkg):
    def update(ts, c, clear, hsv):
        clear.color = hsv(c.hue, c.saturation, c.value)
        c.hue = (c.hue + c.speed * ts) % 360.0

    _system(pkg, update)


@mutant(MUTANTS, STEP, "HueCycleSystem", "colour-not-written", "advances the hue but never writes the clear colour")
def _(pkg):
    def update(ts, c, clear, hsv):
        c.hue = (c.hue + c.speed * ts) % 360.0

    _system(pkg, update)
