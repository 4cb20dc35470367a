"""The numpy light model the step 06 and step 07 references share (float64, linear light): what a light sends to
points of a surface, and the 8-bit sRGB encoding of the framebuffer."""

from __future__ import annotations

import numpy as np

from gandalf_core.resources import linear_to_srgb, srgb_to_linear


def radiance(light) -> np.ndarray:
    """A LightComponent's linear radiance: its sRGB colour in linear light times its intensity."""
    return srgb_to_linear(np.asarray(light.color, dtype=np.float64)) * light.intensity


def incoming(light, transform, p: np.ndarray, n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(unit direction to the light, radiance arriving) at points ``p`` (..., 3) with normals ``n``, for a
    directional or point light placed by ``transform``. A point light's range windows its 1/d² falloff; at the
    light's own position the direction is the normal."""
    if light.kind == "directional":
        t = np.asarray(transform.translation, dtype=np.float64)
        return np.broadcast_to(t / np.linalg.norm(t), p.shape), radiance(light)
    d = np.asarray(transform.translation, dtype=np.float64) - p
    dist = np.linalg.norm(d, axis=-1, keepdims=True)
    to_light = np.where(dist > 1e-6, d / np.maximum(dist, 1e-6), n)
    if light.range <= 0:
        return to_light, radiance(light)
    window = np.clip(1.0 - (dist / light.range) ** 4, 0.0, 1.0)
    return to_light, radiance(light) * window * window / np.maximum(dist * dist, 1e-4)


def to_srgb8(linear: np.ndarray) -> np.ndarray:
    """Linear colours clipped to [0, 1], encoded to 8-bit sRGB (as floats) like the framebuffer."""
    return np.round(linear_to_srgb(np.clip(linear, 0.0, 1.0)) * 255.0)
