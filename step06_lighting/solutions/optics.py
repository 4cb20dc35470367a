"""Reference solution: reflection and refraction directions (vectorised over leading axes)."""

from __future__ import annotations

import numpy as np


def reflect(i: np.ndarray, n: np.ndarray) -> np.ndarray:
    """The mirror direction of ``i`` about ``n``: ``i - 2 (n·i) n``."""
    i, n = np.asarray(i, dtype=np.float64), np.asarray(n, dtype=np.float64)
    return i - 2.0 * np.sum(n * i, axis=-1, keepdims=True) * n


def refract(i: np.ndarray, n: np.ndarray, eta: float | np.ndarray) -> np.ndarray:
    """The refracted direction, or the zero vector on total internal reflection."""
    i, n = np.asarray(i, dtype=np.float64), np.asarray(n, dtype=np.float64)
    eta = np.asarray(eta, dtype=np.float64)[..., None] if np.ndim(eta) else float(eta)
    cos_i = np.sum(n * i, axis=-1, keepdims=True)
    k = 1.0 - eta * eta * (1.0 - cos_i * cos_i)
    t = eta * i - (eta * cos_i + np.sqrt(np.maximum(k, 0.0))) * n
    return np.where(k >= 0.0, t, 0.0)
