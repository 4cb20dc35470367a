"""Step 04's own code with the reference solutions: camera switching, both APIs agree, the tour picture.

The tour picture is compared with its reference (made with Mesa's llvmpipe and lavapipe) within what another
implementation may legally draw differently: the receding tiled floor's pixels whose mip level the
specifications leave open are left out (``legal_lod``: 17.8 % of the picture here), and the rest must agree
within step 03's local differences (99.5 % of pixels within 32 levels, no 8 × 8 square off by more than 12 on
average: edge coverage and nearest-texel rounding). Mesa's softpipe picks the next mip level on a band of the
far floor (up to 80 levels on 0.6 % of the pixels, 21 on average over one 8 × 8 square): all of it inside the
left-out pixels. Plausible orbit-camera bugs still break the comparison.
"""

from __future__ import annotations

import math
import os
from types import SimpleNamespace

import numpy as np
import pytest
from legal_lod import mip_flip_pixels, plane_texels
from PIL import Image
from step04_helpers import REFERENCES, SIZE, make_app, rendered_camera

from gandalf_core.components import CameraComponent
from gandalf_core.math import look_at_rotation
from gandalf_tools.testing import LocalDifferences, compare_images, compare_to_reference, psnr, render_frames
from step04_camera import opengl, solutions, webgpu

#: The floor as ``scene.build_scene`` makes it: a 12 × 12 plane at y = 0 with a 64-texel nearest-filtered,
#: mipmapped checkerboard.
FLOOR_HEIGHT, FLOOR_EXTENT, FLOOR_TEXELS = 0.0, 12.0, 64
AGAINST_REFERENCE = LocalDifferences(level=32, share=0.995)
#: At most this share of the picture is left out (the far floor): the rest still decides.
MOST_LEFT_OUT = 0.25


def primaries(app) -> list[bool]:
    return [c.primary for c in app.scene.query(CameraComponent).column(CameraComponent)]


def test_c_switches_the_primary_camera(backend):
    with make_app(backend, solutions) as app:
        app.step()
        perspective = app.capture()
        assert primaries(app) == [True, False]
        assert rendered_camera(app)[1][3, 2] == -1.0  # perspective: w = -z
        app.input.key("C")
        app.step()
        assert primaries(app) == [False, True]
        assert rendered_camera(app)[1][3, 3] == 1.0  # orthographic: w = 1
        assert psnr(app.capture(), perspective) < 20.0  # a clearly different picture
        app.input.key("C", "release")
        app.step()
        assert primaries(app) == [False, True]  # holding or releasing C does not switch again
        app.input.key("C")
        app.step()
        assert primaries(app) == [True, False]
        compare_images(app.capture(), perspective, f"step04-switch-back-{backend}", min_psnr=60.0)


def default_view(backend: str, impl) -> tuple[np.ndarray, np.ndarray]:
    """(the picture, the pixels whose floor mip level the specifications leave open) of the default view."""
    with make_app(backend, impl) as app:
        app.step()
        view, projection = rendered_camera(app)
        picture = app.capture()
    return picture, mip_flip_pixels(plane_texels(view, projection, SIZE, FLOOR_HEIGHT, FLOOR_EXTENT, FLOOR_TEXELS))


def reference_picture() -> np.ndarray:
    return np.asarray(Image.open(REFERENCES / "default_view.png").convert("RGBA"))


def test_default_view_matches_the_reference(backend):
    picture, open_level = default_view(backend, solutions)
    if os.environ.get("GANDALF_UPDATE_REFERENCES") == "1":
        compare_to_reference(picture, REFERENCES / "default_view.png")
        return
    assert open_level.mean() <= MOST_LEFT_OUT, f"{open_level.mean():.1%} of the picture left out"
    reference = reference_picture()
    compare_images(np.where(open_level[..., None], reference, picture), reference, f"default_view-{backend}",
                   local=AGAINST_REFERENCE)


def _orbit_bug(eye_and_target):
    """The reference orbit camera, then the camera placed by ``eye_and_target(orbit) -> (eye, target)``."""

    class Bugged(solutions.OrbitCameraSystem):
        def on_update_system(self, ts: float) -> None:
            super().on_update_system(ts)
            for orbit, transform in self.components:
                eye, target = eye_and_target(orbit)
                transform.translation = eye
                transform.quaternion = look_at_rotation(eye, target)

    return Bugged


def _direction(yaw: float, pitch: float) -> np.ndarray:
    return np.array([math.cos(pitch) * math.sin(yaw), math.sin(pitch), math.cos(pitch) * math.cos(yaw)])


#: Plausible orbit-camera mistakes that change the default view, each drawn through the whole scene.
ORBIT_BUGS = {
    "degrees used as radians": lambda o: (o.target + o.distance * _direction(o.yaw, o.pitch), o.target),
    "yaw turned the other way": lambda o: (o.target + o.distance * _direction(-math.radians(o.yaw),
                                                                            math.radians(o.pitch)), o.target),
    "orbits the world origin": lambda o: (o.distance * _direction(math.radians(o.yaw), math.radians(o.pitch)),
                                          o.target),
    "looks at the origin, not the target": lambda o: (
        o.target + o.distance * _direction(math.radians(o.yaw), math.radians(o.pitch)), np.zeros(3)),
}


@pytest.mark.parametrize("bug", list(ORBIT_BUGS))
def test_the_legal_differences_still_catch_plausible_bugs(bug):
    impl = SimpleNamespace(look_at=solutions.look_at, OrbitCameraSystem=_orbit_bug(ORBIT_BUGS[bug]))
    picture, open_level = default_view("opengl", impl)
    reference = reference_picture()
    assert AGAINST_REFERENCE.violations(np.where(open_level[..., None], reference, picture), reference), (
        f"{bug}: drawn within the legal local differences")


def test_opengl_and_webgpu_agree():
    # Same scene, same camera, each API's own depth range: PSNR >= 40 dB (measured ~49 dB: a few edge texels
    # of the nearest-filtered checkerboard round the other way).
    gl = render_frames(opengl.create_app, 2, width=160, height=120)
    wg = render_frames(webgpu.create_app, 2, width=160, height=120)
    compare_images(wg, gl, "step04-gl-vs-webgpu", min_psnr=40.0)
