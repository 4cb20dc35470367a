"""Shared helpers of the step 05 tests: a scene run without a window, and a concept's picture after a second of
its scene, in either API."""

from __future__ import annotations

from types import ModuleType

import numpy as np

from gandalf_core import Scene, TransformSystem
from gandalf_tools.testing import compare_images, render_frames


def run_scene(scene: Scene, frames: int, dt: float = 1 / 60) -> None:
    """Update ``scene`` ``frames`` times by ``dt``, with a TransformSystem added if it has none."""
    if not any(isinstance(s, TransformSystem) for s in scene.systems):
        scene.add_system(TransformSystem())
    for _ in range(frames):
        scene.update(dt)


def picture(variants: dict[str, ModuleType], backend: str) -> np.ndarray:
    """The 160x120 picture of ``variants[backend]``'s app after 60 frames."""
    return render_frames(variants[backend].create_app, 60, width=160, height=120)


def check_both_apis_agree(variants: dict[str, ModuleType], name: str) -> None:
    """The WebGPU and OpenGL pictures of a concept agree (PSNR at least 40 dB); ``name`` names the diff images."""
    compare_images(picture(variants, "webgpu"), picture(variants, "opengl"), f"step05-{name}-webgpu-vs-opengl",
                   min_psnr=40.0)
