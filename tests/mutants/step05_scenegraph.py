"""Mutants of step 05: the house's five milestones and the two integrators."""

from __future__ import annotations

import math

import numpy as np

from gandalf_core import TransformComponent
from gandalf_core.components import CameraComponent
from gandalf_core.math import look_at_rotation, quat_from_axis_angle
from gandalf_core.resources import MaterialData, MeshData, TextureData, cube, pyramid
from gandalf_tools.grading.mutants import Mutant, mutant, patch

STEP = "step05_scenegraph"
MUTANTS: list[Mutant] = []


# --- house_meshes ----------------------------------------------------------------------------------


def _moved(mesh, scale, offset, name, keep=True):
    positions = mesh.positions.astype(np.float64) * scale + np.asarray(offset)
    if not keep:
        return MeshData(positions, indices=mesh.indices, name=name)
    return MeshData(
        positions, normals=mesh.normals, uvs=mesh.uvs, tangents=mesh.tangents, indices=mesh.indices, name=name
    )


def _house(pkg, walls_offset=(0.0, 0.5, 0.0), roof_offset=(0.0, 1.0, 0.0), base=1.3, keep=True, wall_size=1.0):
    def house_meshes():
        walls = _moved(cube(wall_size), 1.0, walls_offset, "house.walls", keep)
        return walls, _moved(pyramid(base, 0.7), 1.0, roof_offset, "house.roof", keep)

    patch(pkg, "house.house_meshes", house_meshes)


for _name, _text, _slips in [
    ("walls-sunk", "walls centred on the origin (half under the ground)",
     {"walls_offset": (0.0, 0.0, 0.0), "roof_offset": (0.0, 0.5, 0.0)}),
    ("roof-on-ground", "roof left at y = 0, inside the walls", {"roof_offset": (0.0, 0.0, 0.0)}),
    ("no-overhang", "roof base as wide as the walls", {"base": 1.0}),
    ("drops-attributes", "rebuilds the meshes from positions only (no normals, uvs)", {"keep": False}),
    ("double-size", "walls of size 2 (cube's size read as half-extent)",
     {"walls_offset": (0.0, 1.0, 0.0), "roof_offset": (0.0, 2.0, 0.0), "wall_size": 2.0}),
]:
    mutant(MUTANTS, STEP, "house_meshes", _name, _text)(lambda pkg, _s=_slips: _house(pkg, **_s))


# --- brick_texture_data ----------------------------------------------------------------------------


