"""A material's uniform values, as both backends keep them: validated, colour decoded to linear light.

Each backend's material class derives from :class:`MaterialValues` and only says how the values reach
its shader (:meth:`MaterialValues._upload`): both pack them into the shader's ``Material`` block with the one
layout rule (:mod:`gandalf_core.render.material_block`) and write the same bytes to a uniform buffer, which OpenGL
binds to binding point 2 and WebGPU to ``@group(1) @binding(0)``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..resources import MaterialData, ResourceError
from .color import srgb_rgba_to_linear


class MaterialValues:
    """Holds ``values``: ``{"color": linear RGBA, param: float64 array}``; subclasses upload them."""

    name: str
    data: MaterialData

    def set_values(self, values: Mapping[str, Any]) -> None:
        """Replace the uniform values. ``color`` is sRGB (3 or 4 floats); every value must be finite."""
        checked: dict[str, np.ndarray] = {}
        for key, value in values.items():
            try:
                array = np.asarray(value, dtype=np.float64)
            except (TypeError, ValueError):
                raise ResourceError(f"material '{self.name}'", key, f"{value!r} is not a number or numbers") from None
            if not np.all(np.isfinite(array)):
                raise ResourceError(f"material '{self.name}'", key, f"values must be finite, got {value!r}")
            checked[key] = array
        if "color" in checked:
            if checked["color"].size not in (3, 4):
                raise ResourceError(f"material '{self.name}'", "color", "expected 3 or 4 components")
            checked["color"] = srgb_rgba_to_linear(checked["color"])
        self.values = checked
        self._upload()

    def set_color(self, color: Any) -> None:
        """Change only the colour (sRGB); no pipeline or shader is rebuilt."""
        self.set_values({**{k: v for k, v in self.values.items() if k != "color"}, "color": color})

    def _upload(self) -> None:
        """Make the values reach the shader (backend-specific)."""
        raise NotImplementedError
