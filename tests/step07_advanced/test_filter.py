"""The image filter (``step07_advanced.filter``): exercises ``blur_kernel`` (the normalised Gaussian weights) and
``convolve`` (one clamp-to-edge blur pass), graded on the student's own GLSL (OpenGL compute) and WGSL (WebGPU
compute) in both APIs, against the float64 numpy reference (``filter/reference.py``).

Tolerances:
* weight tables: |got - reference| <= 1e-5 per tap for radii 0..32; sums within 1e-5 of 1; symmetric to 1e-7;
  radius 0 gives exactly [1] (± 1e-7). The reference solution measures <= 1.2e-7.
* blurred 8-bit images: |got - 255 · reference| <= 1 step per channel (the rgba8 store rounds once); the reference
  solution measures at most 0.5 (correct rounding) in both APIs, for every method (separable, naive, tiled).
* the scene's OpenGL and WebGPU pictures: PSNR >= 35 dB (measured 84 dB at 640×480, largest difference 1).
The convolve tests fill the weight table from the numpy reference, so they do not depend on ``blur_kernel``. Each
graded check also runs on plausible wrong implementations (mutants, in ``test_filter_reference.py`` with the
engine's checks that run on the reference solution), each of which must fail one.
"""

from __future__ import annotations

import sys
from pathlib import Path
from types import ModuleType, SimpleNamespace

import numpy as np
import pytest
from shader_checks import LANGUAGE

from gandalf_tools.grading import shader_box
from gandalf_tools.testing import psnr
from step07_advanced.filter import kernels, reference
from step07_advanced.filter.shaders import impl_shader_dir

HINT = {
    "weights": "w(i) = exp(-i² / (2 sigma²)) / (sum over j = -radius..radius of exp(-j² / (2 sigma²))), "
               "sigma = radius / 2",
    "sum": "divide by the sum over ALL 2 radius + 1 taps (j = -radius..radius), so the table sums to 1",
    "identity": "radius 0 must give the identity kernel [1] (sigma is 0 there: handle it before dividing)",
    "blur": "sum kernel_weight(i) * load_texel(clamp(p + i * dir, 0, image_size() - 1)) for i = -radius..radius",
    "border": "clamp-to-edge: clamp each tap's coordinates to 0..image_size() - 1 (no wrap, no zero padding)",
    "impulse": "a one-pixel impulse must give the kernel back, along dir only (use dir, don't swap x and y)",
    "alpha": "blur all four channels: return the whole weighted sum, alpha included (not 1, not the centre's)",
}


# --- filters on headless apps, one app per API for the whole module ---------------------------------------
class _Filters:
    """One headless context (OpenGL 4.3+) and one device (WebGPU) for the module, shared by the filters on them
    (made with the first implementation asked for: a filter compiles its kernels on first use only)."""

    def __init__(self) -> None:
        self.base: dict[str, object] = {}
        self.filters: dict[tuple[str, str], object] = {}

    def get(self, backend: str, impl: ModuleType | SimpleNamespace, keep: bool = True):
        if shader_box.routes(impl):  # a student's package: its kernels run in the grader's shader process
            return _ShaderProcessFilter(backend, impl)
        key = (backend, str(impl_shader_dir(impl)))
        if key in self.filters:
            return self.filters[key]
        if backend == "opengl":
            from step07_advanced.filter.compute_gl import GLImageFilter

            if backend not in self.base:
                self.base[backend] = GLImageFilter.standalone(impl)
            flt = GLImageFilter(self.base[backend].ctx, impl)
        else:
            from step07_advanced.filter.compute_wgpu import WGPUImageFilter

            if backend not in self.base:
                self.base[backend] = WGPUImageFilter.standalone(impl)
            flt = WGPUImageFilter(self.base[backend].device, impl)
        if keep:
            self.filters[key] = flt
        return flt

    def close(self) -> None:
        for flt in self.filters.values():
            flt.release()
        for flt in self.base.values():
            flt.release()