def _texture(
    pkg, *, size=64, brick=(0.62, 0.24, 0.17), mortar=(0.82, 0.80, 0.75), joint_rule=None, shade=True, shift=True
):
    def brick_texture_data(size_arg: int = 64):
        y, x = np.mgrid[0:size_arg, 0:size_arg]
        course = size_arg // 4
        row = y // course
        shifted = (x + ((row % 2) * (size_arg // 4) if shift else 0)) % size_arg
        joint = (y % course < 2) | (shifted % (size_arg // 2) < 2)
        if joint_rule is not None:
            joint = joint_rule(joint)
        brick_id = row * 2 + shifted // (size_arg // 2)
        factor = 0.9 + 0.1 * ((brick_id * 7919) % 5) / 4.0 if shade else np.ones_like(brick_id, dtype=float)
        rgb = np.where(joint[..., None], np.asarray(mortar), np.asarray(brick) * factor[..., None])
        return TextureData.from_array(rgb, name="house.brick")

    if size != 64:
        patch(pkg, "house.brick_texture_data", lambda *a, **k: brick_texture_data(size))
    else:
        patch(pkg, "house.brick_texture_data", brick_texture_data)


for _name, _text, _slips in [
    ("no-mortar", "forgets the mortar joints: one brick colour", {"joint_rule": lambda j: np.zeros_like(j)}),
    ("inverted-joints", "mortar where the bricks are and bricks in the joints", {"joint_rule": lambda j: ~j}),
    ("grey", "brick and mortar the same grey", {"brick": (0.6, 0.6, 0.6), "mortar": (0.6, 0.6, 0.6)}),
    ("small", "a 32 x 32 texture whatever size is asked", {"size": 32}),
    ("stack-bond", "no half-brick shift between courses", {"shift": False}),
    ("byte-colours", "colours given in 0-255 (clipped to white)",
     {"brick": (158.0, 61.0, 43.0), "mortar": (209.0, 204.0, 191.0)}),
]:
    mutant(MUTANTS, STEP, "brick_texture_data", _name, _text)(lambda pkg, _s=_slips: _texture(pkg, **_s))


# --- house_material_data ---------------------------------------------------------------------------


def _materials(pkg, walls, roof):
    def house_material_data():
        return {"house.walls": walls, "house.roof": roof}

    patch(pkg, "house.house_material_data", house_material_data)


WALLS = MaterialData("shaded_textured", ["house.brick"], color=(1.0, 1.0, 1.0), name="house.walls")
ROOF = MaterialData("shaded", color=(1.0, 0.5, 0.0), name="house.roof")


@mutant(MUTANTS, STEP, "house_material_data", "untextured-walls", "walls lit but without the brick texture")
def _(pkg):
    _materials(pkg, MaterialData("shaded", color=(1.0, 1.0, 1.0), name="house.walls"), ROOF)


@mutant(MUTANTS, STEP, "house_material_data", "unlit-walls", "walls textured but unlit")
def _(pkg):
    _materials(pkg, MaterialData("unlit_textured", ["house.brick"], color=(1.0, 1.0, 1.0), name="house.walls"), ROOF)


@mutant(MUTANTS, STEP, "house_material_data", "byte-orange", "orange as (255, 128, 0)")
def _(pkg):
    _materials(pkg, WALLS, MaterialData("shaded", color=(255.0, 128.0, 0.0), name="house.roof"))


@mutant(MUTANTS, STEP, "house_material_data", "red-roof", "a red roof instead of orange (1, 0.5, 0)")
def _(pkg):
    _materials(pkg, WALLS, MaterialData("shaded", color=(1.0, 0.0, 0.0), name="house.roof"))


@mutant(MUTANTS, STEP, "house_material_data", "swapped", "the walls' material under the roof's name and back")
def _(pkg):
    _materials(pkg, ROOF, WALLS)


# --- house_camera ----------------------------------------------------------------------------------


def _camera(
    pkg,
    *,
    eye=(0.0, 1.8, 4.2),
    target=(0.0, 0.8, 0.0),
    fov=45.0,
    keep_aspect=True,
    aim=True,
    projection=None,
    swap=False,
):
    def house_camera(aspect=None):
        e, t = np.array(eye), np.array(target)
        kwargs = {} if projection is None else {"projection": projection}
        camera = CameraComponent(fov, 0.1, 50.0, aspect=aspect if keep_aspect else None, **kwargs)
        q = look_at_rotation(t, e) if swap else look_at_rotation(e, t)
        return camera, TransformComponent(e, quaternion=q) if aim else TransformComponent(e)

    patch(pkg, "house.house_camera", house_camera)


for _name, _text, _slips in [
    ("ignores-aspect", "drops the aspect argument", {"keep_aspect": False}),
    ("looks-away", "look_at_rotation(target, eye): turned the wrong way", {"swap": True}),
    ("eye-target-swapped", "eye and target swapped: placed at the house's middle, looking out at the eye",
     {"eye": (0.0, 0.8, 0.0), "target": (0.0, 1.8, 4.2)}),
    ("off-centre", "looks past the house: the target a metre to its side", {"target": (1.0, 0.8, 0.0)}),
    ("radians-fov", "field of view given in radians (0.785 degrees)", {"fov": math.radians(45.0)}),
    ("too-far", "the camera ten times as far away", {"eye": (0.0, 8.8, 42.0)}),
    ("not-aimed", "placed but never turned towards the house", {"eye": (0.0, 4.0, 1.2), "aim": False}),
]:
    mutant(MUTANTS, STEP, "house_camera", _name, _text)(lambda pkg, _s=_slips: _camera(pkg, **_s))


# --- HouseRotationSystem ---------------------------------------------------------------------------


def _rotation(pkg, **slips):
    base = pkg.house.HouseRotationSystem

    class HouseRotationSystem(base):
        def on_update_entity(self, ts, entity, components):
            rotation, transform = components
            app = self.scene.app
            if not slips.get("no_pause") and app is not None and app.input.pressed(rotation.pause_key):
                rotation.paused = True if slips.get("pause_once") else not rotation.paused
            if not rotation.paused:
                step = rotation.speed * (1.0 if slips.get("per_frame") else ts)
                angle = rotation.angle + step
                rotation.angle = angle if slips.get("no_wrap") else math.fmod(angle, 360.0)
            axis = (1.0, 0.0, 0.0) if slips.get("x_axis") else (0.0, 1.0, 0.0)
            radians = rotation.angle if slips.get("radians") else math.radians(rotation.angle)
            transform.quaternion = quat_from_axis_angle(axis, radians)

    patch(pkg, "house.HouseRotationSystem", HouseRotationSystem)


for _name, _text, _slips in [
    ("radians", "the angle in degrees passed as radians", {"radians": True}),
    ("no-pause", "the pause key does nothing", {"no_pause": True}),
    ("pause-once", "the pause key pauses but never resumes", {"pause_once": True}),
    ("per-frame", "speed degrees per frame, not per second", {"per_frame": True}),
    ("x-axis", "turns about x instead of y", {"x_axis": True}),
    ("no-wrap", "the angle grows past 360", {"no_wrap": True}),
]:
    mutant(MUTANTS, STEP, "HouseRotationSystem", _name, _text)(lambda pkg, _s=_slips: _rotation(pkg, **_s))


# --- integrators -----------------------------------------------------------------------------------


def _euler(pkg, step):
    patch(pkg, "integrators.semi_implicit_euler_step", step)


@mutant(MUTANTS, STEP, "semi_implicit_euler_step", "explicit", "explicit Euler: the position with the OLD velocity")
def _(pkg):
    _euler(pkg, lambda x, v, a, dt: (x + v * dt, v + a(x, v) * dt))


@mutant(MUTANTS, STEP, "semi_implicit_euler_step", "position-first", "moves first, then the velocity from the new x")
def _(pkg):
    def step(x, v, a, dt):
        x_new = x + v * dt
        return x_new, v + a(x_new, v) * dt

    _euler(pkg, step)


@mutant(MUTANTS, STEP, "semi_implicit_euler_step", "no-dt-in-x", "x + v_new (forgets dt in the position)")
def _(pkg):
    def step(x, v, a, dt):
        v_new = v + a(x, v) * dt
        return x + v_new, v_new

    _euler(pkg, step)


@mutant(MUTANTS, STEP, "semi_implicit_euler_step", "no-damping", "acceleration evaluated at zero velocity")
def _(pkg):
    def step(x, v, a, dt):
        v_new = v + a(x, 0.0 * v) * dt
        return x + v_new * dt, v_new

    _euler(pkg, step)


@mutant(MUTANTS, STEP, "semi_implicit_euler_step", "trapezoid", "the position with the mean of old and new velocity")
def _(pkg):
    def step(x, v, a, dt):
        v_new = v + a(x, v) * dt
        return x + 0.5 * (v + v_new) * dt, v_new

    _euler(pkg, step)


def _rk4(pkg, *, weights=(1.0, 2.0, 2.0, 1.0), k2=0.5, k3=0.5, k4=1.0, stage_velocity=True, euler_x=False):
    total = sum(weights)

    def rk4_step(x, v, accel, dt):
        k1x, k1v = v, accel(x, v)
        k2x, k2v = (v + k2 * dt * k1v if stage_velocity else v), accel(x + k2 * dt * k1x, v + k2 * dt * k1v)
        k3x, k3v = (v + k3 * dt * k2v if stage_velocity else v), accel(x + k3 * dt * k2x, v + k3 * dt * k2v)
        k4x, k4v = (v + k4 * dt * k3v if stage_velocity else v), accel(x + k4 * dt * k3x, v + k4 * dt * k3v)
        w1, w2, w3, w4 = weights
        x_new = x + v * dt if euler_x else x + dt / total * (w1 * k1x + w2 * k2x + w3 * k3x + w4 * k4x)
        return x_new, v + dt / total * (w1 * k1v + w2 * k2v + w3 * k3v + w4 * k4v)

    patch(pkg, "integrators.rk4_step", rk4_step)


for _name, _text, _slips in [
    ("equal-weights", "weights 1, 1, 1, 1 instead of 1, 2, 2, 1", {"weights": (1.0, 1.0, 1.0, 1.0)}),
    ("full-step-k2", "k2 evaluated a whole step ahead", {"k2": 1.0}),
    ("half-step-k4", "k4 evaluated only half a step ahead", {"k4": 0.5}),
    ("frozen-velocity", "the position stages all use the starting velocity", {"stage_velocity": False}),
    ("euler-position", "RK4 for the velocity but x + v dt for the position", {"euler_x": True}),
]:
    mutant(MUTANTS, STEP, "rk4_step", _name, _text)(lambda pkg, _s=_slips: _rk4(pkg, **_s))
