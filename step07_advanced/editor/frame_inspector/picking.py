"""Pixel picking: which draw, entity, material and shader wrote a pixel, and its depth, in both APIs.

A pick draws the frame again, only where it is asked: the captured frame's draws (:mod:`.capture`) replayed in their
order with their own pipelines, one instance at a time, with a scissor of one pixel and an occlusion query around
each instance (``ctx.query(samples=True)`` in OpenGL, an ``occlusion`` query set in WebGPU). The last instance
whose fragments passed the depth test there wrote the pixel; the depth buffer then holds its depth. Using the
scene's own shaders (not an id shader of the engine's), a vertex shader that displaces, a tessellated terrain or a
mesh pulled from a buffer picks exactly as it draws. It costs one replay of the frame's draws at one pixel, and only
when asked; the frame's picture is left as it was (OpenGL redraws the one pixel as it was, WebGPU replays into
targets of its own).
"""

from __future__ import annotations

import uuid
from dataclasses import dataclass
from typing import Any

import numpy as np

from gandalf_core.render.frame import DrawBatch

from .capture import DrawRecord, FrameCapture, FrameRecorder, name_entities

#: The passes a pick replays (the shadow map and the overlays write no pixel of the scene).
PICKED_PASSES = ("opaque", "sky", "transparent")


@dataclass
class Pick:
    """What wrote pixel (``x``, ``y``): the draw (None: only the clear colour), the instance in it and its entity,
    the material and shader, and the depth-buffer value there (in the API's depth range)."""

    x: int
    y: int
    draw: DrawRecord | None
    instance: int | None
    entity: uuid.UUID | None
    depth: float

    @property
    def material(self) -> str | None:
        return self.draw.material if self.draw is not None else None

    @property
    def shader(self) -> str | None:
        return self.draw.shader if self.draw is not None else None

    @property
    def shader_files(self) -> list[str]:
        return self.draw.shader_files if self.draw is not None else []

    def describe(self) -> str:
        if self.draw is None:
            return f"pixel ({self.x}, {self.y}): background (no draw), depth {self.depth:.6g}"
        what = f"entity {self.entity}" if self.entity is not None else "no entity"
        return (f"pixel ({self.x}, {self.y}): draw {self.draw.label} in pass '{self.draw.pass_name}', {what}, "
                f"material '{self.draw.material}', shader '{self.draw.shader}', depth {self.depth:.6g}")


def pick(app: Any, x: int, y: int) -> Pick:
    """Render ``app``'s scene once more (its next frame's data, into the renderer's own target) and pick pixel
    (``x`` from the left, ``y`` from the top)."""
    from gandalf_core.render.render_system import RenderSystem

    systems = [s for s in app.scene.systems if isinstance(s, RenderSystem)]
    if not systems:
        raise ValueError(f"pick: scene '{app.scene.name}' has no RenderSystem")
    return pick_frame(app.renderer, systems[0].frame_data(0.0), app.scene, x, y)


def pick_frame(renderer: Any, data: Any, scene: Any, x: int, y: int) -> Pick:
    """Render frame ``data`` of ``scene`` into the renderer's current target (the editor's viewport target while
    it draws) with a capture, then pick pixel (``x``, ``y``) of it."""
    if not (0 <= int(x) < renderer.width and 0 <= int(y) < renderer.height):
        raise ValueError(f"pick: pixel ({x}, {y}) lies outside the {renderer.width}x{renderer.height} frame")
    recorder = FrameRecorder(renderer, timing=False)
    overlays, renderer.overlays = renderer.overlays, []  # the scene alone: no GUI drawn over it
    previous, renderer.recorder = renderer.recorder, recorder
    try:
        renderer.render(data, scene.assets)
    except BaseException:
        recorder.abandon()
        raise
    finally:
        renderer.recorder = previous  # a capture the editor has armed goes on with the next frame
        renderer.overlays = overlays
    capture = recorder.finish()
    name_entities(capture, scene)
    return pick_captured(renderer, capture, data, scene.assets, int(x), int(y))


def pick_captured(renderer: Any, capture: FrameCapture, data: Any, assets: Any, x: int, y: int) -> Pick:
    """Pick pixel (``x``, ``y``) of the frame just rendered and captured (the renderer still holds its data)."""
    draws = [d for d in capture.draws if d.pass_name in PICKED_PASSES]
    calls = dict(renderer.stats)
    try:
        if renderer.backend == "opengl":
            samples, depth = _replay_gl(renderer, draws, data, assets, x, y)
        else:
            samples, depth = _replay_wgpu(renderer, draws, data, assets, x, y)
    finally:
        renderer.stats.update(calls)  # a pick is not a frame: the counters stay the frame's
    winner = None
    for key, count in samples:
        if count > 0:
            winner = key
    if winner is None:
        return Pick(x, y, None, None, None, depth)
    draw, instance = winner
    entity = draw.entities[instance] if instance is not None and instance < len(draw.entities) else None
    return Pick(x, y, draw, instance, entity, depth)


def _instances(draw: DrawRecord) -> list[DrawBatch | None]:
    """One batch per instance of a scene draw (None for the sky's one triangle)."""
    if draw.mesh is None:
        return [None]
    return [DrawBatch(draw.mesh, draw.material, np.array(draw.rows[i:i + 1] or [0], dtype=np.intp),
                      first_instance=draw.first_instance + i, mirrored=draw.mirrored)
            for i in range(draw.instances)]


def _replay_gl(renderer: Any, draws: list[DrawRecord], data: Any, assets: Any, x: int,
               y: int) -> tuple[list[Any], float]:
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
            for i, batch in enumerate(_instances(draw)):
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


def _replay_wgpu(renderer: Any, draws: list[DrawRecord], data: Any, assets: Any, x: int,
                 y: int) -> tuple[list[Any], float]:
    import wgpu

    device = renderer.device
    count = sum(len(_instances(d)) for d in draws) or 1
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
        shadow = renderer._shadow
        rpass.set_bind_group(0, shadow[2] if data.shadows and shadow is not None else renderer._frame_group)
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
            for i, batch in enumerate(_instances(draw)):
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