class _ShaderProcessFilter:
    """A filter of a student's kernels, which run in the grader's shader process: its two calls, each a round trip
    that brings the numbers back (``shader_box``)."""

    def __init__(self, backend: str, impl) -> None:
        self.backend, self.impl = backend, impl

    def run(self, image: np.ndarray, op: str, radius: int = 0, weights: np.ndarray | None = None) -> np.ndarray:
        return _filter_call(self.backend, self.impl, "run", image, op, radius, weights)

    def weight_table(self, radius: int) -> np.ndarray:
        return _filter_call(self.backend, self.impl, "weight_table", radius)

    def release(self) -> None:
        pass


_in_this_process = _Filters()  # the shader process's filters (made on first use, kept for its life)


@shader_box.on_shader_box
def _filter_call(backend: str, impl, method: str, *args):
    return getattr(_in_this_process.get(backend, impl), method)(*args)


@pytest.fixture(scope="module")
def filters():
    cache = _Filters()
    yield cache
    cache.close()


def _impl_from(folder: Path) -> SimpleNamespace:
    """An implementation 'package' whose shader files are in ``folder`` (for mutants and broken shaders)."""
    return SimpleNamespace(__file__=str(folder / "__init__.py"))


# --- images ------------------------------------------------------------------------------------------------
def noise_image(width: int, height: int, seed: int = 1) -> np.ndarray:
    rng = np.random.default_rng(seed)
    image = rng.integers(0, 256, size=(height, width, 4), dtype=np.uint8)
    image[..., 3] = 255
    return image


def scene_like(width: int, height: int) -> np.ndarray:
    return reference.source_image(width, height)


def _compare_image(flt, image: np.ndarray, op: str, radius: int, kind: str, weights: bool = True,
                   region: np.ndarray | None = None) -> str | None:
    """None, or a message naming the worst pixel: input, expected against got, and a hint."""
    table = reference.gaussian_weights(radius) if weights else None
    got = flt.run(image, op, radius, table).astype(np.float64)
    expected = reference.apply(image, op, radius) * 255.0
    error = np.abs(got - expected)
    if region is not None:
        error = np.where(region[..., None], error, 0.0)
    worst = float(error.max())
    if worst <= 1.0:
        return None
    y, x, c = (int(v) for v in np.unravel_index(int(np.argmax(error)), error.shape))
    h, w = image.shape[:2]
    return (f"{op} blur, radius {radius}, {w}x{h} image: pixel (x={x}, y={y}) channel {'RGBA'[c]}: expected "
            f"{expected[y, x, c]:.2f}, got {got[y, x, c]:.0f} (off by {worst:.2f} steps of 1/255, allowed 1); "
            f"input there {image[y, x].tolist()}. Hint: {HINT[kind]}")


# --- checks of exercise blur_kernel (each returns None or a failure message) ---------------------------------
WEIGHT_RADII = (0, 1, 2, 3, 4, 7, 8, 16, 31, 32)


def check_weight_tables(flt) -> str | None:
    for r in WEIGHT_RADII:
        got = flt.weight_table(r).astype(np.float64)
        expected = reference.gaussian_weights(r)
        if not np.all(np.isfinite(got)):
            more = "…" if len(got) > 5 else ""
            return (f"radius {r}: got the weights {got[:5].tolist()}{more}, expected finite ones "
                    f"{np.round(expected[:5], 5).tolist()}{more}. Hint: {HINT['identity']}")
        error = np.abs(got - expected)
        if error.max() > 1e-5:
            k = int(np.argmax(error))
            return (f"radius {r}, tap i = {k - r}: expected weight {expected[k]:.7f}, got {got[k]:.7f} "
                    f"(tolerance 1e-5). Hint: {HINT['weights']}")
    return None


