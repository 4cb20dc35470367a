"""The exploding bunny, the same scene for OpenGL and WebGPU.

Every triangle of the bunny moves along its own face normal and back, periodically:

    offset(t) = amount · (1 − cos(2π t / period)) / 2 · n_face,   n_face = normalize((p1 − p0) × (p2 − p0))

in world space (after the model matrix), so the mesh is whole at t = 0 and at every whole period and flies
furthest apart (``amount`` along each normal) at half a period. The shader function ``explode_offset`` is the
step's exercise (``exercises/explode.glsl|.wgsl``).

The two APIs take different routes to the same triangles, and the variant files pass the route in
(:class:`ExplodeRoute`): OpenGL runs a geometry shader over the bunny's indexed triangles; WebGPU has no
geometry stage, so it draws ``3·F`` attribute-less vertices and its vertex shader *pulls* the triangle's three
corners from storage buffers. The time the shaders see is a material parameter (``explode_time``) that
:class:`ExplodeSystem` advances by the app's fixed time step, so a picture depends on the frame number only.
"""

from __future__ import annotations

import math
import uuid
from pathlib import Path
from types import ModuleType
from typing import Any, Protocol

import numpy as np

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Part
from gandalf_core.components import (
    CameraComponent,
    ClearColorComponent,
    InfoComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
)
from gandalf_core.ecs import Component, System
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, MeshData, ResourceError
from gandalf_core.resources.mesh_loader import load_mesh

from ..checks import checked_number

#: Frames the course tour renders before it takes the picture (at 60 frames per simulated second): 1.5 s,
#: 85 % of the way out.
TOUR_FRAMES = 90
BUNNY_PATH = Path(__file__).resolve().parents[2] / "step06_lighting" / "models" / "bunny.glb"
#: Seconds from one whole bunny to the next.
PERIOD = 4.0
#: How far (world units) each face moves at the peak, half a period in.
AMOUNT = 0.35
COLOR = (0.86, 0.55, 0.36)
SPECULAR = 0.3
SHININESS = 40.0
BACKGROUND = (0.08, 0.09, 0.12)
EYE = (0.0, 1.35, 4.4)
TARGET = (0.0, 0.85, 0.0)
FOV = 40.0
#: The shader that draws a mesh unexploded with the same lighting (tests compare against it).
LIT_SHADER = "explode_lit"


class ExplodeRoute(Protocol):
    """How one API gets exploded triangles on screen (the variant files pass one to :func:`build_scene`)."""

    #: The shader of the exploding material (built by the variant file).
    shader: str

    def prepare(self, name: str, mesh: MeshData) -> tuple[MeshData, tuple[str, ...]]:
        """The mesh the renderer draws for ``mesh`` and the storage buffers the material binds."""

    def check(self, mesh_name: str, mesh: MeshData, material_name: str, material: MaterialData) -> None:
        """Raise a ResourceError naming both when ``mesh`` cannot be drawn with ``material``."""


# --8<-- [start:geometry_route]
class GeometryShaderRoute:
    """OpenGL: the engine draws the indexed mesh as triangles; the program's geometry shader moves each one."""

    shader = "explode"

    def prepare(self, name: str, mesh: MeshData) -> tuple[MeshData, tuple[str, ...]]:
        return mesh, ()

    def check(self, mesh_name: str, mesh: MeshData, material_name: str, material: MaterialData) -> None:
        if mesh.normals is None:
            raise ResourceError(f"mesh '{mesh_name}'", "normals",
                                f"material '{material_name}' (shader '{material.shader}') shades with vertex normals")


# --8<-- [end:geometry_route]


