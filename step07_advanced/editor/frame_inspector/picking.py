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
            from .picking_gl import replay
        else:
            from .picking_wgpu import replay
        samples, depth = replay(renderer, draws, data, assets, x, y)
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
