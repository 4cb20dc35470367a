"""Step 04's own code with the reference solutions: camera switching, both APIs agree, the tour picture."""

from __future__ import annotations

from step04_helpers import REFERENCES, make_app, rendered_camera

from gandalf_core.components import CameraComponent
from gandalf_tools.testing import compare_images, compare_to_reference, psnr, render_frames
from step04_camera import opengl, solutions, webgpu


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


def test_default_view_matches_the_reference(backend):
    with make_app(backend, solutions) as app:
        app.step()
        compare_to_reference(app.capture(), REFERENCES / "default_view.png", min_psnr=40.0)


def test_opengl_and_webgpu_agree():
    # Same scene, same camera, each API's own depth range: PSNR >= 40 dB (measured ~49 dB: a few edge texels
    # of the nearest-filtered checkerboard round the other way).
    gl = render_frames(opengl.create_app, 2, width=160, height=120)
    wg = render_frames(webgpu.create_app, 2, width=160, height=120)
    compare_images(wg, gl, "step04-gl-vs-webgpu", min_psnr=40.0)
