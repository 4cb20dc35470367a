"""The frame the plain-API lesson files (``stepNN_*/*_gl.py`` and ``*_wgpu.py``) share around their API calls.

Steps 01 and 02's lessons make every moderngl or wgpu call themselves, up to and including the read-back of their
frame: the offscreen target, the render pass and the copy back are their subject. The later lessons teach something
else (textures, uniforms, lights) and draw into the same frame through :func:`gl_frame` and :func:`wgpu_frame`,
which hold exactly those calls, written once. :func:`image` turns read-back bytes into a picture (OpenGL's rows
start at the bottom, WebGPU's at the top) and :func:`command` gives every lesson the same command line
(``--out FILE.png --size WIDTHxHEIGHT``). :func:`webgpu_limits` is what a WebGPU lesson asks its device for.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from typing import Any

import numpy as np

from gandalf_core.render.capabilities import FLOOR, Needs, check, webgpu_offer

#: The background every lesson clears to (opaque black), in both APIs.
CLEAR = (0.0, 0.0, 0.0, 1.0)


def image(pixels: bytes, width: int, height: int, *, bottom_up: bool) -> np.ndarray:
    """The read-back RGBA8 ``pixels`` as a (height, width, 4) uint8 array, top row first.

    ``bottom_up``: the rows start at the bottom (OpenGL's ``fbo.read``), not at the top (WebGPU's ``read_texture``).
    """
    rows = np.frombuffer(pixels, dtype=np.uint8).reshape(height, width, 4)
    return (rows[::-1] if bottom_up else rows).copy()


def webgpu_limits(adapter: Any, what: str, needs: Needs = FLOOR) -> dict[str, int]:
    """The limits a WebGPU lesson ``what`` requests its device with: WebGPU's defaults (what every implementation
    guarantees), raised where ``needs`` says, after checking that ``adapter`` has them (a
    :class:`~gandalf_core.render.capabilities.CapabilityError` that names the lesson and the gap).

    ``adapter.request_device_sync()`` without limits asks wgpu for everything the adapter has: a lesson that then
    used more than the defaults would run here and fail on another GPU or in a browser."""
    if adapter is None:
        raise RuntimeError(f"{what}: no WebGPU adapter found: install a Vulkan driver (on Debian: "
                           "mesa-vulkan-drivers libvulkan1)")
    check(needs, webgpu_offer(adapter), what)
    return needs.device_limits(adapter.limits)


def gl_frame(ctx: Any, width: int, height: int, draw: Callable[[], None], *, depth: bool = False) -> np.ndarray:
    """Step 02's OpenGL frame: an RGBA8 framebuffer (with a depth buffer if ``depth``), cleared to :data:`CLEAR`
    (depth to 1), in which ``draw()`` makes its draw calls; read back as (height, width, 4) uint8, top row first."""
    size = (width, height)
    fbo = ctx.framebuffer(color_attachments=[ctx.texture(size, 4)],
                          depth_attachment=ctx.depth_renderbuffer(size) if depth else None)
    fbo.use()
    ctx.clear(*CLEAR, depth=1.0)
    draw()
    return image(fbo.read(components=4), width, height, bottom_up=True)


def wgpu_frame(device: Any, width: int, height: int, draw: Callable[[Any], None], *,
               depth: bool = False) -> np.ndarray:
    """Step 02's WebGPU frame: an rgba8unorm target (with a depth24plus one if ``depth``) and one render pass that
    clears it to :data:`CLEAR` (depth to 1), in which ``draw(rpass)`` records its draws; the pass is submitted and
    the target read back as (height, width, 4) uint8, top row first."""
    import wgpu

    attachment = wgpu.TextureUsage.RENDER_ATTACHMENT
    target = device.create_texture(size=(width, height, 1), format="rgba8unorm",
                                   usage=attachment | wgpu.TextureUsage.COPY_SRC)
    depth_attachment = None
    if depth:
        depth_texture = device.create_texture(size=(width, height, 1), format="depth24plus", usage=attachment)
        depth_attachment = {"view": depth_texture.create_view(), "depth_clear_value": 1.0, "depth_load_op": "clear",
                            "depth_store_op": "store"}
    encoder = device.create_command_encoder()
    rpass = encoder.begin_render_pass(
        color_attachments=[{"view": target.create_view(), "clear_value": CLEAR, "load_op": "clear",
                            "store_op": "store"}],
        depth_stencil_attachment=depth_attachment)
    draw(rpass)
    rpass.end()
    device.queue.submit([encoder.finish()])
    pixels = device.queue.read_texture({"texture": target}, {"bytes_per_row": 4 * width, "rows_per_image": height},
                                       (width, height, 1))
    return image(pixels, width, height, bottom_up=False)


def command(render: Callable[[int, int], np.ndarray], doc: str, out: str,
            size: str = "640x480") -> Callable[[list[str] | None], int]:
    """A lesson's ``main(argv=None)``: :func:`main` with the lesson's ``render``, docstring and default PNG name."""

    def lesson_main(argv: list[str] | None = None) -> int:
        return main(render, doc, out, size, argv=argv)

    return lesson_main


def main(render: Callable[[int, int], np.ndarray], doc: str, out: str, size: str = "640x480",
         argv: list[str] | None = None) -> int:
    """A lesson's command line: render ``WIDTHxHEIGHT`` with ``render(width, height)`` and write the PNG ``--out``.

    ``doc`` is the lesson's module docstring (its first line is the help's description).
    """
    from PIL import Image

    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--out", default=out, help=f"PNG file to write (default: {out})")
    parser.add_argument("--size", default=size, help=f"WIDTHxHEIGHT (default: {size})")
    args = parser.parse_args(argv)
    width, height = (int(v) for v in args.size.lower().split("x"))
    Image.fromarray(render(width, height)).save(args.out)
    print(f"wrote {args.out}")
    return 0
