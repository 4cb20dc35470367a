"""sRGB <-> linear conversion (IEC 61966-2-1), written once for both backends."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike


def srgb_to_linear(c: ArrayLike) -> np.ndarray:
    """Decode sRGB values in [0, 1] to linear light (alpha, if you pass it, must be handled by the caller)."""
    c = np.clip(np.asarray(c, dtype=np.float64), 0.0, 1.0)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(c: ArrayLike) -> np.ndarray:
    """Encode linear light in [0, 1] as sRGB."""
    c = np.clip(np.asarray(c, dtype=np.float64), 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)


def srgb_rgba_to_linear(rgba: ArrayLike) -> np.ndarray:
    """An sRGB RGBA colour with its RGB decoded to linear and alpha kept as it is."""
    rgba = np.asarray(rgba, dtype=np.float64)
    return np.concatenate([srgb_to_linear(rgba[:3]), rgba[3:4]])
