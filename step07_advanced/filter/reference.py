"""The float64 numpy reference of every filter, and the rules the GPU kernels share with it.

* **Weights**: a Gaussian of ``sigma = radius / 2`` sampled at the integer taps ``-radius..radius`` and divided
  by their sum, so the table sums to 1 (a constant image stays constant); radius 0 is the identity ``[1]``.
* **Border rule**: clamp-to-edge. A tap outside the image reads the nearest edge pixel (``np.pad(mode="edge")``).
* **Separable blur** = a horizontal pass then a vertical pass; the 2-D kernel ``w(i) · w(j)`` gives the same
  image in one (slower) pass.
* **Sobel**: the gradient of the luminance ``Y = 0.2126 R + 0.7152 G + 0.0722 B`` (of the stored values) with
  the 3×3 Sobel kernels, magnitude ``|g| · SOBEL_SCALE`` clamped to 1, written to RGB with alpha 1.

Images are (H, W, 4) float64 in [0, 1] (``to_float``) or uint8 RGBA (``to_unorm8``). The filters work on the
stored 8-bit values as data: no sRGB decoding, as most image-processing code does (and as WebGPU must: it has no
sRGB storage textures).
"""

from __future__ import annotations

import numpy as np

#: Sobel magnitude scale: a 0 → 0.5 step edge has |g| = 2, shown as 1 (white); stronger edges saturate.
SOBEL_SCALE = 0.5
#: Rec. 709 luminance weights.
LUMA = np.array([0.2126, 0.7152, 0.0722])


def sigma_for(radius: int) -> float:
    """The Gaussian's standard deviation for a kernel ``radius``: ``radius / 2`` (the taps reach ±2σ)."""
    return radius / 2.0


def to_float(image: np.ndarray) -> np.ndarray:
    """uint8 RGBA → float64 in [0, 1]."""
    return np.asarray(image, dtype=np.float64) / 255.0


def to_unorm8(values: np.ndarray) -> np.ndarray:
    """float [0, 1] → uint8 with rounding to nearest (what an ``rgba8`` store does)."""
    return np.rint(np.clip(values, 0.0, 1.0) * 255.0).astype(np.uint8)


# --8<-- [start:gaussian]
def gaussian_weights(radius: int) -> np.ndarray:
    """The normalised weight table, float64, shape (2·radius + 1,): taps ``-radius..radius``."""
    if radius < 0:
        raise ValueError(f"radius must be >= 0, got {radius}")
    if radius == 0:
        return np.ones(1)
    i = np.arange(-radius, radius + 1, dtype=np.float64)
    w = np.exp(-(i * i) / (2.0 * sigma_for(radius) ** 2))
    return w / w.sum()


def blur_pass(image: np.ndarray, radius: int, axis: int) -> np.ndarray:
    """One 1-D pass along ``axis`` (1 = horizontal, 0 = vertical) with clamp-to-edge, float64."""
    img = np.asarray(image, dtype=np.float64)
    w = gaussian_weights(radius)
    pad = [(0, 0)] * img.ndim
    pad[axis] = (radius, radius)
    padded = np.pad(img, pad, mode="edge")
    n = img.shape[axis]
    out = np.zeros_like(img)
    for k, weight in enumerate(w):
        out += weight * np.take(padded, np.arange(k, k + n), axis=axis)
    return out
# --8<-- [end:gaussian]


def blur(image: np.ndarray, radius: int) -> np.ndarray:
    """The separable Gaussian blur (horizontal, then vertical) of a float image, float64."""
    return blur_pass(blur_pass(image, radius, 1), radius, 0)


def blur_2d(image: np.ndarray, radius: int) -> np.ndarray:
    """The same blur as one 2-D convolution with ``w(i) · w(j)`` (the naive kernel's reference), float64."""
    img = np.asarray(image, dtype=np.float64)
    w = gaussian_weights(radius)
    padded = np.pad(img, [(radius, radius), (radius, radius)] + [(0, 0)] * (img.ndim - 2), mode="edge")
    h, wd = img.shape[:2]
    out = np.zeros_like(img)
    for j, wj in enumerate(w):
        for i, wi in enumerate(w):
            out += wj * wi * padded[j:j + h, i:i + wd]
    return out


