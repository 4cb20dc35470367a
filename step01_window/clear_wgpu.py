"""Step 01's API lesson in plain wgpu: clear a frame to one colour and read it back.

WebGPU has no current context and no immediate calls: you ask for an adapter and a device, *record* a render
pass whose colour attachment says "clear on load" into a command encoder, *submit* the finished command buffer
to the queue, and copy the texture back. On a window the target is ``context.get_current_texture()`` and the
"present" step is ``context.present()``; headless it is a texture of our own.
Compare with ``clear_gl.py``: the picture is the same, the route is not.
"""

from __future__ import annotations

import numpy as np
import wgpu

from gandalf_tools import lesson

#: The clear colour, linear RGBA; 0.2, 0.4 and 0.8 are exact multiples of 1/255 (51, 102, 204).
COLOR = (0.2, 0.4, 0.8, 1.0)


def render(width: int = 64, height: int = 48, color: tuple = COLOR) -> np.ndarray:
    """One cleared frame as (height, width, 4) uint8, top row first."""
    # --8<-- [start:frame]
    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    # Ask for WebGPU's default limits, not for all this adapter has (wgpu's default): what runs here then
    # runs on every WebGPU implementation, and a lesson that needs more says so before it starts.
    limits = lesson.webgpu_limits(adapter, "step01_window.clear_wgpu")
    device = adapter.request_device_sync(required_limits=limits)
    target = device.create_texture(size=(width, height, 1), format="rgba8unorm",
                                   usage=wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC)
    encoder = device.create_command_encoder()  # nothing runs yet: we record
    rpass = encoder.begin_render_pass(color_attachments=[{
        "view": target.create_view(), "clear_value": color,
        "load_op": "clear", "store_op": "store",  # the clear is part of the pass
    }])
    rpass.end()
    device.queue.submit([encoder.finish()])  # now it runs
    pixels = device.queue.read_texture({"texture": target},
                                       {"bytes_per_row": 4 * width, "rows_per_image": height},
                                       (width, height, 1))
    device.destroy()
    # --8<-- [end:frame]
    return lesson.image(pixels, width, height, bottom_up=False)  # rows top-down


main = lesson.command(render, __doc__, "clear_wgpu.png")


if __name__ == "__main__":
    raise SystemExit(main())
