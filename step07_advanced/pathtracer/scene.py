"""The path tracer's scene, the same for OpenGL and WebGPU: what is traced comes from the ECS.

Entities with a :class:`TracedSphereComponent` or a :class:`TracedMeshComponent` (and a TransformComponent) are
what the rays see; a :class:`PathTracerComponent` holds the settings, the primary camera's entity the eye, and a
SkyboxComponent's cube map the light (every path ends in the sky or carries no light). :class:`PathTraceSystem`
gathers them after the TransformSystem ran — world transforms applied on the CPU in float64, triangles sorted
into a BVH (``bvh.py``) — and packs float32 arrays for the GPU. Each frame it asks the kernel (``compute_gl.py`` /
``compute_wgpu.py``, passed in by the variant file) for one more sample per pixel, added to the accumulation
buffer; a full-screen material (``shaders/display.*``) shows the mean, tonemapped, every frame. When the camera or
an object moves, the accumulation starts again.

The display needs no mesh data: it draws one attribute-less triangle that covers the screen.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from gandalf_core import Scene, TransformComponent
from gandalf_core.app.cli import Needs, Part
from gandalf_core.components import (
    CameraComponent,
    ClearColorComponent,
    InfoComponent,
    MaterialComponent,
    MeshComponent,
    SkyboxComponent,
)
from gandalf_core.ecs import Component, System
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import CubeTextureData, MaterialData, MeshData, ResourceError, sky_cube, srgb_to_linear
from gandalf_core.resources.mesh_loader import load_mesh
from gandalf_core.systems import TransformSystem
from gandalf_core.systems.camera_controllers import OrbitControllerComponent, OrbitControllerSystem

from ..checks import checked_number
from .bvh import build_bvh, usable_triangles
from .shaders import DISPLAY_SHADER, PARAMS_LAYOUT

#: Frames (= samples per pixel) the course tour renders before it takes the picture.
TOUR_FRAMES = 32
#: The storage buffer the kernel accumulates into and the display material reads: vec4 per pixel (rgb sum, count).
ACCUM_BUFFER = "pathtracer.accum"
#: Material kinds, their number in the GPU's material table.
KINDS = {"lambert": 0, "metal": 1, "glass": 2}
#: The most bounces a path may take (each scatter is one); the shaders' loops take any number.
MAX_BOUNCES = 64
BUNNY_PATH = Path(__file__).resolve().parents[2] / "step06_lighting" / "models" / "bunny.glb"
EYE = (0.0, 1.15, 4.3)
TARGET = (0.0, 0.45, 0.0)
FOV = 40.0
SKY_SIZE = 128


# --- what the scene says -----------------------------------------------------------------------------------
@dataclass(frozen=True)
class TraceMaterial:
    """A path-traced surface: ``kind`` 'lambert' (diffuse), 'metal' (mirror, blurred by ``fuzz`` in [0, 1]) or
    'glass' (a dielectric of index ``ior`` > 0; ``color`` tints what passes). ``color`` is an sRGB albedo in
    [0, 1] (decoded to linear light here, as every colour a scene sets)."""

    kind: str = "lambert"
    color: tuple[float, float, float] = (0.8, 0.8, 0.8)
    fuzz: float = 0.0
    ior: float = 1.5
    name: str = "material"

    def __post_init__(self) -> None:
        label = f"path material '{self.name}'"
        if self.kind not in KINDS:
            raise ResourceError(label, "kind", f"{self.kind!r} is not one of {', '.join(map(repr, KINDS))}")
        try:
            c = np.asarray(self.color, np.float64).reshape(-1)
        except (TypeError, ValueError):
            raise ResourceError(label, "color", f"expected 3 numbers, got {self.color!r}") from None
        if c.size != 3 or not np.all(np.isfinite(c)) or np.any(c < 0.0) or np.any(c > 1.0):
            raise ResourceError(label, "color", f"expected 3 numbers in [0, 1] (an albedo), got {self.color!r}")
        object.__setattr__(self, "color", tuple(float(x) for x in c))
        for key, ok, rule in (("fuzz", lambda v: 0.0 <= v <= 1.0, "in [0, 1] (0: a mirror, 1: very rough)"),
                              ("ior", lambda v: v > 0.0, "> 0 (glass is about 1.5, 1 lets rays straight through)")):
            object.__setattr__(self, key, checked_number(label, key, getattr(self, key), rule, ok, f"a number {rule}"))

    def packed(self) -> np.ndarray:
        """Two vec4: (linear albedo, kind), (fuzz, ior, 0, 0)."""
        albedo = srgb_to_linear(np.asarray(self.color, np.float64))
        return np.array([*albedo, KINDS[self.kind], self.fuzz, self.ior, 0.0, 0.0], np.float64)


def lambert(color, name: str = "lambert") -> TraceMaterial:
    return TraceMaterial("lambert", color, name=name)


def metal(color, fuzz: float = 0.0, name: str = "metal") -> TraceMaterial:
    return TraceMaterial("metal", color, fuzz=fuzz, name=name)


def glass(ior: float = 1.5, color=(1.0, 1.0, 1.0), name: str = "glass") -> TraceMaterial:
    return TraceMaterial("glass", color, ior=ior, name=name)


def _trace_material(component: str, material: object) -> TraceMaterial:
    """``material`` checked to be a :class:`TraceMaterial` (the error names ``component``'s field)."""
    if not isinstance(material, TraceMaterial):
        raise TypeError(f"{component}.material must be a TraceMaterial, got {type(material).__name__}")
    return material


class TracedSphereComponent(Component):
    """A sphere of ``radius`` (world units, times the entity's uniform world scale) at the entity's position."""

    def __init__(self, radius: float, material: TraceMaterial) -> None:
        r = float(radius)
        if not (math.isfinite(r) and r > 0.0):
            raise ValueError(f"TracedSphereComponent.radius must be finite and > 0, got {radius!r}")
        self.radius = r
        self.material = _trace_material("TracedSphereComponent", material)


class TracedMeshComponent(Component):
    """The triangles of mesh asset ``mesh`` (in the scene's assets), placed by the entity's world transform."""

    def __init__(self, mesh: str, material: TraceMaterial) -> None:
        if not isinstance(mesh, str) or not mesh:
            raise TypeError(f"TracedMeshComponent.mesh must be a mesh asset name, got {mesh!r}")
        self.mesh = mesh
        self.material = _trace_material("TracedMeshComponent", material)


class PathTracerComponent(Component):
    """The settings: ``samples`` per pixel to accumulate (then it stops), ``max_bounces`` per path, the
    ``seed`` of the random streams, and the display's ``exposure``."""

    def __init__(self, samples: int = 4096, max_bounces: int = 8, seed: int = 1, exposure: float = 1.0) -> None:
        self.samples = check_count("PathTracerComponent.samples", samples, 1, 1 << 24,
                                   "samples per pixel (0 would show nothing)")
        self.max_bounces = check_count("PathTracerComponent.max_bounces", max_bounces, 1, MAX_BOUNCES, "bounces")
        self.seed = check_count("PathTracerComponent.seed", seed, 0, 2**32 - 1, "a 32-bit seed")
        e = float(exposure)
        if not (math.isfinite(e) and e > 0.0):
            raise ValueError(f"PathTracerComponent.exposure must be finite and > 0, got {exposure!r}")
        self.exposure = e


def check_count(name: str, value: Any, low: int, high: int, what: str) -> int:
    """``value`` as an int in [low, high], or a ValueError naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise ValueError(f"{name} must be an integer ({what}), got {value!r}")
    if not low <= int(value) <= high:
        raise ValueError(f"{name} must be in [{low}, {high}] ({what}), got {value}")
    return int(value)


# --- what the GPU gets ---------------------------------------------------------------------------------------
@dataclass
class TraceScene:
    """Everything the kernel traces, gathered from the ECS in float64 (world space)."""

    origin: np.ndarray
    right: np.ndarray  # unit camera axes
    up: np.ndarray
    forward: np.ndarray
    fov: float  # vertical, degrees
    aspect: float | None  # None: the target's
    spheres: np.ndarray  # (S, 4): centre, radius
    sphere_materials: np.ndarray  # (S,) int
    triangles: np.ndarray  # (T, 3, 3) corners
    normals: np.ndarray  # (T, 3, 3) unit vertex normals
    triangle_materials: np.ndarray  # (T,) int
    materials: list[TraceMaterial]
    sky: np.ndarray | None  # (6, n, n, 3) linear RGB, or None
    background: np.ndarray  # linear RGB when there is no sky
    settings: PathTracerComponent = field(default_factory=PathTracerComponent)


@dataclass
class PackedScene:
    """float32 arrays for the storage buffers (never empty: a dummy row when there is nothing) and the counts."""

    spheres: np.ndarray
    materials: np.ndarray
    triangles: np.ndarray
    nodes: np.ndarray
    sky: np.ndarray
    counts: tuple[int, int, int]  # spheres, triangles, nodes
    camera: np.ndarray  # (4, 4) float64 rows: origin, right * tan * aspect, up * tan, forward
    background: np.ndarray  # (4,) rgb, sky face size
    max_bounces: int
    seed: int

    def params(self, sample_index: int, width: int, height: int, seed: int | None = None) -> bytes:
        """The kernels' Params block for one dispatch (:data:`.shaders.PARAMS_LAYOUT`)."""
        origin, right, up, forward = self.camera
        return PARAMS_LAYOUT.pack({
            "origin": origin, "right": right, "up": up, "forward": forward, "background": self.background,
            "size": (width, height, sample_index & 0xFFFFFFFF, self.seed if seed is None else seed),
            "counts": (*self.counts, self.max_bounces)})


def _world_of(scene: Scene, entity: Any) -> np.ndarray:
    transform = scene.try_component(entity, TransformComponent)
    return np.eye(4) if transform is None else np.asarray(transform.world, np.float64)


def sky_texels(cube: CubeTextureData) -> np.ndarray:
    """A cube map's level 0 as linear RGB float64 (6, n, n, 3) (sRGB-decoded when the texture is sRGB)."""
    rgb = cube.pixels[..., :3].astype(np.float64) / 255.0
    return srgb_to_linear(rgb) if cube.srgb else rgb


def gather(scene: Scene) -> TraceScene:
    """What the rays see, from the scene's entities (world matrices must be current: run after TransformSystem)."""
    settings = [c for _, (c,) in scene.view(PathTracerComponent)]
    config = settings[0] if settings else PathTracerComponent()
    cameras = [(e, c) for e, (c,) in scene.view(CameraComponent) if c.primary]
    if not cameras:
        raise ResourceError(f"scene '{scene.name}'", "camera", "the path tracer needs a primary CameraComponent")
    cam_entity, camera = cameras[0]
    if camera.projection != "perspective":
        raise ResourceError(scene.describe(cam_entity), "CameraComponent.projection",
                            f"the path tracer shoots perspective rays; got {camera.projection!r}")
    m = _world_of(scene, cam_entity)
    lengths = np.linalg.norm(m[:3, :3], axis=0)
    if not np.all(np.isfinite(lengths) & (lengths > 0.0)):  # its axes, and so its rays, would be NaN
        raise ResourceError(scene.describe(cam_entity), "TransformComponent.scale",
                            f"the path tracer's camera needs a non-zero world scale on every axis (its axes give the "
                            f"rays' directions); got axis lengths {lengths.tolist()}")
    axes = m[:3, :3] / lengths
    materials: list[TraceMaterial] = []
    index: dict[int, int] = {}

    def material_index(mat: TraceMaterial) -> int:
        if id(mat) not in index:
            index[id(mat)] = len(materials)
            materials.append(mat)
        return index[id(mat)]

    spheres, sphere_mats = [], []
    for entity, (sphere,) in scene.view(TracedSphereComponent):
        w = _world_of(scene, entity)
        scale = np.linalg.norm(w[:3, :3], axis=0)
        if not np.allclose(scale, scale[0], rtol=1e-9):
            raise ResourceError(scene.describe(entity), "TransformComponent.scale",
                                f"a traced sphere needs a uniform world scale, got {np.round(scale, 6).tolist()}")
        spheres.append([*w[:3, 3], sphere.radius * scale[0]])
        sphere_mats.append(material_index(sphere.material))
    tris, norms, tri_mats = [], [], []
    for entity, (traced,) in scene.view(TracedMeshComponent):
        mesh = scene.assets.meshes.get(traced.mesh)
        if mesh is None:
            raise ResourceError(scene.describe(entity), "TracedMeshComponent.mesh",
                                f"no mesh asset named {traced.mesh!r} in scene '{scene.name}'")
        corners, normals = world_triangles(mesh, _world_of(scene, entity), f"mesh '{traced.mesh}'")
        tris.append(corners)
        norms.append(normals)
        tri_mats.append(np.full(len(corners), material_index(traced.material)))
    sky = None
    skies = [(e, c) for e, (c,) in scene.view(SkyboxComponent)]
    if skies:
        entity, box = skies[0]
        cube = scene.assets.textures.get(box.texture)
        if not isinstance(cube, CubeTextureData):
            got = "nothing" if cube is None else f"a 2-D texture ({type(cube).__name__})"
            raise ResourceError(scene.describe(entity), "SkyboxComponent.texture",
                                f"the path tracer's sky must be a cube map (CubeTextureData) in the scene's assets; "
                                f"{box.texture!r} is {got}")
        sky = sky_texels(cube)
    clear = [c for _, (c,) in scene.view(ClearColorComponent)]
    background = srgb_to_linear(np.asarray(clear[0].color[:3], np.float64)) if clear else np.zeros(3)
    return TraceScene(
        origin=m[:3, 3].copy(), right=axes[:, 0], up=axes[:, 1], forward=-axes[:, 2], fov=float(camera.fov),
        aspect=camera.aspect, spheres=np.array(spheres, np.float64).reshape(-1, 4),
        sphere_materials=np.array(sphere_mats, np.int64),
        triangles=np.concatenate(tris) if tris else np.zeros((0, 3, 3)),
        normals=np.concatenate(norms) if norms else np.zeros((0, 3, 3)),
        triangle_materials=np.concatenate(tri_mats) if tri_mats else np.zeros(0, np.int64),
        materials=materials, sky=sky, background=background, settings=config)


def world_triangles(mesh: MeshData, world: np.ndarray, label: str) -> tuple[np.ndarray, np.ndarray]:
    """The mesh's usable triangles in world space (T, 3, 3) and their unit vertex normals (T, 3, 3), float64.
    Normals come from the mesh (inverse-transpose of the world matrix) or, without them, the face normals.
    Degenerate (zero-area) triangles are dropped; none left is a ResourceError naming ``label``."""
    if mesh.patch_size is not None:
        raise ResourceError(label, "patch_size", "a patch mesh has no triangles to trace")
    idx = mesh.triangles().astype(np.int64)
    positions = np.asarray(mesh.positions, np.float64) @ world[:3, :3].T + world[:3, 3]
    corners = positions[idx] if len(idx) else np.zeros((0, 3, 3))
    keep = usable_triangles(corners, label)
    corners = corners[keep]
    face = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    face /= np.linalg.norm(face, axis=1, keepdims=True)
    if np.linalg.det(world[:3, :3]) < 0:
        face = -face  # a mirrored object keeps its outside out
    if mesh.normals is None:
        return corners, np.repeat(face[:, None, :], 3, axis=1)
    normal_matrix = np.linalg.inv(world[:3, :3]).T
    normals = (np.asarray(mesh.normals, np.float64) @ normal_matrix.T)[idx[keep]]
    length = np.linalg.norm(normals, axis=2, keepdims=True)
    normals = np.where(length > 1e-12, normals / np.maximum(length, 1e-300), face[:, None, :])
    return corners, normals


def pack(trace: TraceScene, width: int, height: int) -> PackedScene:
    """The float32 buffers and the camera rows for a ``width`` × ``height`` picture."""
    if not trace.materials:
        trace.materials.append(TraceMaterial())
    materials = np.array([m.packed() for m in trace.materials]).reshape(-1, 4)
    spheres = np.zeros((max(len(trace.spheres), 1), 8))
    spheres[:len(trace.spheres), :4] = trace.spheres
    spheres[:len(trace.spheres), 4] = trace.sphere_materials
    nodes = np.zeros((2, 4), np.float32)
    triangles = np.zeros((6, 4))
    node_count = 0
    if len(trace.triangles):
        bvh = build_bvh(trace.triangles, "traced meshes")
        o = bvh.order
        triangles = np.zeros((len(o), 6, 4))
        triangles[:, 0:3, :3] = trace.triangles[o]
        triangles[:, 3:6, :3] = trace.normals[o]
        triangles[:, 0, 3] = trace.triangle_materials[o]
        triangles = triangles.reshape(-1, 4)
        nodes = bvh.packed()
        node_count = len(bvh.nodes)
    if trace.sky is None:
        sky, size = np.zeros((1, 4)), 0
    else:
        size = trace.sky.shape[1]
        sky = np.zeros((6 * size * size, 4))
        sky[:, :3] = trace.sky.reshape(-1, 3)
    aspect = trace.aspect if trace.aspect is not None else width / height
    tan_half = math.tan(math.radians(trace.fov) / 2.0)
    camera = np.array([[*trace.origin, 0.0], [*(trace.right * tan_half * aspect), 0.0],
                       [*(trace.up * tan_half), 0.0], [*trace.forward, 0.0]])
    f32 = np.float32
    return PackedScene(spheres=spheres.reshape(-1, 4).astype(f32), materials=materials.astype(f32),
                       triangles=triangles.astype(f32), nodes=nodes.astype(f32), sky=sky.astype(f32),
                       counts=(len(trace.spheres), len(trace.triangles), node_count), camera=camera,
                       background=np.array([*trace.background, size], np.float64),
                       max_bounces=trace.settings.max_bounces, seed=trace.settings.seed)


# --- the running part -----------------------------------------------------------------------------------------
class PathKernel(Protocol):
    """What the system needs from a backend's kernel (``compute_gl.GLPathTracer`` / ``compute_wgpu.WGPUPathTracer``)."""

    width: int
    height: int

    def load(self, packed: PackedScene) -> None: ...
    def clear(self) -> None: ...
    def dispatch(self, sample_index: int) -> None: ...
    def release(self) -> None: ...


class PathTraceSystem(System):
    """Gathers the scene on its first frame (and again when a traced entity or the camera moves: the
    accumulation restarts) and adds one sample per pixel per frame until the settings' ``samples``."""

    def __init__(self, kernel: PathKernel) -> None:
        super().__init__((), name="PathTraceSystem")
        self.kernel = kernel
        self.samples = 0
        self.limit = 0
        self._signature: bytes | None = None

    def _world_signature(self) -> bytes:
        scene = self.scene
        parts = [_world_of(scene, e) for e, _ in scene.view(CameraComponent)]
        for kind in (TracedSphereComponent, TracedMeshComponent):
            parts += [_world_of(scene, e) for e, _ in scene.view(kind)]
        return b"".join(p.tobytes() for p in parts)

    def restart(self) -> None:
        """Gather and upload the scene again and start a new accumulation."""
        trace = gather(self.scene)
        self.kernel.load(pack(trace, self.kernel.width, self.kernel.height))
        self.kernel.clear()
        self.samples = 0
        self.limit = trace.settings.samples

    def on_update_system(self, ts: float) -> None:
        signature = self._world_signature()
        if signature != self._signature:
            self._signature = signature
            self.restart()
        if self.samples < self.limit:
            self.kernel.dispatch(self.samples)
            self.samples += 1

    def on_destroy_system(self) -> None:
        self.kernel.release()


def display_material(width: int, height: int, exposure: float = 1.0) -> MaterialData:
    """The full-screen material: the accumulation's mean × ``exposure``, tonemapped (ACES fit) in linear light.
    It writes depth (z = 0 in clip space) so that the renderer's sky pass, drawn where nothing else is, stays
    hidden behind it: the sky the path tracer sees is in the picture already."""
    return MaterialData(DISPLAY_SHADER, params={"exposure": float(exposure), "trace_width": float(width),
                                                "trace_height": float(height)},
                        buffers=(ACCUM_BUFFER,), cull="none", name="display")


def add_display(scene: Scene, width: int, height: int, exposure: float = 1.0) -> None:
    """One attribute-less triangle that covers the screen, drawn with :func:`display_material`."""
    scene.assets.mesh("fullscreen", MeshData(np.zeros((3, 3)), name="fullscreen"))
    scene.assets.material("display", display_material(width, height, exposure))
    scene.create_entity(InfoComponent("display"), TransformComponent(), MeshComponent("fullscreen"),
                        MaterialComponent("display"))


def add_tracer(scene: Scene, kernel: PathKernel, exposure: float = 1.0) -> PathTraceSystem:
    """The TransformSystem (world matrices first), the path tracing system and the display of ``scene``."""
    scene.add_system(TransformSystem())
    system = scene.add_system(PathTraceSystem(kernel))
    add_display(scene, kernel.width, kernel.height, exposure)
    return system


def camera_entity(scene: Scene, eye=EYE, target=TARGET, fov: float = FOV, orbit: bool = False) -> None:
    """The primary camera at ``eye`` looking at ``target``; with ``orbit`` the mouse turns it around the target
    (left drag) and zooms (scroll), and the accumulation restarts whenever it moves."""
    components = [InfoComponent("camera"), TransformComponent(eye, quaternion=look_at_rotation(eye, target)),
                  CameraComponent(fov=fov, near=0.1, far=100.0)]
    if orbit:
        offset = np.subtract(eye, target, dtype=np.float64)
        distance = float(np.linalg.norm(offset))
        components.append(OrbitControllerComponent(target, distance, math.degrees(math.atan2(offset[0], offset[2])),
                                                   math.degrees(math.asin(offset[1] / distance))))
    scene.create_entity(*components)


def build_scene(kernel: PathKernel, *, samples: int = 4096, max_bounces: int = 8, seed: int = 1,
                sky_size: int = SKY_SIZE, bunny: bool = True) -> Scene:
    """The showcase: a glass, a metal and two diffuse spheres and the bunny on a huge ground sphere, under the
    daylight sky cube map."""
    scene = Scene("step07_pathtracer")
    scene.assets.texture("sky", sky_cube(sky_size))
    scene.create_entity(InfoComponent("sky"), SkyboxComponent("sky"))
    scene.create_entity(InfoComponent("settings"), PathTracerComponent(samples=samples, max_bounces=max_bounces,
                                                                       seed=seed))
    camera_entity(scene, orbit=True)
    scene.add_system(OrbitControllerSystem())  # before add_tracer: the camera moves, then the tracer looks
    spheres = [
        ("ground", (0.0, -1000.0, 0.0), 1000.0, lambert((0.8, 0.76, 0.66), "ground")),
        ("glass ball", (-1.25, 0.5, 0.35), 0.5, glass(1.5)),
        ("metal ball", (1.25, 0.5, 0.1), 0.5, metal((0.9, 0.75, 0.45), 0.08, "gold")),
        ("blue ball", (0.55, 0.22, 1.15), 0.22, lambert((0.15, 0.3, 0.75), "blue")),
    ]
    for name, centre, radius, mat in spheres:
        scene.create_entity(InfoComponent(name), TransformComponent(centre), TracedSphereComponent(radius, mat))
    if bunny:
        scene.assets.mesh("bunny", load_mesh(BUNNY_PATH))
        scene.create_entity(InfoComponent("bunny"), TransformComponent((0.0, 0.0, -0.35), rotation=(0.0, 20.0, 0.0),
                                                                       scale=0.55),
                            TracedMeshComponent("bunny", lambert((0.86, 0.55, 0.36), "clay")))
    add_tracer(scene, kernel)
    return scene


# --- numpy references (the tests and the study use them) ------------------------------------------------------
def pcg_hash_np(v: np.ndarray) -> np.ndarray:
    """The shaders' PCG hash on uint32 arrays (wrapping arithmetic)."""
    v = np.asarray(v, np.uint32)
    with np.errstate(over="ignore"):
        state = v * np.uint32(747796405) + np.uint32(2891336453)
        word = ((state >> ((state >> np.uint32(28)) + np.uint32(4))) ^ state) * np.uint32(277803737)
    return (word >> np.uint32(22)) ^ word


def sample_sky_np(texels: np.ndarray, directions: np.ndarray) -> np.ndarray:
    """The shaders' bilinear cube-map lookup in float64: ``texels`` (6, n, n, 3), ``directions`` (..., 3)."""
    d = np.asarray(directions, np.float64)
    shape = d.shape[:-1]
    d = d.reshape(-1, 3)
    size = texels.shape[1]
    a = np.abs(d)
    x_major = (a[:, 0] >= a[:, 1]) & (a[:, 0] >= a[:, 2])
    y_major = ~x_major & (a[:, 1] >= a[:, 2])
    z_major = ~x_major & ~y_major
    face = np.where(x_major, np.where(d[:, 0] > 0, 0, 1), np.where(y_major, np.where(d[:, 1] > 0, 2, 3),
                                                                  np.where(d[:, 2] > 0, 4, 5)))
    ma = np.where(x_major, a[:, 0], np.where(y_major, a[:, 1], a[:, 2]))
    sc = np.where(x_major, np.where(d[:, 0] > 0, -d[:, 2], d[:, 2]),
                  np.where(y_major, d[:, 0], np.where(d[:, 2] > 0, d[:, 0], -d[:, 0])))
    tc = np.where(x_major | z_major, -d[:, 1], np.where(d[:, 1] > 0, d[:, 2], -d[:, 2]))
    fx = 0.5 * (sc / ma + 1.0) * size - 0.5
    fy = 0.5 * (tc / ma + 1.0) * size - 0.5
    x0 = np.clip(np.floor(fx), 0, size - 1)
    y0 = np.clip(np.floor(fy), 0, size - 1)
    wx = np.clip(fx - x0, 0.0, 1.0)[:, None]
    wy = np.clip(fy - y0, 0.0, 1.0)[:, None]
    c0, r0 = x0.astype(int), y0.astype(int)
    c1, r1 = np.minimum(c0 + 1, size - 1), np.minimum(r0 + 1, size - 1)
    top = texels[face, r0, c0] * (1 - wx) + texels[face, r0, c1] * wx
    bottom = texels[face, r1, c0] * (1 - wx) + texels[face, r1, c1] * wx
    return (top * (1 - wy) + bottom * wy).reshape(*shape, 3)


def tonemap_np(mean: np.ndarray, exposure: float = 1.0) -> np.ndarray:
    """The display's tonemap in float64 (linear in, linear out, [0, 1]): Narkowicz's ACES fit."""
    x = np.maximum(np.asarray(mean, np.float64) * exposure, 0.0)
    return np.clip((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0)




def rng_seed_np(pixel: np.ndarray, sample_index: int, seed: int) -> np.ndarray:
    """The shaders' ``rng_seed`` on uint32 arrays."""
    inner = pcg_hash_np(np.uint32(sample_index & 0xFFFFFFFF) ^ pcg_hash_np(np.uint32(seed)))
    return pcg_hash_np(np.asarray(pixel, np.uint32) ^ inner)


def rng_next_np(state: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(new state, number in [0, 1)) as the shaders' ``rng_next``."""
    state = pcg_hash_np(state)
    return state, (state >> np.uint32(8)).astype(np.float64) / 16777216.0


def camera_rays_np(packed: PackedScene, width: int, height: int, sample_index: int) -> np.ndarray:
    """The unit directions (height, width, 3) of sample ``sample_index``'s camera rays, float64: the kernel's
    jitter (its first two random numbers per pixel) and pinhole camera."""
    y, x = np.mgrid[0:height, 0:width]
    state = rng_seed_np((y * width + x).astype(np.uint32), sample_index, packed.seed)
    state, jx = rng_next_np(state)
    state, jy = rng_next_np(state)
    sx = 2.0 * (x + jx) / width - 1.0
    sy = 1.0 - 2.0 * (y + jy) / height
    cam = packed.camera
    d = cam[3, :3] + sx[..., None] * cam[1, :3] + sy[..., None] * cam[2, :3]
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


# In saved scenes (step07_advanced.usd): refused, naming why.


#: The technique the variants (``opengl.py``, ``webgpu.py``) hand the launcher with their backends.
PART = Part(__package__, needs=Needs(opengl=430, opengl_for="compute shaders and storage buffers"))