def sobel(image: np.ndarray) -> np.ndarray:
    """Sobel edge magnitude of the luminance, (H, W, 4) float64: grey RGB, alpha 1."""
    img = np.asarray(image, dtype=np.float64)
    y = img[..., :3] @ LUMA
    p = np.pad(y, 1, mode="edge")
    h, w = y.shape

    def at(dy: int, dx: int) -> np.ndarray:
        return p[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]

    gx = (at(-1, 1) + 2 * at(0, 1) + at(1, 1)) - (at(-1, -1) + 2 * at(0, -1) + at(1, -1))
    gy = (at(1, -1) + 2 * at(1, 0) + at(1, 1)) - (at(-1, -1) + 2 * at(-1, 0) + at(-1, 1))
    m = np.clip(np.hypot(gx, gy) * SOBEL_SCALE, 0.0, 1.0)
    return np.stack([m, m, m, np.ones_like(m)], axis=-1)


def source_image(width: int = 256, height: int = 192, seed: int = 5) -> np.ndarray:
    """A photo-like procedural landscape, uint8 RGBA (H, W, 4): a sky gradient with a sun, hills, a house with
    a checkered wall and a dark roof (hard edges), and film grain (noise), the same for the same arguments."""
    if width < 1 or height < 1:
        raise ValueError(f"image size must be positive, got {width}x{height}")
    y, x = np.mgrid[0:height, 0:width].astype(np.float64)
    u, v = (x + 0.5) / width, (y + 0.5) / height  # v = 0 at the top
    rgb = np.empty((height, width, 3))
    rgb[:] = np.stack([0.35 + 0.4 * v, 0.55 + 0.3 * v, 0.95 - 0.15 * v], axis=-1)  # sky: deep blue to haze
    sun = np.hypot((u - 0.78) * width / height, v - 0.22)
    rgb = np.where((sun < 0.09)[..., None], (1.0, 0.93, 0.7), rgb)
    ridge = 0.62 + 0.06 * np.sin(u * 9.0) + 0.03 * np.sin(u * 23.0 + 1.0)
    hill = v > ridge
    rgb = np.where(hill[..., None], np.stack([0.2 + 0.2 * (v - ridge), 0.45 - 0.25 * (v - ridge),
                                              0.15 + 0 * v], axis=-1), rgb)
    wall = (u > 0.14) & (u < 0.42) & (v > 0.48) & (v < 0.8)
    checker = ((np.floor(u * 40) + np.floor(v * 30)) % 2)[..., None]
    rgb = np.where(wall[..., None], (0.85, 0.82, 0.74) - 0.25 * checker * np.array([0.2, 0.5, 0.8]), rgb)
    roof = (v <= 0.48) & (v > 0.3) & (np.abs(u - 0.28) < (v - 0.3) * 0.95)
    rgb = np.where(roof[..., None], (0.35, 0.12, 0.1), rgb)
    door = (np.abs(u - 0.3) < 0.03) & (v > 0.66) & (v < 0.8)
    rgb = np.where(door[..., None], (0.25, 0.17, 0.1), rgb)
    rng = np.random.default_rng(seed)
    rgb = rgb + rng.normal(0.0, 0.025, size=rgb.shape)
    out = np.ones((height, width, 4))
    out[..., :3] = np.clip(rgb, 0.0, 1.0)
    return to_unorm8(out)


def apply(image: np.ndarray, op: str, radius: int = 0) -> np.ndarray:
    """The float64 result in [0, 1] that a GPU filter's ``run(image, op, radius)`` rounds to 8 bits."""
    x = to_float(image)
    if op == "sobel":
        return sobel(x)
    if op == "naive":
        return blur_2d(x, radius)
    if op in ("separable", "tiled"):
        return blur(x, radius)
    if op in ("horizontal", "vertical"):
        return blur_pass(x, radius, 1 if op == "horizontal" else 0)
    raise ValueError(f"unknown op {op!r}")