# --8<-- [start:pulling_route]
class PullingRoute:
    """WebGPU: no geometry stage. The bunny's corners, normals and indices go to storage buffers
    (``renderer.buffers``); the renderer draws ``3·F`` attribute-less vertices and the vertex shader pulls each
    triangle's three corners from them. ``shader`` names the pulling program (GLSL works the same way)."""

    def __init__(self, renderer: Any, shader: str = "explode_pulled") -> None:
        self.renderer = renderer
        self.shader = shader
        self.faces: dict[tuple[str, ...], int] = {}

    def prepare(self, name: str, mesh: MeshData) -> tuple[MeshData, tuple[str, ...]]:
        triangles = mesh.triangles()
        count = mesh.vertex_count
        positions = np.ones((count, 4), np.float32)
        positions[:, :3] = mesh.positions
        normals = np.zeros((count, 4), np.float32)
        if mesh.normals is not None:
            normals[:, :3] = mesh.normals
        names = (f"{name}.positions", f"{name}.normals", f"{name}.indices")
        for buffer, data in zip(names, (positions, normals, np.ascontiguousarray(triangles.reshape(-1), np.uint32)),
                                strict=True):
            self.renderer.buffers.build(buffer, data)
        self.faces[names] = len(triangles)
        # The positions of this mesh are never uploaded: it only says how many vertices to draw.
        return MeshData(np.zeros((3 * len(triangles), 3)), name=f"{name} (pulled)"), names

    def check(self, mesh_name: str, mesh: MeshData, material_name: str, material: MaterialData) -> None:
        buffers = tuple(getattr(material, "buffers", ()))
        faces = self.faces.get(buffers)
        if faces is None:
            raise ResourceError(f"material '{material_name}'", "buffers",
                                f"{buffers!r} were not prepared by the vertex-pulling route (use add_exploding_mesh)")
        if mesh.indices is not None or mesh.vertex_count != 3 * faces:
            got = f"{mesh.index_count} indices" if mesh.indices is not None else f"{mesh.vertex_count} vertices"
            raise ResourceError(f"mesh '{mesh_name}'", "vertex_count",
                                f"material '{material_name}' pulls {faces} triangles from {buffers[0]!r}, so it needs "
                                f"a non-indexed mesh of 3 x {faces} = {3 * faces} vertices; got {got}")


# --8<-- [end:pulling_route]


def validate_explosion(label: str, amount: float, period: float) -> tuple[float, float]:
    """``amount`` (≥ 0) and ``period`` (> 0) as finite floats, or a ResourceError naming the parameter."""
    return (checked_number(label, "amount", amount, ">= 0", lambda v: v >= 0.0, "a number of world units"),
            checked_number(label, "period", period, "> 0", lambda v: v > 0.0, "a number of seconds"))


def explode_material(shader: str, amount: float = AMOUNT, period: float = PERIOD, *, time: float = 0.0,
                     buffers: tuple[str, ...] = (), color=COLOR, name: str = "explode") -> MaterialData:
    """The exploding material: Blinn-Phong values plus ``amount``, ``period`` and the current ``explode_time``."""
    amount, period = validate_explosion(f"material '{name}'", amount, period)
    params = {"explode_time": float(time), "amount": amount, "period": period, "specular": SPECULAR,
              "shininess": SHININESS}
    extra = {"buffers": tuple(buffers)} if buffers else {}
    return MaterialData(shader, color=color, params=params, cull="none", name=name, **extra)


def lit_material(color=COLOR) -> MaterialData:
    """The same surface, never exploded (shader :data:`LIT_SHADER`)."""
    return MaterialData(LIT_SHADER, color=color, params={"specular": SPECULAR, "shininess": SHININESS}, cull="none",
                        name="lit")


class ExplodeComponent(Component):
    """The explosion clock of an entity whose material explodes: ``time`` (s) advances by ``speed`` × dt."""

    def __init__(self, time: float = 0.0, speed: float = 1.0) -> None:
        for key, value in (("time", time), ("speed", speed)):
            if not math.isfinite(float(value)):
                raise ValueError(f"ExplodeComponent.{key} must be finite, got {value!r}")
        self.time = float(time)
        self.speed = float(speed)


