"""Other tools' units: a stage's up axis and metres per unit, and UsdLux light intensities, in the engine's terms.

**Frame.** The engine is Y-up in metres. A Z-up stage is turned by -90° about X ((x, y, z) -> (x, z, -y)) and a
stage of ``metersPerUnit`` m is scaled by m (a stage that does not author it is taken as metres, not as USD's
fallback of centimetres: most hand-made files that omit it mean the engine's unit). :func:`stage_frame` gives
that rotation and scale, and :func:`to_engine_frame` applies it to a root entity's transform (a rotation and a
uniform scale keep a translate-rotate-scale one: ``C·T·R·S = T(m·Rc·t)·(Rc·R)·S(m·s)``).

**Lights.** UsdLux's lights emit radiance ``L = intensity · 2^exposure`` (nits: a light of 1 seen head-on is a
pixel of 1), divided by a size factor when ``inputs:normalize`` is on. The engine's lights are defined by what
they deliver: a directional light's intensity is the irradiance on a surface facing it, a point light's the
irradiance at 1 m (``intensity / d²``), an ambient light's the radiance of a uniform surround (a white diffuse
surface reflects it as it is). So:

* a ``SphereLight`` emits ``L`` from its surface (radius r in world metres, xform scale and ``metersPerUnit``
  included): power ``Φ = π·L·4πr²``, or ``Φ = π·I`` with ``normalize`` (divided by the area 4πr²; also for radius
  0 and ``treatAsPoint``). Its intensity is ``Φ / 4π``: ``π·L·r²``, or ``L / 4`` normalised. It falls off with the
  inverse square out to a range where it has faded below 1/512 of white (``sqrt(512 · intensity · max colour)``;
  the window there costs < 3 % at a fifth of the range);
* a ``DistantLight`` is a disc of angular radius ``θ = angle / 2`` (``inputs:angle``, 0.53° unless authored) of
  radiance ``L``: a surface facing it receives ``L·π·sin²θ`` (the cosine-weighted solid angle of the disc; ``L·π``
  once it spans more than a hemisphere). With ``normalize``, ``L`` is divided by that size factor (``π·sin²θ``, or
  ``(2 - sin²θ)·π`` beyond a hemisphere), so the irradiance is the intensity itself (lux). An angle of 0 is a
  parallel light: its intensity is the irradiance. Unauthored, the intensity is UsdLux's 50000 (the sun:
  50000 · π·sin²(0.265°) = 3.4);
* a ``DomeLight`` is a uniform surround of radiance ``L`` (``normalize`` does not apply to it): the ambient
  light's intensity is ``L``. A texture on it is not read (the ambient light is uniform), and a note says so.
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


def schema_fallback(prim: Usd.Prim, name: str, default: float) -> float:
    """The value of ``name`` that ``prim``'s schema gives when the file does not author it (a DistantLight's
    intensity is 50000, not LightAPI's 1), or ``default``."""
    attribute = prim.GetAttribute(name)
    value = attribute.Get() if attribute else None
    return float(value) if value is not None else default


def _authored_bool(prim: Usd.Prim, name: str) -> bool:
    attribute = prim.GetAttribute(name)
    return bool(attribute.Get()) if attribute and attribute.HasAuthoredValue() else False


def distant_irradiance(value: float, angle_degrees: float, normalize: bool) -> float:
    """The irradiance a DistantLight of radiance ``value`` and angular diameter ``angle_degrees`` gives a surface
    facing it (see the module docstring)."""
    theta = min(max(math.radians(angle_degrees) / 2.0, 0.0), math.pi)
    if theta == 0.0:
        return value
    s2 = math.sin(theta) ** 2
    received = math.pi * s2 if theta <= math.pi / 2 else math.pi
    size = math.pi * s2 if theta <= math.pi / 2 else (2.0 - s2) * math.pi
    return value * received / size if normalize else value * received


def lux_intensity(prim: Usd.Prim, intensity: float, exposure: float, metres: float,
                  notes: list[tuple[str, str]]) -> tuple[float, float]:
    """(engine intensity, range) of a UsdLux light prim whose ``inputs:intensity`` and ``inputs:exposure`` are
    given (see the module docstring); ``metres``: the stage's metres per unit."""
    value = intensity * 2.0 ** exposure
    kind = str(prim.GetTypeName())
    if kind == "DistantLight":
        return distant_irradiance(value, schema_fallback(prim, "inputs:angle", 0.53),
                                  _authored_bool(prim, "inputs:normalize")), 0.0
    if kind != "SphereLight":
        texture = prim.GetAttribute("inputs:texture:file")
        if texture and texture.HasAuthoredValue():
            notes.append((str(prim.GetPath()), "a DomeLight's texture is not read: a uniform ambient light of its "
                                              "intensity stands in for it"))
        return value, 0.0
    radius_attr = prim.GetAttribute("inputs:radius")
    radius = float(radius_attr.Get()) if radius_attr and radius_attr.Get() is not None else 0.5
    normalize = _authored_bool(prim, "inputs:normalize")
    as_point = _authored_bool(prim, "treatAsPoint")
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
