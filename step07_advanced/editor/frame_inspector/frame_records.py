"""The records of a captured frame (:mod:`.capture`): passes in order, and per draw what went into it.

Kept apart from the recorder (:mod:`.capture`) so that the per-draw description it calls (:mod:`.inspect_draw`)
can build records without importing it back.
"""

from __future__ import annotations

import uuid
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from gandalf_core.render.frame import DrawBatch


@dataclass
class DrawRecord:
    """One draw call as it was issued."""

    index: int  # in the frame, from 0
    pass_name: str
    mesh: str | None
    material: str | None
    shader: str
    shader_files: list[str]
    instances: int
    first_instance: int
    rows: list[int]  # rows of the TransformComponent store (None-free; the sky has none)
    vertex_count: int
    index_count: int
    layout: list[str]  # "name: format @offset", the vertex buffer's attributes
    state: dict[str, Any]
    blocks: dict[str, dict[str, Any]]  # block name -> {"binding": ..., "values": {field: value}}
    textures: list[dict[str, Any]]
    buffers: list[dict[str, Any]]
    mirrored: bool = False  # its instances' world matrices flip handedness (clockwise front faces)
    sky: str | None = None  # the sky pass's cube texture
    entities: list[uuid.UUID] = field(default_factory=list)
    gpu_ms: float | None = None

    @property
    def label(self) -> str:
        what = f"{self.mesh} · {self.material}" if self.mesh else self.shader
        return f"#{self.index} {what} ×{self.instances}"


@dataclass
class PassRecord:
    """A pass: a run of draws of one kind into one target."""

    name: str
    target: str
    draws: list[DrawRecord] = field(default_factory=list)
    gpu_ms: float | None = None


@dataclass
class FrameCapture:
    """One captured frame (see the module's docstring)."""

    backend: str
    passes: list[PassRecord]
    #: Which GPU timer ran, or why there was none.
    timing: str
    #: GPU milliseconds of each render() call of the frame, first timestamp to last (None without a timer).
    frame_gpu_ms: list[float] = field(default_factory=list)
    #: Whether the (last) render() call drew with reverse-Z.
    reverse_z: bool = False
    #: The buffers and textures the renderer held after the frame, in bytes by kind (``Renderer.gpu_memory()``).
    gpu_memory: dict[str, int] = field(default_factory=dict)

    @property
    def draws(self) -> list[DrawRecord]:
        return [d for p in self.passes for d in p.draws]

    def pass_names(self) -> list[str]:
        return [p.name for p in self.passes]

    def draws_of(self, entity: uuid.UUID) -> list[DrawRecord]:
        """The draws that drew ``entity``."""
        return [d for d in self.draws if entity in d.entities]


def instance_batches(draw: DrawRecord) -> list[DrawBatch | None]:
    """One batch per instance of a scene draw (None for the sky's one triangle)."""
    if draw.mesh is None:
        return [None]
    return [DrawBatch(draw.mesh, draw.material, np.array(draw.rows[i:i + 1] or [0], dtype=np.intp),
                      first_instance=draw.first_instance + i, mirrored=draw.mirrored)
            for i in range(draw.instances)]