def check_weight_sums(flt) -> str | None:
    for r in range(kernels.MAX_RADIUS + 1):
        got = flt.weight_table(r).astype(np.float64)
        total = float(got.sum())
        if not np.isfinite(total) or abs(total - 1.0) > 1e-5:
            return f"radius {r}: the {2 * r + 1} weights sum to {total:.7g}, expected 1 (± 1e-5). Hint: {HINT['sum']}"
        if np.abs(got - got[::-1]).max() > 1e-7:
            return (f"radius {r}: got the weights {np.round(got, 6).tolist()}, expected a symmetric table "
                    f"(w(-i) = w(i)). "
                    f"Hint: {HINT['weights']}")
    return None


def check_identity(flt) -> str | None:
    got = flt.weight_table(0)
    if got.shape != (1,) or not abs(float(got[0]) - 1.0) <= 1e-7:
        return f"radius 0: expected the identity [1.0], got {got.tolist()}. Hint: {HINT['identity']}"
    return None


# --- checks of exercise convolve ------------------------------------------------------------------------------
def check_reference(flt) -> str | None:
    image = scene_like(37, 23)  # no multiple of the 16x16 work group
    for op in ("horizontal", "vertical", "separable"):
        for r in (1, 3, 32):
            if (msg := _compare_image(flt, image, op, r, "blur")) is not None:
                return msg
    return None


def check_radius_zero(flt) -> str | None:
    return _compare_image(flt, noise_image(21, 13, seed=4), "separable", 0, "blur")


def check_one_pixel(flt) -> str | None:
    image = np.array([[[200, 30, 120, 255]]], dtype=np.uint8)
    for r in (1, kernels.MAX_RADIUS):
        if (msg := _compare_image(flt, image, "separable", r, "border")) is not None:
            return msg
    return None


def check_borders(flt) -> str | None:
    image = noise_image(40, 24, seed=9)
    r = 6
    h, w = image.shape[:2]
    y, x = np.mgrid[0:h, 0:w]
    for op in ("horizontal", "vertical"):
        near = (x <= r) | (x >= w - 1 - r) if op == "horizontal" else (y <= r) | (y >= h - 1 - r)
        if (msg := _compare_image(flt, image, op, r, "border", region=near)) is not None:
            return msg
    return None


def check_alpha(flt) -> str | None:
    """"Return the sum (all four channels)": a translucent image (random alpha) blurs its alpha like its colours."""
    image = noise_image(29, 17, seed=12)
    image[..., 3] = np.random.default_rng(13).integers(0, 256, size=image.shape[:2], dtype=np.uint8)
    return _compare_image(flt, image, "separable", 4, "alpha")


def check_constant(flt) -> str | None:
    image = np.empty((23, 37, 4), dtype=np.uint8)
    image[:] = (90, 161, 40, 255)
    return _compare_image(flt, image, "separable", 9, "sum")


def check_impulse(flt) -> str | None:
    image = np.zeros((41, 41, 4), dtype=np.uint8)
    image[..., 3] = 255
    image[20, 20, :3] = 255
    r = 8
    for op in ("horizontal", "vertical"):
        got = flt.run(image, op, r, reference.gaussian_weights(r))[..., 0].astype(np.float64)
        line = got[20, 20 - r:21 + r] if op == "horizontal" else got[20 - r:21 + r, 20]
        expected = 255.0 * reference.gaussian_weights(r)
        rest = got.copy()
        if op == "horizontal":
            rest[20, 20 - r:21 + r] = 0.0
        else:
            rest[20 - r:21 + r, 20] = 0.0
        if np.abs(line - expected).max() > 1.0 or rest.max() > 0.0 or np.any(line != line[::-1]):
            return (f"{op} pass of an impulse (255 at the centre of a black 41x41 image, radius {r}): expected the "
                    f"kernel along the {'row' if op == 'horizontal' else 'column'} {np.rint(expected).tolist()}, "
                    f"got {line.tolist()} there and a largest value of {rest.max():.0f} elsewhere. "
                    f"Hint: {HINT['impulse']}")
    return None


