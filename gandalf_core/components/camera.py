"""The Camera component: a projection attached to an entity whose Transform places the eye.

The camera looks down its own -Z axis. Its view matrix is the inverse of its entity's world matrix,
computed every frame, so a camera parented to a moving entity never goes stale. The projection uses
the renderer's depth range, which is why one scene and one camera give the same picture in both APIs.
"""

from __future__ import annotations

import math

import numpy as np

from ..ecs import Component
from ..math import orthographic, perspective
from .fields import Choice, Flag, Number

PROJECTIONS = ("perspective", "orthographic")
# Parameter names of the projection functions -> this component's fields, for error messages.
_FIELDS = {"fovy_degrees": "fov", "aspect": "aspect", "near": "near", "far": "far"}


class CameraComponent(Component):
    """Perspective (``fov`` degrees, vertical) or orthographic (``height`` world units) projection.

    ``aspect=None`` follows the render target (and so the window when it is resized). Validation runs
    on construction and again whenever a projection is built, so a bad value names its field.

    ``reverse_z`` maps near to the far end of the depth range and far (which may be ``math.inf``) to the
    near end. With a [0, 1] clip depth and a float depth buffer that spreads precision evenly over huge depth
    ranges: WebGPU has both; OpenGL switches to them for reverse-Z frames (clip control and a 32-bit float depth
    target), so one camera gives the same picture, with the same precision, in both APIs.
    """

    fov = Number(0.0, 180.0, note="degrees, vertical")
    near = Number(0.0)
    far = Number(0.0, allow_inf=True)
    projection = Choice(PROJECTIONS)
    height = Number(0.0, note="world units, orthographic")
    aspect = Number(0.0, optional=True, note="None follows the render target")
    primary = Flag()
    reverse_z = Flag()

    def __init__(
        self,
        fov: float = 60.0,
        near: float = 0.1,
        far: float = 100.0,
        *,
        projection: str = "perspective",
        height: float = 2.0,
        aspect: float | None = None,
        primary: bool = True,
        reverse_z: bool = False,
    ) -> None:
        self._set_fields(fov=fov, near=near, far=far, projection=projection, height=height, aspect=aspect,
                         primary=primary, reverse_z=reverse_z)
        self.projection_matrix("opengl", 1.0)  # validate now, naming the bad field

    def projection_matrix(self, depth_range: str, target_aspect: float) -> np.ndarray:
        """The projection for an API's depth range ('opengl' or 'webgpu').

        A bad value raises ValueError naming the component's field (``CameraComponent.fov`` ...).
        """
        try:
            return self._projection(depth_range, target_aspect)
        except ValueError as exc:
            message = str(exc)
            for parameter, field in _FIELDS.items():
                message = message.replace(parameter, f"CameraComponent.{field}")
            raise ValueError(message) from None

    def _projection(self, depth_range: str, target_aspect: float) -> np.ndarray:
        aspect = target_aspect if self.aspect is None else self.aspect
        if not (isinstance(aspect, (int, float)) and math.isfinite(aspect) and aspect > 0):
            raise ValueError(f"aspect must be finite and > 0, got {aspect!r}")
        if self.projection == "perspective":
            return perspective(self.fov, aspect, self.near, self.far, depth_range=depth_range, reverse_z=self.reverse_z)
        if self.projection == "orthographic":
            if not self.far > self.near:  # the box would be inside out: nothing in front of the camera would show
                raise ValueError(f"far must be greater than near ({self.near!r}), got {self.far!r}")  # named below
            if not (math.isfinite(self.height) and self.height > 0):
                raise ValueError(f"CameraComponent.height must be a positive number, got {self.height!r}")
            half_h = self.height / 2
            half_w = half_h * aspect
            if not math.isfinite(half_w):
                raise ValueError(f"CameraComponent.height ({self.height!r}) times the aspect ({aspect!r}) is too large "
                                 "to represent")
            try:
                return orthographic(-half_w, half_w, -half_h, half_h, self.near, self.far, depth_range=depth_range,
                                    reverse_z=self.reverse_z)
            except ValueError as exc:
                if "left" not in str(exc):
                    raise
                message = f"CameraComponent.height ({self.height!r}) with the aspect ({aspect!r}): {exc}"
                raise ValueError(message) from None
        raise ValueError(f"CameraComponent.projection must be one of {PROJECTIONS}, got {self.projection!r}")
