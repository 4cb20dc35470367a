"""A pick's replay on WebGPU (see :mod:`.picking`): the frame's draws again into colour and depth targets of its
own, scissored to one pixel, with an ``occlusion`` query set; the frame's picture is left alone."""

from __future__ import annotations

from typing import Any

import numpy as np

from .frame_records import DrawRecord, instance_batches


def replay(renderer: Any, draws: list[DrawRecord], data: Any, assets: Any, x: int, y: int) -> tuple[list[Any], float]:
    """Replay ``draws`` into targets of its own, scissored to pixel (``x``, ``y``), with an occlusion query per
    instance: (key, samples) each, and the depth there."""
    import wgpu

    device = renderer.device
    count = sum(len(instance_batches(d)) for d in draws) or 1
    usage = wgpu.TextureUsage
    size = (renderer.width, renderer.height, 1)
    color = device.create_texture(size=size, format=renderer._target_format, usage=usage.RENDER_ATTACHMENT)
    depth = device.create_texture(size=size, format="depth32float", usage=usage.RENDER_ATTACHMENT | usage.COPY_SRC)
    queries = device.create_query_set(type="occlusion", count=count)
    resolved = device.create_buffer(size=8 * count, usage=wgpu.BufferUsage.QUERY_RESOLVE | wgpu.BufferUsage.COPY_SRC)
    try:
        encoder = device.create_command_encoder()
        rpass = encoder.begin_render_pass(
            color_attachments=[{"view": color.create_view(), "clear_value": tuple(float(c) for c in data.clear_color),
                                "load_op": "clear", "store_op": "store"}],
            depth_stencil_attachment={"view": depth.create_view(), "depth_clear_value": 0.0 if data.reverse_z
                                      else 1.0, "depth_load_op": "clear", "depth_store_op": "store"},
            occlusion_query_set=queries,
        )
        rpass.set_scissor_rect(x, y, 1, 1)
        rpass.set_bind_group(0, renderer.frame_group(bool(data.shadows) and renderer._shadow is not None))
        keys: list[Any] = []
        for draw in draws:
            if draw.mesh is None:  # the sky
                pipeline, group = renderer._sky_draw(draw.sky, assets, data.reverse_z)
                rpass.set_pipeline(pipeline)
                rpass.set_bind_group(1, group)
                rpass.begin_occlusion_query(len(keys))
                rpass.draw(3)
                rpass.end_occlusion_query()
                keys.append((draw, None))
                continue
            material = renderer.materials.get(draw.material)
            mesh = renderer.meshes.get(draw.mesh)
            pipeline, attributes = renderer._pipeline(material, mesh, data.reverse_z, draw.mirrored)
            rpass.set_pipeline(pipeline)
            if material.bind_group is not None:
                rpass.set_bind_group(1, material.bind_group)
            for i, batch in enumerate(instance_batches(draw)):
                rpass.begin_occlusion_query(len(keys))
                renderer._draw_batch(rpass, material.shader, mesh, attributes, batch)
                rpass.end_occlusion_query()
                keys.append((draw, i))
        rpass.end()
        encoder.resolve_query_set(queries, 0, count, resolved, 0)
        device.queue.submit([encoder.finish()])
        samples = np.frombuffer(device.queue.read_buffer(resolved, 0, 8 * count), dtype=np.uint64).tolist()
        # A depth texture is copied whole or not at all (WebGPU's rule): read it all, keep one texel.
        data_bytes = device.queue.read_texture({"texture": depth, "origin": (0, 0, 0), "aspect": "depth-only"},
                                               {"offset": 0, "bytes_per_row": 4 * renderer.width,
                                                "rows_per_image": renderer.height}, size)
        value = float(np.frombuffer(data_bytes, dtype=np.float32)[y * renderer.width + x])
    finally:
        for obj in (color, depth, resolved):
            obj.destroy()
        queries.destroy()
    return list(zip(keys, samples)), value