CHECKS = {
    "blur_kernel": {"tables": check_weight_tables, "sums": check_weight_sums, "identity": check_identity},
    "convolve": {"reference": check_reference, "radius_zero": check_radius_zero, "one_pixel": check_one_pixel,
                 "borders": check_borders, "constant": check_constant, "impulse": check_impulse,
                 "alpha": check_alpha},
}


def _grade(filters, exercise: str, check: str, impl, backend: str) -> None:
    message = CHECKS[exercise][check](filters.get(backend, impl))
    if message is not None:
        pytest.fail(f"[{LANGUAGE[backend]}] {message}", pytrace=False)


@pytest.mark.exercise("blur_kernel")
@pytest.mark.parametrize("check", list(CHECKS["blur_kernel"]))
def test_blur_kernel(filters, impl, backend, check):
    _grade(filters, "blur_kernel", check, impl, backend)


@pytest.mark.exercise("convolve")
@pytest.mark.parametrize("check", list(CHECKS["convolve"]))
def test_convolve(filters, impl, backend, check):
    _grade(filters, "convolve", check, impl, backend)


# --- the engine side (not graded) ---------------------------------------------------------------------------
def test_shared_memory_limit_names_the_limit():
    assert kernels.shared_bytes() == 8192 and kernels.largest_radius_for(16384) == 96
    kernels.check_shared_memory(16384, "maxComputeWorkgroupStorageSize")
    with pytest.raises(RuntimeError, match="needs 8192 bytes.*maxComputeWorkgroupStorageSize is 4096"):
        kernels.check_shared_memory(4096, "maxComputeWorkgroupStorageSize")


def test_reference_rules():
    for r in range(kernels.MAX_RADIUS + 1):
        w = reference.gaussian_weights(r)
        assert w.shape == (2 * r + 1,) and abs(w.sum() - 1.0) < 1e-12 and np.allclose(w, w[::-1])
    assert reference.gaussian_weights(2)[2] / reference.gaussian_weights(2)[3] == pytest.approx(np.exp(0.5))
    image = reference.to_float(noise_image(19, 11))
    assert np.allclose(reference.blur(image, 5), reference.blur_2d(image, 5), atol=1e-12)
    assert np.array_equal(reference.blur(image, 0), image)
    constant = np.full((5, 7, 4), 0.3)
    assert np.allclose(reference.blur(constant, 9), 0.3) and np.all(reference.sobel(constant)[..., :3] == 0.0)
    edge = np.zeros((6, 6, 4))
    edge[:, 3:, :3] = 0.5  # a vertical step of 0.5: |g| = 2 on both sides of it, shown as white
    assert np.allclose(reference.sobel(edge)[:, 2:4, 0], 1.0) and np.all(reference.sobel(edge)[:, [0, 5], 0] == 0.0)


def test_both_apis_show_the_same_picture():
    from gandalf_tools.testing import render_frames
    from step07_advanced.filter import opengl, scene, webgpu

    pictures = {m.__name__: render_frames(m.create_app, frames=1, width=160, height=120) for m in (opengl, webgpu)}
    gl, wg = pictures.values()
    value = psnr(gl, wg)
    assert value >= 35.0, f"OpenGL and WebGPU pictures differ: PSNR {value:.1f} dB (need >= 35)"
    # the blur panel (top right) is smoother than the original (top left): less pixel-to-pixel variation
    left, right = gl[10:50, 10:70, :3].astype(float), gl[10:50, 90:150, :3].astype(float)
    assert np.abs(np.diff(right, axis=1)).mean() < 0.8 * np.abs(np.diff(left, axis=1)).mean()
    assert scene.TOUR_FRAMES >= 1


def test_study_help_only_prints_help(capsys):
    from step07_advanced.filter import study

    with pytest.raises(SystemExit) as exc:
        study.main(["--help"])
    assert exc.value.code == 0 and "--quick" in capsys.readouterr().out


if __name__ == "__main__":  # pragma: no cover
    sys.exit(pytest.main([__file__, "-q"]))
