"""What a frame hands a renderer: camera and light uniforms, and instanced draw batches (written once for
both APIs).

Per-instance data is the entity's world matrix as three float32 ``vec4`` rows (the affine part; the
last row is always 0 0 0 1): 48 bytes an instance, uploaded in one write per frame. Shaders rebuild
the model matrix from the rows and the normal matrix from cross products of its columns, so the CPU
never inverts a matrix per entity.

The frame and light uniform blocks are declared once (``resources/blocks.py``: FRAME_LAYOUT, LIGHTS_LAYOUT) and
packed by field name with the one layout rule (``resources/layout.py``): the same bytes in GLSL (std140) and WGSL
(see ``shaders/frame.glsl`` and ``shaders/frame.wgsl``).

**Camera-relative positions.** Everything the GPU sees is relative to the camera: the instance rows' translations,
the view matrix, point lights and the shadow projection are moved by ``-origin`` (the camera's world position) in
float64 on the CPU, before they become float32. A world 1e6 units from the origin then draws like one at the
origin; shaders that need absolute positions add ``origin_high + origin_low`` (the origin split into two float32s).

**Time.** A plain float32 time steps by 2 s at 3e7 s (a year), so no shader gets one. The time since start is kept
in float64 on the CPU and handed over in forms that stay smooth (each wrap taken in float64):

* ``time.x``: seconds wrapped to :data:`TIME_WRAP` (1024 s), steps exact to 1.2e-4 s; ``time.z`` counts the wraps.
  ``fract(time.x * f)`` is smooth across the wrap when ``1024 f`` is a whole number (periods of 1024 s / n:
  1 s, 0.5 s, 2 s, 1/60 s ...), a plain ``sin(time.x)`` is not (it jumps every 17 minutes).
* ``time.w``: seconds wrapped to :data:`ANGLE_WRAP` (163 turns of 2π, 1024.16 s): ``sin(k * time.w)`` and
  ``cos(k * time.w)`` are smooth across the wrap for every whole ``k`` (an angle in radians at k rad/s).
* any other period: a per-animation phase, ``phase(time, period)`` in float64 on the CPU, written as a material
  value (the explode technique's ``explode_time`` is its clock wrapped to its own period).

Each form is smooth and steps exactly to 1e-4 s for as long as the float64 clock resolves 1e-4 s itself
(past 1e11 s, three thousand years); tested at 1e5 s, 1e7 s and across each wrap in both APIs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..resources import MaterialData

# The lights block's sizes live below the systems that pack it; the renderers read them from here too.
from ..resources.blocks import FRAME_LAYOUT as FRAME_LAYOUT
from ..resources.blocks import LIGHTS_BLOCK_BYTES as LIGHTS_BLOCK_BYTES
from ..resources.blocks import LIGHTS_BYTES as LIGHTS_BYTES
from ..resources.blocks import MAX_LIGHTS as MAX_LIGHTS
from ..resources.blocks import SHADOW_BYTES as SHADOW_BYTES
from ..resources.blocks import SHADOW_MAP_SIZE as SHADOW_MAP_SIZE

INSTANCE_FLOATS = 12
INSTANCE_STRIDE = INSTANCE_FLOATS * 4
# view, projection, camera_position, time, clip_to_direction, depth, origin_high, origin_low
FRAME_FLOATS = FRAME_LAYOUT.size // 4
#: ``time.x`` wraps after this many seconds: float32's step at 1024 s is 1.2e-4 s, under 1% of 1/60 s.
TIME_WRAP = 1024.0
#: ``time.w`` wraps after this many seconds: 163 whole turns of 2π, so ``sin(k * time.w)`` never jumps.
ANGLE_WRAP = 163 * 2.0 * math.pi


def phase(time: float, period: float) -> float:
    """``time`` wrapped to ``[0, period)`` in float64: a periodic animation's clock that float32 keeps exact for
    ever (``sin(2π phase / period)`` is smooth across the wrap because the wrap is one whole period)."""
    if not (math.isfinite(period) and period > 0.0):
        raise ValueError(f"phase: the period must be a finite number of seconds > 0, got {period!r}")
    return float(time) % period


#: The sky pass's shader name (core shaders ``render/shaders/skybox.*``) and fixed state: it is drawn
#: where nothing else is, at the far plane, with no depth writes and no culling.
SKY_SHADER = "gandalf.skybox"
SKY_STATE = MaterialData(SKY_SHADER, cull="none", depth_write=False, name="sky")
#: The shadow pass's shader name (core shaders ``render/shaders/shadow_depth.*``): positions and instance
#: rows only, depth only.
SHADOW_SHADER = "gandalf.shadow_depth"
#: The engine's own passes: pass -> (shader name, file stem in ``render/shaders``: ``.vert``/``.frag`` and ``.wgsl``).
PASS_SHADERS = {"sky": (SKY_SHADER, "skybox"), "shadow": (SHADOW_SHADER, "shadow_depth")}


@dataclass
class FrameData:
    """Everything a renderer needs to draw one frame."""

    clear_color: np.ndarray  # linear RGBA
    frame: bytes  # the frame uniform block
    lights: bytes  # the lights uniform block (LIGHTS_BLOCK_BYTES)
    batches: list[DrawBatch]  # opaque ones first, then the transparent ones back to front
    instances: np.ndarray | None  # (total instances, 12) float32
    #: The rows of ``instances`` that changed since the frame ``instances_since`` named ([lo, hi): upload only
    #: those), or None: all of them are new.
    instance_span: tuple[int, int] | None = None
    #: (source, frame number) of these instance rows, and of the frame ``instance_span`` is counted from: a renderer
    #: that uploaded exactly that frame last may upload the span alone; any other renderer uploads every row.
    instances_version: tuple[object, int] | None = None
    instances_since: tuple[object, int] | None = None
    #: GPU work over the instance rows before the draws read them (the render system's ``instance_pass`` hook:
    #: ``run(renderer, instances, count)`` in OpenGL, ``record(renderer, encoder, instances, count)`` in WebGPU,
    #: each returning the buffer the draws read), or None.
    instance_pass: Any = None
    skybox: str | None = None  # cube texture name, or None for no sky pass (drawn after the opaque batches)
    reverse_z: bool = False
    shadows: bool = False  # a shadow-casting light is on: draw the shadow map before the main pass


@dataclass
class DrawBatch:
    """All entities that share a mesh and a material: drawn with one instanced call."""

    mesh: str
    material: str
    rows: np.ndarray  # rows of the TransformComponent store
    first_instance: int = 0
    transparent: bool = False  # blended: drawn after the opaque batches and the sky, back to front
    farthest: float = 0.0  # view depth of its farthest instance (transparent batches, this frame)
    mirrored: bool = False  # its world matrices flip handedness (negative determinant): front faces wind clockwise

    @property
    def count(self) -> int:
        return len(self.rows)


def pack_frame(
    view: np.ndarray,
    projection: np.ndarray,
    camera_position: np.ndarray,
    time: float,
    dt: float,
    depth_ends: tuple[float, float] = (-1.0, 1.0),
    origin: np.ndarray | None = None,
) -> bytes:
    """The frame uniform block as bytes (matrices column-major, as both APIs expect).

    ``view`` and ``camera_position`` are relative to ``origin`` (default: the world origin), which is stored split
    into a float32 and the float32 of the remainder, so a shader can rebuild absolute positions.

    ``depth_ends`` are the NDC depths of the near and far planes (swapped by reverse-Z); the skybox
    draws at the far one. ``clip_to_direction`` maps a clip-space point on the far plane to a world
    direction (the inverse of projection × the view's rotation). The projection is uploaded scaled by
    :func:`clip_scale`.
    """
    block, field = _FRAME_BLOCK, _FRAME_FIELDS  # reused: every field is written below, the bytes copied out
    field["view"][...] = view
    field["projection"][...] = projection * clip_scale(projection, depth_ends[0])
    field["camera_position"][:3] = np.asarray(camera_position, dtype=np.float64)[:3]
    field["camera_position"][3] = 1.0
    wraps, wrapped = divmod(float(time), TIME_WRAP)
    field["time"][:] = (wrapped, dt, wraps, phase(time, ANGLE_WRAP))
    field["depth"][:2] = depth_ends
    field["clip_to_direction"][...] = _clip_to_direction(projection, view[:3, :3])
    if origin is None:
        field["origin_high"][:3] = field["origin_low"][:3] = 0.0
    else:
        origin = np.asarray(origin, dtype=np.float64)
        high = origin.astype(np.float32)
        field["origin_high"][:3] = high
        field["origin_low"][:3] = origin - high.astype(np.float64)
    return block.tobytes()


def clip_scale(projection: np.ndarray, near_ndc: float) -> float:
    """The factor a perspective projection is multiplied by before upload, so that clip w is 1 on the near plane.

    Clip coordinates are homogeneous: ``k · clip`` for any k > 0 rasterises to the same pixels, the same depth
    (z / w) and the same perspective-correct varyings. But the GPU's own set-up arithmetic (clipping, edge
    equations) multiplies clip coordinates together, and a scene of size 1e-20 (near plane 1e-21) makes products
    near 1e-40, below float32's smallest normal number (1.2e-38): an NVIDIA GPU flushes them to zero and draws
    nothing. Scaled by about 1 / (w at the near plane), clip w runs from about 1 to far / near whatever the scene's
    size. The factor is a power of two, so the scaling is exact in float32: every quotient the GPU forms from clip
    coordinates is bit for bit what it was, and a scene of ordinary size draws exactly the same pixels.
    1 for an orthographic projection (w is 1 already) or a matrix whose near plane cannot be read off.
    """
    if projection[3, 3] != 0.0 or projection[2, 3] == 0.0:
        return 1.0
    # z_ndc = (P22 z + P23) / (P32 z) = near_ndc at the near plane: w there is P32 z = -P23 P32 / (P22 - near_ndc P32).
    denominator = float(projection[2, 2] - near_ndc * projection[3, 2])
    if denominator == 0.0:
        return 1.0
    w_near = abs(float(projection[2, 3] * projection[3, 2]) / denominator)
    if not (math.isfinite(w_near) and w_near > 0.0):
        return 1.0
    return math.ldexp(1.0, -math.frexp(w_near)[1])  # 2^-e with w_near = m 2^e, m in [0.5, 1): w from 0.5 to 1


def _clip_to_direction(projection: np.ndarray, rotation: np.ndarray) -> np.ndarray:
    """The inverse of projection x the view's rotation; the last one is kept, as the camera rarely changes."""
    global _LAST_CLIP_TO_DIRECTION
    key = projection.tobytes() + rotation.tobytes()
    if _LAST_CLIP_TO_DIRECTION[0] == key:
        return _LAST_CLIP_TO_DIRECTION[1]
    rotation_only = np.eye(4)
    rotation_only[:3, :3] = rotation
    if projection[3, 3] != 0.0 and projection[3, 2] == 0.0:
        # Orthographic: every pixel would look the same way. Give the sky a 90° perspective of the same
        # aspect instead, so it still shows a view of the surroundings.
        aspect = abs(projection[1, 1] / projection[0, 0]) if projection[0, 0] else 1.0
        projection = np.array([[1 / aspect, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, -0.2], [0, 0, -1, 0]])
    try:
        inverse = np.linalg.inv(projection @ rotation_only)
    except np.linalg.LinAlgError:
        inverse = np.eye(4)
    _LAST_CLIP_TO_DIRECTION = (key, inverse)
    return inverse


