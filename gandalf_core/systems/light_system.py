"""The light system: collects every Light into the lights uniform block, once per frame.

The block is declared once, :data:`~gandalf_core.resources.blocks.LIGHTS_LAYOUT` (the same bytes in GLSL's std140
and WGSL, see ``render/shaders/frame.glsl``), and packed by field name::

    count: ivec4 (x = lights used), ambient: vec4 (rgb, linear),
    position[64]: vec4 (xyz position with w = 1, or direction towards the light with w = 0),
    color[64]: vec4 (rgb linear colour × intensity, a = range; 0 means no falloff)
    light_view_projection: mat4 (world -> the shadow-casting light's clip space)
    shadow: vec4 (x = 1 when a shadow map is on, y = depth bias, z = 1 / map size, w = the light's index)

:meth:`LightSystem.pack` makes the lights part (``LIGHTS_BYTES``); :meth:`LightSystem.shadow` the shadow
part at the end (``SHADOW_BYTES``), for the renderer's depth range, which the render system passes in.
Subclass it and override :meth:`LightSystem.pack` to change how lights are collected (step 06's exercise).
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np

from ..components import TransformComponent
from ..components.light import LightComponent
from ..ecs import System
from ..math import orthographic
from ..resources.blocks import LIGHTS_BYTES, LIGHTS_LAYOUT, MAX_LIGHTS, SHADOW_MAP_SIZE
from ..resources.color import srgb_rgba_to_linear


class LightSystem(System):
    """Packs the scene's lights into :attr:`data` (bytes) for the renderer."""

    def __init__(self) -> None:
        super().__init__([LightComponent, TransformComponent])
        self._data: bytes | None = pack_lights([])

    def on_update_system(self, ts: float) -> None:
        if self._stock_packing:
            # The render system packs the lights once, relative to the camera (relative()), and data is packed only
            # if something reads it.
            self._data = None
        else:
            self._data = self.pack(self.components)  # a subclass's own packing runs (and fails) in its own update

    @property
    def data(self) -> bytes:
        """This frame's lights block (the lights part, world positions), as :meth:`pack` made it."""
        if self._data is None:
            self._data = self.pack(self.components)
        return self._data

    @data.setter
    def data(self, block: bytes) -> None:
        self._data = block

    def pack(self, components: list[tuple[LightComponent, TransformComponent]]) -> bytes:
        return pack_lights(components)

    @property
    def _stock_packing(self) -> bool:
        """Whether the lights are packed by this class's :meth:`pack`, not a subclass's own (step 06's exercise)."""
        return type(self).pack is LightSystem.pack

    def shadow(self, depth_range: str | tuple[float, float], origin: np.ndarray | None = None) -> bytes:
        """The shadow part of the block for this frame's lights, projected for ``depth_range``, from positions
        relative to ``origin``."""
        return pack_shadow(self.components, depth_range, origin)

    @property
    def casts_shadows(self) -> bool:
        """Whether a light of this frame casts shadows (the renderer then draws the shadow pass)."""
        return shadow_light(self.components) is not None

    def relative(self, origin: np.ndarray) -> bytes:
        """:attr:`data` with point lights relative to ``origin``. The stock packing recomputes them from the
        float64 world matrices; a subclass's own :meth:`pack` (step 06's exercise) is moved by ``-origin`` from
        its float32 values."""
        if self._stock_packing:
            return pack_lights(self.components, origin)
        return relative_lights(self.data, origin)


def relative_lights(block: bytes, origin: np.ndarray) -> bytes:
    """A packed lights part with its point lights (w = 1) moved by ``-origin`` (in float64)."""
    data = np.frombuffer(block, dtype=np.float32).copy()
    count = int(data[0:1].view(np.int32)[0])
    first = LIGHTS_LAYOUT.offset("position") // 4
    positions = data[first:first + 4 * MAX_LIGHTS].reshape(MAX_LIGHTS, 4)[:count]
    points = positions[:, 3] == 1.0
    positions[points, :3] = positions[points, :3].astype(np.float64) - np.asarray(origin, dtype=np.float64)
    return data.tobytes()