# --8<-- [start:clock]
class ExplodeSystem(System):
    """Checks each exploding entity's mesh against its material, then every frame advances the explosion
    clock and writes it to the material's ``explode_time`` (no shader or pipeline is rebuilt)."""

    def __init__(self, route: ExplodeRoute) -> None:
        super().__init__((ExplodeComponent, MeshComponent, MaterialComponent))
        self.route = route

    def on_create_entity(self, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        _explode, mesh, material = components
        assets = self.scene.assets
        if mesh.mesh in assets.meshes and material.material in assets.materials:
            self.route.check(mesh.mesh, assets.meshes[mesh.mesh], material.material,
                             assets.materials[material.material])

    def on_update_entity(self, ts: float, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        explode, _mesh, material = components
        explode.time += explode.speed * ts
        app = self.scene.app
        if app is None:
            return
        built = app.renderer.resolve_material(material.material, self.scene.assets)
        built.set_values({**built.data.uniform_values(), "explode_time": explode.time})


# --8<-- [end:clock]


def add_exploding_mesh(scene: Scene, route: ExplodeRoute, name: str, mesh: MeshData, *, time: float = 0.0,
                       speed: float = 1.0, amount: float = AMOUNT, period: float = PERIOD,
                       transform: TransformComponent | None = None) -> uuid.UUID:
    """Register ``mesh`` and its exploding material (both called ``name``) the ``route``'s way; add an entity."""
    drawn, buffers = route.prepare(name, mesh)
    scene.assets.mesh(name, drawn)
    scene.assets.material(name, explode_material(route.shader, amount, period, time=time, buffers=buffers,
                                                 name=name))
    return scene.create_entity(InfoComponent(f"exploding {name}"), transform or TransformComponent(),
                               ExplodeComponent(time, speed), MeshComponent(name), MaterialComponent(name))


def add_view(scene: Scene, eye=EYE, target=TARGET) -> None:
    """Camera (at ``eye``, looking at ``target``), background and lights shared by the demo, the tests and the
    study: a key and a fill light and ambient."""
    scene.create_entity(InfoComponent("background"), ClearColorComponent(BACKGROUND))
    key = (-3.0, 5.0, 4.0)
    scene.create_entity(InfoComponent("key light"),
                        TransformComponent(key, quaternion=look_at_rotation(key, (0, 0, 0))),
                        LightComponent("directional", (1.0, 0.96, 0.9), intensity=1.1))
    fill = (4.0, 1.5, -2.0)
    scene.create_entity(InfoComponent("fill light"),
                        TransformComponent(fill, quaternion=look_at_rotation(fill, (0, 0, 0))),
                        LightComponent("directional", (0.55, 0.65, 1.0), intensity=0.45))
    scene.create_entity(InfoComponent("ambient"), TransformComponent(), LightComponent("ambient", (0.16, 0.16, 0.2)))
    scene.create_entity(InfoComponent("camera"), TransformComponent(eye, quaternion=look_at_rotation(eye, target)),
                        CameraComponent(FOV, 0.1, 100.0))


def bunny() -> MeshData:
    """The course's bunny (step 06's model)."""
    return load_mesh(BUNNY_PATH)


def build_scene(impl: ModuleType, route: ExplodeRoute, *, time: float = 0.0, speed: float = 1.0) -> Scene:
    """The demo: the bunny exploding and re-assembling every :data:`PERIOD` seconds. ``impl`` (exercises or
    solutions) is the package the variant file built the shaders with; ``time``/``speed`` set the clock."""
    del impl  # the shaders were built with it; the scene itself is the same for both
    scene = Scene("step07_explode")
    add_exploding_mesh(scene, route, "bunny", bunny(), time=time, speed=speed,
                       transform=TransformComponent(rotation=(0.0, 35.0, 0.0)))
    add_view(scene)
    scene.add_system(ExplodeSystem(route))
    return scene


# --- the numpy reference (float64) ------------------------------------------------------------------
def face_normals_np(p0: np.ndarray, p1: np.ndarray, p2: np.ndarray) -> np.ndarray:
    """Unit face normals by the right-hand rule, rows of zeros for zero-area triangles (the exercise's rule)."""
    e1 = np.asarray(p1, np.float64) - np.asarray(p0, np.float64)
    e2 = np.asarray(p2, np.float64) - np.asarray(p0, np.float64)
    s = np.maximum(np.abs(e1), np.abs(e2)).max(axis=-1, keepdims=True)
    safe = np.where(s > 0.0, s, 1.0)
    c = np.cross(e1 / safe, e2 / safe)
    length = np.linalg.norm(c, axis=-1, keepdims=True)
    ok = (s > 0.0) & (length > 1e-12)
    return np.where(ok, c / np.where(ok, length, 1.0), 0.0)


def explode_weight_np(t: np.ndarray | float, period: float) -> np.ndarray:
    """(1 − cos(2π t / period)) / 2: 0 at whole periods, 1 at half periods."""
    return 0.5 - 0.5 * np.cos(2.0 * np.pi * np.asarray(t, np.float64) / period)


def explode_offset_np(p0, p1, p2, t, amount, period) -> np.ndarray:
    """The exercise's ``explode_offset`` in float64, for arrays of triangles (rows) and times."""
    w = explode_weight_np(t, np.asarray(period, np.float64)) * np.asarray(amount, np.float64)
    return face_normals_np(p0, p1, p2) * np.asarray(w)[..., None]


def exploded_triangles_np(mesh: MeshData, model: np.ndarray, t: float, amount: float = AMOUNT,
                          period: float = PERIOD) -> np.ndarray:
    """World-space corners (F, 3, 3) of ``mesh`` under the affine ``model`` matrix, exploded to time ``t``."""
    p = mesh.positions.astype(np.float64) @ np.asarray(model, np.float64)[:3, :3].T + np.asarray(model)[:3, 3]
    corners = p[mesh.triangles().astype(np.int64)]
    offset = explode_offset_np(corners[:, 0], corners[:, 1], corners[:, 2], t, amount, period)
    return corners + offset[:, None, :]


# In saved scenes (step07_advanced.usd): the clock is saved; the system is not.


#: The technique the variants (``opengl.py``, ``webgpu.py``) hand the launcher with their backends.
PART = Part(__package__)
