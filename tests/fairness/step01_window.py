"""Correct alternatives of step 01: HSV by the per-channel formula, the hue wrapped with while loops."""

from __future__ import annotations

from gandalf_tools.grading.fairness import alternative
from gandalf_tools.grading.mutants import Mutant, patch

STEP = "step01_window"
ALTERNATIVES: list[Mutant] = []


@alternative(ALTERNATIVES, STEP, "hsv_to_rgb", "per-channel-formula",
             "no sector table: channel n is v - v s max(0, min(k, 4 - k, 1)) with k = (n + h / 60) mod 6")
def _(pkg):
    def hsv_to_rgb(hue, saturation, value):
        def channel(n):
            k = (n + hue / 60.0) % 6.0
            return value - value * saturation * max(0.0, min(k, 4.0 - k, 1.0))

        return (channel(5.0), channel(3.0), channel(1.0))

    patch(pkg, "hue.hsv_to_rgb", hsv_to_rgb)


@alternative(ALTERNATIVES, STEP, "HueCycleSystem", "while-wrap", "the hue brought into [0, 360) with while loops")
def _(pkg):
    base, hsv = pkg.hue.HueCycleSystem, pkg.hue.hsv_to_rgb

    class HueCycleSystem(base):
        def on_update_entity(self, ts, entity, components):
            hue_cycle, clear_color = components
            hue = hue_cycle.hue + hue_cycle.speed * ts
            while hue >= 360.0:
                hue -= 360.0
            while hue < 0.0:
                hue += 360.0
            hue_cycle.hue = hue
            clear_color.color = hsv(hue, hue_cycle.saturation, hue_cycle.value)

    patch(pkg, "hue.HueCycleSystem", HueCycleSystem)
