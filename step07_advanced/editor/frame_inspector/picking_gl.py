"""A pick's replay on OpenGL (see :mod:`.picking`): the frame's draws again into its own framebuffer, scissored to
one pixel, with ``ctx.query(samples=True)`` around each instance; the pixel is drawn again as it was."""

from __future__ import annotations

from typing import Any

import numpy as np

from .frame_records import DrawRecord, instance_batches


def replay(renderer: Any, draws: list[DrawRecord], data: Any, assets: Any, x: int, y: int) -> tuple[list[Any], float]:
    """Replay ``draws`` at pixel (``x``, ``y``) with an occlusion query per instance: (key, samples) each, and the
    depth there."""
    renderer.make_current()
    ctx = renderer.ctx
    fbo = renderer.framebuffer
    fbo.use()
    gl_y = renderer.height - 1 - y  # GL's rows count from the bottom
    pixel = (x, gl_y, 1, 1)
    r, g, b, a = (float(c) for c in data.clear_color)
    fbo.depth_mask = True
    fbo.clear(r, g, b, a, depth=0.0 if data.reverse_z else 1.0, viewport=pixel)
    renderer._clip_depth(data.reverse_z)
    renderer._state = None
    renderer.use_instance_rows()  # an overlay drawn since the frame may have bound another texture there
    results: list[Any] = []
    fbo.scissor = pixel
    try:
        for draw in draws:
            if draw.mesh is None:  # the sky
                sky = renderer._prepare_sky(draw.sky, assets)
                query = ctx.query(samples=True)
                with query:
                    renderer._draw_sky(sky, data.reverse_z)
                results.append(((draw, None), query))
                continue
            material = renderer.materials.get(draw.material)
            mesh = renderer.meshes.get(draw.mesh)
            renderer._apply_state(material.data, data.reverse_z, draw.mirrored)
            material.apply()
            for i, batch in enumerate(instance_batches(draw)):
                query = ctx.query(samples=True)
                with query:
                    renderer._draw_batch(material.shader, mesh, batch)
                results.append(((draw, i), query))
        depth = np.frombuffer(fbo.read(viewport=pixel, attachment=-1, dtype="f4"), dtype=np.float32)[0]
    finally:
        fbo.scissor = None
        renderer._clip_depth(False)
        renderer._state = None
    return [(key, query.samples) for key, query in results], float(depth)
