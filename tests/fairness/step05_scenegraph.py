"""Correct alternatives of step 05: the house's open choices (joint placement, bricks per course, camera pose) and
other valid ways to write the milestones and integrators."""

from __future__ import annotations

import math

import numpy as np

from gandalf_core import TransformComponent
from gandalf_core.components import CameraComponent
from gandalf_core.math import look_at_rotation, quat_from_axis_angle
from gandalf_core.resources import MeshData, TextureData, cube, pyramid
from gandalf_tools.grading.fairness import alternative
from gandalf_tools.grading.mutants import Mutant, patch

STEP = "step05_scenegraph"
ALTERNATIVES: list[Mutant] = []


# --- brick_texture_data: where the joints sit and how many bricks a course holds are free -------------------


def _bricks(*, bricks_per_course=2, bed_at_bottom=False, head_at_right=False, roll=(0, 0), shade=True):
    brick, mortar = np.array([0.62, 0.24, 0.17]), np.array([0.82, 0.80, 0.75])

    def brick_texture_data(size: int = 64) -> TextureData:
        rgb = np.empty((size, size, 3))
        course, length = size // 4, size // bricks_per_course
        for y in range(size):  # plain loops, as a student may write them
            row = y // course
            for x in range(size):
                along = (x - (length // 2 if row % 2 else 0)) % size
                in_course, in_brick = y % course, along % length
                bed = in_course >= course - 2 if bed_at_bottom else in_course < 2
                head = in_brick >= length - 2 if head_at_right else in_brick < 2
                factor = 1.0 - 0.08 * ((row * 3 + along // length) % 3) / 2 if shade else 1.0
                rgb[y, x] = mortar if bed or head else brick * factor
        rgb = np.roll(rgb, roll, axis=(0, 1))
        return TextureData.from_array(rgb, name="house.brick")

    return brick_texture_data


for _name, _text, _options in [
    ("joints-bottom-right", "bed joint along the bottom of a course, head joint at the right end of a brick",
     {"bed_at_bottom": True, "head_at_right": True}),
    ("four-per-course", "four bricks per course (the shift is then an eighth of the texture)",
     {"bricks_per_course": 4}),
    ("joints-across-the-edge", "the whole pattern moved by one texel both ways: joints cross the texture's edge",
     {"roll": (1, 1), "shade": False}),
]:
    alternative(ALTERNATIVES, STEP, "brick_texture_data", _name, _text)(
        lambda pkg, _o=_options: patch(pkg, "house.brick_texture_data", _bricks(**_o)))


# --- house_camera: any pose that frames the house --------------------------------------------------------


def _camera(eye, target, fov):
    def house_camera(aspect=None):
        e = np.asarray(eye, dtype=float)
        return CameraComponent(fov, 0.1, 50.0, aspect=aspect), TransformComponent(
            e, quaternion=look_at_rotation(e, np.asarray(target, dtype=float)))

    return house_camera


for _name, _text, _pose in [
    ("three-quarter", "a three-quarter view from the front right, above the eaves",
     ((3.0, 2.2, 3.2), (0.0, 0.85, 0.0), 45.0)),
    ("wide-and-close", "a 60° field of view from closer in, from the left", ((-2.2, 1.5, 2.0), (0.0, 0.8, 0.0), 60.0)),
    ("from-behind", "the house seen from behind (it looks the same from every side)",
     ((0.0, 1.8, -4.2), (0.0, 0.8, 0.0), 45.0)),
]:
    alternative(ALTERNATIVES, STEP, "house_camera", _name, _text)(
        lambda pkg, _p=_pose: patch(pkg, "house.house_camera", _camera(*_p)))


# --- house_meshes: another way to move the meshes ---------------------------------------------------------


@alternative(ALTERNATIVES, STEP, "house_meshes", "homogeneous-matrix",
             "moves the positions with a 4x4 translation matrix")
def _(pkg):
    def moved(mesh, dy, name):
        matrix = np.eye(4)
        matrix[1, 3] = dy
        homogeneous = np.c_[mesh.positions, np.ones(len(mesh.positions))] @ matrix.T
        return MeshData(homogeneous[:, :3], normals=mesh.normals, uvs=mesh.uvs, tangents=mesh.tangents,
                        indices=mesh.indices, name=name)

    patch(pkg, "house.house_meshes", lambda: (moved(cube(1.0), 0.5, "house.walls"),
                                               moved(pyramid(base=1.3, height=0.7), 1.0, "house.roof")))


# --- HouseRotationSystem: the wrap written with fmod ------------------------------------------------------


@alternative(ALTERNATIVES, STEP, "HouseRotationSystem", "fmod-plus-360",
             "math.fmod, then 360 added to a negative angle; the angle converted by hand")
def _(pkg):
    base = pkg.house.HouseRotationSystem

    class HouseRotationSystem(base):
        def on_update_entity(self, ts, entity, components):
            rotation, transform = components
            app = self.scene.app
            if app is not None and app.input.pressed(rotation.pause_key):
                rotation.paused = not rotation.paused
            if not rotation.paused:
                angle = math.fmod(rotation.angle + rotation.speed * ts, 360.0)
                rotation.angle = angle + 360.0 if angle < 0.0 else angle
            transform.quaternion = quat_from_axis_angle(np.array([0.0, 1.0, 0.0]), rotation.angle * math.pi / 180.0)

    patch(pkg, "house.HouseRotationSystem", HouseRotationSystem)


# --- integrators: RK4 from its Butcher tableau -----------------------------------------------------------


@alternative(ALTERNATIVES, STEP, "rk4_step", "butcher-tableau", "the four stages in a loop over the classical tableau")
def _(pkg):
    def rk4_step(x, v, accel, dt):
        nodes, weights = (0.0, 0.5, 0.5, 1.0), (1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0)
        kx, kv = None, None
        sum_x, sum_v = 0.0 * x, 0.0 * v
        for c, b in zip(nodes, weights):
            xs = x if kx is None else x + c * dt * kx
            vs = v if kv is None else v + c * dt * kv
            kx, kv = vs, accel(xs, vs)
            sum_x, sum_v = sum_x + b * kx, sum_v + b * kv
        return x + dt * sum_x, v + dt * sum_v

    patch(pkg, "integrators.rk4_step", rk4_step)


@alternative(ALTERNATIVES, STEP, "semi_implicit_euler_step", "symplectic-form",
             "x + dt v + dt² a: the same update with the position written out")
def _(pkg):
    def semi_implicit_euler_step(x, v, accel, dt):
        a = accel(x, v)
        return x + dt * v + dt * dt * a, v + dt * a

    patch(pkg, "integrators.semi_implicit_euler_step", semi_implicit_euler_step)
