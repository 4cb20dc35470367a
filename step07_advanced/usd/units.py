"""Other tools' units: a stage's up axis and metres per unit, and UsdLux light intensities, in the engine's terms.

**Frame.** The engine is Y-up in metres. A Z-up stage is turned by -90° about X ((x, y, z) -> (x, z, -y)) and a
stage of ``metersPerUnit`` m is scaled by m (a stage that does not author it is taken as metres, not as USD's
fallback of centimetres: most hand-made files that omit it mean the engine's unit). :func:`stage_frame` gives
that rotation and scale, and :func:`to_engine_frame` applies it to a root entity's transform (a rotation and a
uniform scale keep a translate-rotate-scale one: ``C·T·R·S = T(m·Rc·t)·(Rc·R)·S(m·s)``).

**Lights.** UsdLux's ``intensity`` is scaled by ``2^exposure``. A ``SphereLight`` emits that radiance from its
surface (radius r in world metres, xform scale and ``metersPerUnit`` included): power ``Φ = π·I·4πr²``, or
``Φ = π·I`` with ``normalize`` (the power no longer depends on the size; also for radius 0 and ``treatAsPoint``).
The engine's point light gives irradiance ``intensity / d²``, so its intensity is ``Φ / 4π``: ``π·I·r²``, or
``I / 4`` normalised. It falls off with the inverse square out to a range where it has faded below 1/512 of
white (``sqrt(512 · intensity · max colour)``; the window there costs < 3 % at a fifth of the range).
``DistantLight`` and ``DomeLight`` intensities are taken as the irradiance they give (``I·2^exposure``), as Hydra's
Storm and Blender's exporter treat a sun (not scaled by the disc's solid angle as a path tracer would).
"""

from __future__ import annotations

import math

import numpy as np
from pxr import Usd, UsdGeom

from gandalf_core.components import TransformComponent
from gandalf_core.math import quat_mul, quat_rotate

#: Irradiance (linear, white = 1) below which a foreign point light's range ends: under half an 8-bit step.
FADED = 1.0 / 512.0
_Z_UP_TO_Y_UP = np.array([math.sqrt(0.5), -math.sqrt(0.5), 0.0, 0.0])  # -90° about X, (w, x, y, z)


def stage_frame(stage: Usd.Stage) -> tuple[np.ndarray, float] | None:
    """(rotation quaternion, metres per unit) from the stage's axes to the engine's; None when it is Y-up metres."""
    up = UsdGeom.GetStageUpAxis(stage)
    # Unauthored, USD's fallback is centimetres; files that say nothing are taken as the engine's metres instead.
    metres = float(UsdGeom.GetStageMetersPerUnit(stage)) if stage.HasAuthoredMetadata("metersPerUnit") else 1.0
    if up == UsdGeom.Tokens.y and metres == 1.0:
        return None
    rotation = _Z_UP_TO_Y_UP if up == UsdGeom.Tokens.z else np.array([1.0, 0.0, 0.0, 0.0])
    return rotation, metres


def to_engine_frame(transform: TransformComponent, rotation: np.ndarray, metres: float) -> TransformComponent:
    """A root entity's transform moved from the stage's frame into the engine's (see the module docstring)."""
    q = quat_mul(rotation, transform.quaternion) if np.any(transform.quaternion) else rotation
    out = TransformComponent(metres * quat_rotate(rotation, transform.translation), scale=metres * transform.scale)
    out.quaternion = q
    return out


def lux_intensity(prim: Usd.Prim, intensity: float, exposure: float, metres: float,
                  notes: list[tuple[str, str]]) -> tuple[float, float]:
    """(engine intensity, range) of a UsdLux light prim whose ``inputs:intensity`` and ``inputs:exposure`` are
    given (see the module docstring); ``metres``: the stage's metres per unit."""
    value = intensity * 2.0 ** exposure
    if str(prim.GetTypeName()) != "SphereLight":
        return value, 0.0
    radius_attr = prim.GetAttribute("inputs:radius")
    radius = float(radius_attr.Get()) if radius_attr and radius_attr.Get() is not None else 0.5
    normalize_attr = prim.GetAttribute("inputs:normalize")
    normalize = bool(normalize_attr.Get()) if normalize_attr and normalize_attr.HasAuthoredValue() else False
    point_attr = prim.GetAttribute("treatAsPoint")
    as_point = bool(point_attr.Get()) if point_attr and point_attr.HasAuthoredValue() else False
    world = np.array(UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(Usd.TimeCode.Default()))[:3, :3]
    scale = abs(float(np.linalg.det(world))) ** (1.0 / 3.0) * metres  # the radius's world length per unit
    r = radius * scale
    if normalize or as_point or r <= 0.0:
        engine = value / 4.0
        if not normalize:
            notes.append((str(prim.GetPath()), "a SphereLight of radius 0 (or treatAsPoint): its intensity is taken "
                                              "as normalised (power π·intensity)"))
    else:
        engine = math.pi * value * r * r
    color_attr = prim.GetAttribute("inputs:color")
    brightest = float(max(color_attr.Get())) if color_attr and color_attr.Get() is not None else 1.0
    reach = math.sqrt(engine * max(brightest, 0.0) / FADED)
    return engine, reach if reach > 0.0 else 0.0
