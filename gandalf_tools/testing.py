"""Helpers for tests and the autograder: headless renders and image comparison with stated tolerances.

``compare_images`` writes the actual, expected and an amplified difference image when a comparison fails, so a
student or CI log can show what went wrong: into ``$GANDALF_FAILURE_DIR`` when it is set, else ``tests/_failures/`` of
a checkout, else ``gandalf-failures/`` in the current folder (never into an installed package's folder).
Set ``GANDALF_UPDATE_REFERENCES=1`` to (re)write reference images.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike

from gandalf_core.app import Application
from gandalf_core.ecs import Scene


def _failure_dir() -> Path:
    chosen = os.environ.get("GANDALF_FAILURE_DIR")
    if chosen:
        return Path(chosen)
    checkout_tests = Path(__file__).resolve().parent.parent / "tests"
    return checkout_tests / "_failures" if checkout_tests.is_dir() else Path.cwd() / "gandalf-failures"


FAILURE_DIR = _failure_dir()


def render_frames(create_app: Callable[..., Application], frames: int = 1, **kwargs: object) -> np.ndarray:
    """Run a step variant's ``create_app(headless=True, **kwargs)`` for ``frames`` frames; return the image."""
    with create_app(headless=True, **kwargs) as app:
        app.run(frames=frames)
        return app.capture()


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    """Peak signal-to-noise ratio in dB of two uint8 images (RGB only); ``inf`` when identical."""
    if a.shape != b.shape:
        raise ValueError(f"image shapes differ: {a.shape} vs {b.shape}")
    diff = a[..., :3].astype(np.float64) - b[..., :3].astype(np.float64)
    mse = float(np.mean(diff * diff))
    return float("inf") if mse == 0.0 else 10.0 * np.log10(255.0**2 / mse)