def _frame_fields(block: np.ndarray) -> dict[str, np.ndarray]:
    """Typed views of every field of a frame block (FRAME_LAYOUT's offsets), to fill by name."""
    return {name: FRAME_LAYOUT.view(block, name) for name in FRAME_LAYOUT.names()}


_FRAME_BLOCK = FRAME_LAYOUT.new()
_FRAME_FIELDS = _frame_fields(_FRAME_BLOCK)
_LAST_CLIP_TO_DIRECTION: tuple[bytes, np.ndarray] = (b"", np.eye(4))


def instance_capacity(nbytes: int) -> int:
    """Bytes to allocate for ``nbytes`` of instance data: powers of two from 4 KiB, so growth is rare."""
    return 1 << max(12, (nbytes - 1).bit_length())


def pack_instance_rows(world: np.ndarray, rows: np.ndarray, out: np.ndarray, at: np.ndarray,
                       origin: np.ndarray | None) -> None:
    """Pack ``world[rows]`` into the instance rows ``out[at]`` (as :func:`pack_instances` does for all of them)."""
    packed = out.reshape(-1, 3, 4)
    packed[at, :, :3] = world[rows, :3, :3]
    packed[at, :, 3] = world[rows, :3, 3] if origin is None else world[rows, :3, 3] - origin


def pack_instances(world: np.ndarray, rows: np.ndarray | slice, out: np.ndarray | None = None,
                   origin: np.ndarray | None = None) -> np.ndarray:
    """Gather the affine rows of ``world[rows]`` into a ``(count, 12)`` float32 array, translations relative to
    ``origin`` (subtracted in float64, before the conversion to float32).

    ``rows`` is an index array, or a slice when the rows are consecutive (no gathering copy then).
    """
    count = len(range(*rows.indices(len(world)))) if isinstance(rows, slice) else len(rows)
    if out is None or out.shape[0] != count:
        out = np.empty((count, INSTANCE_FLOATS), dtype=np.float32)
    packed = out.reshape(-1, 3, 4)
    packed[:, :, :3] = world[rows, :3, :3]
    if origin is None:
        packed[:, :, 3] = world[rows, :3, 3]
    else:
        packed[:, :, 3] = world[rows, :3, 3] - np.asarray(origin, dtype=np.float64)
    return out
