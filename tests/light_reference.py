"""The numpy light model the step 06 and step 07 references share (float64, linear light): what a light sends to
points of a surface, the 8-bit sRGB encoding of the framebuffer, and how close a picture must come to it."""

from __future__ import annotations

import numpy as np

from gandalf_core.resources import linear_to_srgb, srgb_to_linear
from gandalf_tools.testing import save_failure, shown_failure


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


#: How close a rendered sphere must come to its numpy reference (8-bit steps, every channel of the pixels inside
#: its silhouette): the mean absolute error and the 99th percentile.
MEAN_TOLERANCE = 1.0
P99_TOLERANCE = 3.0


def pixel_errors(image: np.ndarray, expected: np.ndarray, mask: np.ndarray) -> tuple[float, float]:
    """(mean, 99th percentile) absolute channel error in 8-bit steps over the pixels of ``mask``."""
    diff = np.abs(image[..., :3].astype(np.float64) - expected)[mask]
    return float(diff.mean()), float(np.percentile(diff, 99))


def difference_sentence(image: np.ndarray, expected: np.ndarray, mask: np.ndarray, mean: float, p99: float,
                        mean_limit: float = MEAN_TOLERANCE, p99_limit: float = P99_TOLERANCE, case: str = "") -> str:
    """Where a rendered picture and its reference differ, in words: the case drawn (``case``: its input), the pixel
    that differs most (got against expected), the errors against their bounds, and where the pictures were saved
    (got, expected, diff and side by side: :func:`gandalf_tools.testing.save_failure`)."""
    got = image[..., :3].astype(np.float64)
    want = np.broadcast_to(np.asarray(expected, dtype=np.float64), got.shape)
    diff = np.where(mask[..., None], np.abs(got - want), -1.0).max(axis=-1)
    row, col = np.unravel_index(int(np.argmax(diff)), diff.shape)
    # Only the pixels of the mask are compared: outside it the expected picture shows the drawn one (no difference).
    saved = shown_failure(save_failure(image, np.where(mask[..., None], want, got)))
    lead = f"for {case}: " if case else ""
    # The folder before the error figures: the student's one line (at most 300 characters) keeps it. The files are
    # named after the test, which the line starts with.
    return (f"{lead}worst pixel (x {col}, y {row}) got {got[row, col].astype(int).tolist()}, expected "
            f"{np.round(want[row, col]).astype(int).tolist()}; pictures in {saved.rsplit('/', 1)[0]}/; mean error "
            f"{mean:.2f} levels (allowed {mean_limit:g}), 99th percentile {p99:.0f} (allowed {p99_limit:g})")


def assert_near_reference(image: np.ndarray, expected: np.ndarray, mask: np.ndarray, case: str = "") -> None:
    """``image`` within :data:`MEAN_TOLERANCE` and :data:`P99_TOLERANCE` of ``expected`` over ``mask``; ``case``
    says what was drawn (the input), for the failure's sentence."""
    mean, p99 = pixel_errors(image, expected, mask)
    assert mean <= MEAN_TOLERANCE and p99 <= P99_TOLERANCE, difference_sentence(image, expected, mask, mean, p99,
                                                                               case=case)