@dataclass(frozen=True)
class LocalDifferences:
    """What two implementations may legally draw differently, for pictures made by two drivers (or compared with a
    reference made by another): ``share`` of the pixels within ``level`` in every channel, and no ``block`` ×
    ``block`` square whose mean difference exceeds ``block_mean`` (levels of 255).

    Why these differ at all: the APIs let an implementation approximate the level of detail at which a minified
    texture is sampled (OpenGL 4.6 §8.14.1 and Vulkan's "scale factor" may be approximated), so a checkerboard
    receding to the horizon is sampled a mip level apart in a band a few pixels high; and which pixels an edge
    covers depends on the rasteriser's sub-pixel precision (a one-pixel seam). Both are local: averaged over an
    8 × 8 square they stay small (measured on an NVIDIA H200 against Mesa: at most 9.6 levels), while a wrong
    texture, UV, colour space or face changes whole squares.
    """

    level: int
    share: float
    block: int = 8
    block_mean: float = 12.0

    def violations(self, actual: np.ndarray, expected: np.ndarray) -> list[str]:
        diff = np.abs(actual[..., :3].astype(np.float64) - expected[..., :3].astype(np.float64))
        within = float(np.mean(diff.max(axis=-1) <= self.level))
        found = []
        if within < self.share:
            found.append(f"{within:.2%} of pixels within {self.level} levels (need ≥ {self.share:.2%})")
        k = self.block
        h, w = diff.shape[0] // k * k, diff.shape[1] // k * k
        if h and w:
            means = diff.mean(axis=-1)[:h, :w].reshape(h // k, k, w // k, k).mean(axis=(1, 3))
            if means.max() > self.block_mean:
                y, x = np.unravel_index(int(np.argmax(means)), means.shape)
                found.append(f"the {k}x{k} square at pixel ({x * k}, {y * k}) differs by {means.max():.1f} levels "
                             f"on average (allowed {self.block_mean:g})")
        return found


def compare_images(
    actual: np.ndarray, expected: np.ndarray, name: str, *, min_psnr: float = 40.0, max_diff: int | None = None,
    local: LocalDifferences | None = None,
) -> float:
    """Assert two images agree (PSNR ≥ ``min_psnr`` dB, and no channel off by more than ``max_diff``), or, with
    ``local``, within what two implementations may legally draw differently (:class:`LocalDifferences`).

    On failure the images are saved as ``<name>-actual/expected/diff/side-by-side.png`` (:func:`save_failure`) and
    an AssertionError names them. Returns the PSNR.
    """
    value = psnr(actual, expected)
    worst = int(np.abs(actual[..., :3].astype(int) - expected[..., :3].astype(int)).max())
    if local is not None:
        problems = local.violations(actual, expected)
    else:
        problems = [f"PSNR {value:.1f} dB (need ≥ {min_psnr})"] if value < min_psnr else []
        if max_diff is not None and worst > max_diff:
            problems.append(f"largest channel difference {worst} (allowed {max_diff})")
    if problems:
        paths = save_failure(actual, expected, name)
        raise AssertionError(f"{name}: images differ: {'; '.join(problems)} (PSNR {value:.1f} dB, largest channel "
                             f"difference {worst}); got, expected, diff and side by side: {shown_failure(paths)}")
    return value


def compare_to_reference(
    actual: np.ndarray, reference: str | Path, *, min_psnr: float = 40.0, max_diff: int | None = None,
    local: LocalDifferences | None = None,
) -> float:
    """Compare with a committed reference PNG (written instead when ``GANDALF_UPDATE_REFERENCES=1``)."""
    from PIL import Image

    reference = Path(reference)
    if os.environ.get("GANDALF_UPDATE_REFERENCES") == "1" or not reference.exists():
        if not reference.exists() and os.environ.get("GANDALF_UPDATE_REFERENCES") != "1":
            raise AssertionError(f"no reference image {reference}; run with GANDALF_UPDATE_REFERENCES=1 to create it")
        reference.parent.mkdir(parents=True, exist_ok=True)
        Image.fromarray(actual, "RGBA").save(reference)
        return float("inf")
    expected = np.asarray(Image.open(reference).convert("RGBA"))
    return compare_images(actual, expected, reference.stem, min_psnr=min_psnr, max_diff=max_diff, local=local)


def failure_name() -> str:
    """A file name for the running test's failure pictures: its name and parameters (``test_x-opengl-24.0``), from
    pytest's ``PYTEST_CURRENT_TEST``; ``picture`` outside a test."""
    current = os.environ.get("PYTEST_CURRENT_TEST", "").rsplit(" (", 1)[0].split("::")[-1]
    return re.sub(r"[^\w.-]+", "-", current).strip("-") or "picture"


def _rgba8(image: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """An image (or one colour, broadcast) as 8-bit RGBA of ``shape``'s height and width."""
    values = np.broadcast_to(np.asarray(image, dtype=np.float64), (*shape[:2], np.shape(image)[-1]))
    rgba = np.full((*shape[:2], 4), 255.0)
    rgba[..., : min(values.shape[-1], 4)] = values[..., :4]
    return np.clip(np.round(rgba), 0, 255).astype(np.uint8)


def save_failure(actual: np.ndarray, expected: np.ndarray, name: str | None = None) -> list[Path]:
    """Write ``<name>-actual.png``, ``-expected.png``, ``-diff.png`` (the difference, amplified 8 times) and
    ``-side-by-side.png`` (expected | actual | diff) into :data:`FAILURE_DIR`; return their paths.
    ``expected`` may be one colour; ``name`` defaults to the running test's (:func:`failure_name`)."""
    from PIL import Image

    name = name or failure_name()
    actual = _rgba8(actual, np.shape(actual))
    expected = _rgba8(expected, actual.shape)
    FAILURE_DIR.mkdir(parents=True, exist_ok=True)
    diff = np.abs(actual.astype(int) - expected.astype(int))[..., :3]
    diff = np.clip(diff * 8, 0, 255).astype(np.uint8)
    paths = [FAILURE_DIR / f"{name}-{kind}.png" for kind in ("actual", "expected", "diff", "side-by-side")]
    Image.fromarray(actual, "RGBA").save(paths[0])
    Image.fromarray(expected, "RGBA").save(paths[1])
    Image.fromarray(diff, "RGB").save(paths[2])
    gap = np.full((actual.shape[0], 4, 3), 255, np.uint8)  # a white bar between the three
    Image.fromarray(np.concatenate([expected[..., :3], gap, actual[..., :3], gap, diff], axis=1), "RGB").save(paths[3])
    return paths


def shown_failure(paths: list[Path]) -> str:
    """How a failure message names the pictures :func:`save_failure` wrote: ``tests/_failures/<name>-*.png``, from the
    checkout where they lie in it."""
    shown = paths[0].parent / paths[0].name.replace("-actual.png", "-*.png")
    try:
        return str(shown.relative_to(Path(__file__).resolve().parent.parent))
    except ValueError:
        return str(shown)


# --- numpy references for lit spheres (the shading exercises grade against these) ----------------------
def sphere_hits(
    eye: np.ndarray, fov_degrees: float, size: tuple[int, int]
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Ray-trace the unit sphere at the origin seen from ``eye`` (looking at the origin down -Z).

    One ray per pixel centre of a ``size = (width, height)`` picture with a vertical field of view of
    ``fov_degrees``: returns the hit mask (H, W), the hit points (H, W, 3) and the unit rays (H, W, 3).
    """
    eye = np.asarray(eye, dtype=np.float64)
    w, h = size
    x = (np.arange(w) + 0.5) / w * 2.0 - 1.0
    y = 1.0 - (np.arange(h) + 0.5) / h * 2.0
    tan = np.tan(np.radians(fov_degrees) / 2)
    d = np.stack(np.broadcast_arrays(x[None, :] * tan * w / h, y[:, None] * tan, -np.ones((h, w))), -1)
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    b = np.sum(d * eye, axis=-1)
    disc = b * b - (eye @ eye - 1.0)
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    return disc > 0.0, eye + t[..., None] * d, d


def inner(mask: np.ndarray, pixels: int = 2) -> np.ndarray:
    """``mask`` eroded by ``pixels``: silhouette pixels are partly covered and rasterised differently."""
    out = mask.copy()
    for _ in range(pixels):
        out[1:] &= out[:-1]
        out[:-1] &= out[1:]
        out[:, 1:] &= out[:, :-1]
        out[:, :-1] &= out[:, 1:]
    return out


# --- lights described as (LightComponent, TransformComponent) pairs, reusable across scenes ----------
def directional_light(towards: ArrayLike, color: ArrayLike = (1.0, 1.0, 1.0), intensity: float = 1.0) -> tuple:
    """A directional light whose light comes from direction ``towards`` (a vector pointing at the light)."""
    from gandalf_core.components import LightComponent, TransformComponent
    from gandalf_core.math import look_at_rotation

    t = np.asarray(towards, dtype=np.float64)
    return LightComponent("directional", color, intensity), TransformComponent(
        t, quaternion=look_at_rotation(t, (0, 0, 0))
    )


def point_light(
    position: ArrayLike, color: ArrayLike = (1.0, 1.0, 1.0), intensity: float = 1.0, range: float = 0.0
) -> tuple:
    from gandalf_core.components import LightComponent, TransformComponent

    return LightComponent("point", color, intensity, range), TransformComponent(position)


def ambient_light(color: ArrayLike) -> tuple:
    from gandalf_core.components import LightComponent, TransformComponent

    return LightComponent("ambient", color), TransformComponent()


def add_lights(scene: Scene, lights: list[tuple]) -> None:
    """Copies of ``lights`` as entities of ``scene``: one list may describe several scenes (and a reference)."""
    from gandalf_core.components import LightComponent, TransformComponent

    for light, transform in lights:
        scene.create_entity(
            TransformComponent(transform.translation, quaternion=transform.quaternion, scale=transform.scale),
            LightComponent(light.kind, light.color, light.intensity, light.range),
        )