def pack_lights(components: list[tuple[Any, Any]], origin: np.ndarray | None = None) -> bytes:
    """The lights block for (LightComponent, TransformComponent) pairs (world matrices already computed); point
    lights relative to ``origin`` (subtracted in float64)."""
    block = LIGHTS_LAYOUT.new()  # filled by field name through typed views of the block
    ambient = LIGHTS_LAYOUT.view(block, "ambient")
    positions = LIGHTS_LAYOUT.view(block, "position")
    colors = LIGHTS_LAYOUT.view(block, "color")
    n = dropped = 0
    for light, transform in components:
        linear = srgb_rgba_to_linear((*light.color, 1.0))[:3] * light.intensity
        if light.kind == "ambient":
            ambient[:3] += linear
            continue
        if n == MAX_LIGHTS:
            dropped += 1  # ambient lights further on still count
            continue
        world = transform.world
        if light.kind == "point":
            position = world[:3, 3] if origin is None else world[:3, 3] - np.asarray(origin, dtype=np.float64)
            positions[n] = (*position, 1.0)
        else:
            forward = -world[:3, 2]  # the light shines along its -Z axis
            length = np.linalg.norm(forward)
            towards = -forward / length if length > 0 else np.array([0.0, 1.0, 0.0])
            positions[n] = (*towards, 0.0)
        colors[n] = (*linear, light.range)
        n += 1
    if dropped:
        warnings.warn(f"{n + dropped} point and directional lights; only the first {MAX_LIGHTS} are used",
                      stacklevel=2)
    LIGHTS_LAYOUT.view(block, "count")[0] = n
    return block[:LIGHTS_BYTES].tobytes()


# --8<-- [start:pack_shadow]
def pack_shadow(components: list[tuple[Any, Any]], depth_range: str | tuple[float, float] = "opengl",
                origin: np.ndarray | None = None) -> bytes:
    """The shadow part of the lights block: the first shadow-casting directional light's view-projection
    and shadow parameters (all zero, so ``shadow.x == 0``, when no light casts shadows); ``shadow.y`` is the depth
    bias of one map texel times the light's ``shadow_bias``.

    The light looks along its -Z axis from its world position, the centre of an orthographic box
    ``2 · shadow_extent`` wide and high and ``shadow_depth`` long; ``depth_range`` is the API's NDC depth
    range, as for a camera. With ``origin`` the matrix takes positions relative to it (camera-relative rendering).
    """
    found = shadow_light(components)
    if found is None:
        return _NO_SHADOW
    index, light, transform = found
    extent, depth = light.shadow_extent, light.shadow_depth
    view = light_view(transform.world)
    projection = orthographic(-extent, extent, -extent, extent, -depth / 2, depth / 2, depth_range=depth_range)
    if origin is not None:  # positions arrive relative to origin: move them back first (float64)
        view = view.copy()
        view[:3, 3] += view[:3, :3] @ np.asarray(origin, dtype=np.float64)
    texel = 2.0 * extent / SHADOW_MAP_SIZE
    # Depth is stored in [0, 1] over the box's length in both APIs: one texel's width in those units.
    # y: the bias of one map texel's depth, scaled by the light's shadow_bias (1 by default).
    shadow = (1.0, light.shadow_bias * texel / depth, 1.0 / SHADOW_MAP_SIZE, float(index))
    block = LIGHTS_LAYOUT.pack({"light_view_projection": projection @ view, "shadow": shadow})
    return block[LIGHTS_BYTES:]


def shadow_light(components: list[tuple[Any, Any]]) -> tuple[int, Any, Any] | None:
    """The first shadow-casting directional light among the packed ones: ``(its slot, light, transform)``, or
    None (then the frame has no shadow pass)."""
    index = 0  # the light's slot in position[] and color[], counted as pack_lights() does
    for light, transform in components:
        if light.kind == "ambient":
            continue
        if index == MAX_LIGHTS:
            break
        if light.cast_shadows:
            return index, light, transform
        index += 1
    return None
# --8<-- [end:pack_shadow]


_NO_SHADOW = LIGHTS_LAYOUT.pack({})[LIGHTS_BYTES:]


def light_view(world: np.ndarray) -> np.ndarray:
    """The view matrix of a light placed by ``world``: its rotation (scale and shear removed) and position.

    A zero -Z axis makes the light look straight down, as :func:`pack_lights` treats it.
    """
    z = world[:3, 2]
    length = np.linalg.norm(z)
    z = z / length if length > 0 else np.array([0.0, 1.0, 0.0])
    x = world[:3, 0] - np.dot(world[:3, 0], z) * z
    if np.linalg.norm(x) < 1e-9 * max(1.0, np.linalg.norm(world[:3, 0])):
        # No usable X axis: any direction across the light will do for a square box.
        helper = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
        x = helper - np.dot(helper, z) * z
    x = x / np.linalg.norm(x)
    y = np.cross(z, x)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = x, y, z
    view[:3, 3] = -view[:3, :3] @ world[:3, 3]
    return view
