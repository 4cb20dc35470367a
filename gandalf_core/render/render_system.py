"""The render system: the last system of a frame. Backend-neutral: it reads components, groups
entities into instanced batches, gathers their world matrices, and hands all of it to the renderer.

Batches are planned again only when components come or go. Instance rows are packed again only for the
entities whose world matrix the transform system wrote this frame (its ``changed`` rows), and the renderer
uploads only that span: a frame in which nothing moved uploads nothing. A moving camera moves every row (they are
camera-relative), as do blended batches (sorted every frame): those frames pack and upload every row.
Instances whose world matrix mirrors
(a negative determinant, e.g. one negative scale) turn their triangles' winding around; they are drawn in a
batch of their own with clockwise front faces, so culling keeps the faces that point at the camera.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..components import (
    CameraComponent,
    ClearColorComponent,
    MaterialComponent,
    MeshComponent,
    SkyboxComponent,
    TransformComponent,
)
from ..ecs import System
from ..math import depth_range, invert_affine
from ..math.transform import cross3
from ..resources import MaterialData
from ..systems.light_system import LightSystem, pack_lights, pack_shadow
from ..systems.transform_system import TransformSystem
from .base import Renderer
from .color import srgb_rgba_to_linear
from .frame import DrawBatch, FrameData, pack_frame, pack_instance_rows, pack_instances

DEFAULT_CLEAR = (0.0, 0.0, 0.0, 1.0)
_FEW_INSTANCES = 8
_NO_LIGHTS = pack_lights([]) + pack_shadow([])


class RenderSystem(System):
    """Draws the scene with ``renderer`` once per frame."""

    saved = False  # the app adds it; a saved scene does not hold it

    def __init__(self, renderer: Renderer) -> None:
        super().__init__([TransformComponent, MeshComponent, MaterialComponent])
        self.renderer = renderer
        self._plan_key: tuple[int, int] = (-1, -1)
        self.batches: list[DrawBatch] = []
        self._rows: np.ndarray | slice = np.zeros(0, dtype=np.intp)
        self._instances: np.ndarray | None = None
        self._clear_key: bytes = b""
        self._clear_linear = np.zeros(4)
        #: False while another view shows the scene and covers this frame (the editor's viewport panel): the
        #: frame is then only cleared, and its overlays drawn, instead of drawing the scene a second time.
        self.draws_scene = True
        self._blank_frame: bytes | None = None  # the frame block of a cleared frame, made on first use
        # What the packed rows were made from: the transform system's generation and the origin (None: repack all).
        self._packed_generation: int | None = None
        self._packed_origin = np.full(3, np.nan)
        self._instance_of_row: np.ndarray | None = None  # store row -> instance row (-1: not drawn)
        self._frames = 0
        self._token = object()  # names this system's instance rows to the renderer
        self._mirrored_any = False
        self._frame_batches: list[DrawBatch] = []
        self._transform_system = None
        self._camera_key: tuple | None = None  # what the last camera() was computed from, and its result
        self._camera_value: tuple[np.ndarray, np.ndarray, np.ndarray, bool] | None = None
        self._order = 0  # bumped whenever the instance order changes (a new plan, sorting, mirrored splits)

    def on_create_system(self) -> None:
        scene = self.scene
        self._backgrounds = scene.query(ClearColorComponent)
        self._cameras = scene.query(CameraComponent, TransformComponent)
        self._skyboxes = scene.query(SkyboxComponent)

    # --8<-- [start:clear_color]
    def clear_color(self) -> np.ndarray:
        """The first ClearColorComponent's colour in linear light (black when the scene has none)."""
        comps = self._backgrounds.components
        srgb = np.asarray(comps[0][0].color if comps else DEFAULT_CLEAR, dtype=np.float64)
        key = srgb.tobytes()
        if key != self._clear_key:  # converted again only when the colour changes
            self._clear_key, self._clear_linear = key, srgb_rgba_to_linear(srgb)
        return self._clear_linear
    # --8<-- [end:clear_color]

    def primary_camera(self) -> tuple[object, CameraComponent, TransformComponent] | None:
        for entity, (camera, transform) in zip(self._cameras.entities, self._cameras.components):
            if camera.primary:
                return entity, camera, transform
        return None

    def camera(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
        """(view, projection, eye position, reverse_z) of the primary camera; identity when there is none.

        With no camera, positions are already clip-space coordinates (step 02 starts there). The matrices are
        computed again only when the camera's pose, its fields or the target's aspect change (every frame reads
        them; they are read-only arrays).
        """
        chosen = self.primary_camera()
        if chosen is None:
            return np.eye(4), np.eye(4), np.zeros(3), False
        entity, camera, transform = chosen
        world = transform.world
        depth = self.renderer.depth_range_for(camera.reverse_z)
        key = (world.tobytes(), camera.fov, camera.near, camera.far, camera.projection, camera.height, camera.aspect,
               camera.reverse_z, depth, self.renderer.aspect)
        if key == self._camera_key:
            return self._camera_value
        try:
            view = invert_affine(world)
        except ValueError as exc:
            raise ValueError(f"camera {self.scene.describe(entity)}: its world matrix is singular ({exc})") from None
        projection = camera.projection_matrix(depth, self.renderer.aspect)
        eye = world[:3, 3].copy()
        for matrix in (view, projection, eye):
            matrix.flags.writeable = False
        self._camera_key, self._camera_value = key, (view, projection, eye, camera.reverse_z)
        return self._camera_value

    def plan(self) -> None:
        """Group entities by (material, mesh): opaque batches first, sorted so that batches sharing a
        shader are adjacent, then the blended (transparent) ones, which are re-sorted every frame."""
        groups: dict[tuple[str, str], list[int]] = {}
        for transform, mesh, material in self.components:
            groups.setdefault((material.material, mesh.mesh), []).append(transform._row)

        def order(item: tuple[tuple[str, str], list[int]]) -> tuple[bool, str, str, str]:
            (material, mesh), _rows = item
            data = self._material_data(material)
            return (data is not None and data.blend != "opaque", getattr(data, "shader", ""), material, mesh)

        self.batches = []
        for (material, mesh), rows in sorted(groups.items(), key=order):
            data = self._material_data(material)
            transparent = data is not None and data.blend != "opaque"
            self.batches.append(DrawBatch(mesh, material, np.array(rows, dtype=np.intp), transparent=transparent))
        self._number_batches()
        rows = np.concatenate([b.rows for b in self.batches]) if self.batches else np.zeros(0, np.intp)
        # Consecutive rows (the common case: entities created together) are read as a slice, no gather.
        consecutive = len(rows) > 0 and rows[-1] - rows[0] == len(rows) - 1 and np.all(np.diff(rows) == 1)
        self._rows = slice(int(rows[0]), int(rows[-1]) + 1) if consecutive else rows
        self._number_rows(rows)
        self._plan_key = self._current_plan_key()
        self._packed_generation = None

    def _number_rows(self, rows: np.ndarray) -> None:
        """Remember which instance row each transform row is drawn as (-1: not drawn)."""
        self._instance_of_row = np.full(self.scene.store(TransformComponent).count, -1, dtype=np.intp)
        self._instance_of_row[rows] = np.arange(len(rows))
        self._order += 1

    def _material_data(self, name: str) -> MaterialData | None:
        data = self.scene.assets.materials.get(name)
        if data is None and name in self.renderer.materials:
            data = self.renderer.materials.get(name).data
        return data

    def _number_batches(self) -> None:
        first = 0
        for batch in self.batches:
            batch.first_instance = first
            first += batch.count

    def _sort_transparent(self, world: np.ndarray, view: np.ndarray) -> None:
        """Blended batches draw back to front: their instances by depth along the view direction (right for
        orthographic cameras too), the batches by their farthest instance. Instances of two blended
        batches at interleaved depths still come out batch by batch: the price of instancing."""
        transparent = [b for b in self.batches if b.transparent]
        if not transparent:
            return
        for batch in transparent:
            # View-space z is negative in front of the camera: the most negative is the farthest.
            distance = -(world[batch.rows, :3, 3] @ view[2, :3] + view[2, 3])
            order = np.argsort(-distance, kind="stable")
            batch.rows = batch.rows[order]
            batch.farthest = float(distance[order[0]])
        transparent.sort(key=lambda b: -b.farthest)
        self.batches = [b for b in self.batches if not b.transparent] + transparent
        self._number_batches()
        self._rows = np.concatenate([b.rows for b in self.batches])

    def _mirrored(self, world: np.ndarray) -> np.ndarray:
        """Per packed instance: does its world matrix flip handedness (negative determinant)?

        Read from the float32 rows just packed (no second gather of the float64 matrices: this runs every
        frame); the few rows where float32 cannot tell (a determinant that underflows to 0 or overflows, at
        scales like 1e-20 or 1e20) are decided again in float64 from the world matrices."""
        p = self._instances.reshape(-1, 3, 4)
        if len(p) <= _FEW_INSTANCES:  # plain floats: cheaper than a dozen numpy calls on a handful of rows
            dets = [a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0)
                    for (a0, b0, c0, _), (a1, b1, c1, _), (a2, b2, c2, _) in p.tolist()]
            if all(math.isfinite(d) and d != 0.0 for d in dets):
                return np.array(dets) < 0.0
        with np.errstate(over="ignore", invalid="ignore"):  # the rows it overflows in are decided below
            det = np.einsum("ij,ij->i", p[:, :, 0], cross3(p[:, :, 1], p[:, :, 2]))
        unsure = ~np.isfinite(det) | (det == 0.0)
        if unsure.any():
            rows = np.arange(len(world))[self._rows][unsure]
            m = world[rows, :3, :3]
            m = m / np.abs(m).max(axis=(1, 2), keepdims=True).clip(min=np.finfo(np.float64).tiny)
            det[unsure] = np.einsum("ij,ij->i", m[:, :, 0], cross3(m[:, :, 1], m[:, :, 2]))
        return det < 0.0

    def _split_mirrored(self, flipped: np.ndarray) -> list[DrawBatch]:
        """The frame's batches with each batch's mirrored instances split into a batch of their own."""
        batches, first = [], 0
        for batch in self.batches:
            mask = flipped[first:first + batch.count]
            first += batch.count
            for mirrored, part in ((False, batch.rows[~mask]), (True, batch.rows[mask])):
                if len(part):
                    batches.append(DrawBatch(batch.mesh, batch.material, part, transparent=batch.transparent,
                                             farthest=batch.farthest, mirrored=mirrored))
        first = 0
        for batch in batches:
            batch.first_instance = first
            first += batch.count
        return batches

    # --8<-- [start:pack]
    def _pack(self, world: np.ndarray, view: np.ndarray, origin: np.ndarray) -> tuple[int, int] | None:
        """Bring the packed instance rows up to date with the world matrices; return the span of rows that
        changed, or None when every row was packed anew. Sets the frame's batches (:attr:`_frame_batches`)."""
        transforms = self._transforms()
        if transforms is not None and not transforms.enabled:  # paused: world matrices may be written by hand
            transforms = None
        generation = transforms.generation if transforms is not None else None
        seen, self._packed_generation = self._packed_generation, generation
        same_origin = bool(np.array_equal(origin, self._packed_origin))
        if (seen is not None and same_origin and self._instances is not None and not self._mirrored_any
                and not any(b.transparent for b in self.batches)):
            if generation == seen:  # the transform system did not run: nothing moved
                return (0, 0)
            if generation == seen + 1:
                span = self._pack_changed(world, transforms.changed, origin, transforms.positive_scales)
                if span is not None:
                    return span
        self._packed_origin[:] = origin
        self._sort_transparent(world, view)  # may reorder the blended batches: a new self.batches
        self._frame_batches = self.batches
        self._instances = pack_instances(world, self._rows, self._instances, origin)
        # With every scale positive no instance can mirror: the per-instance determinants are not needed.
        flipped = None if transforms is not None and transforms.positive_scales else self._mirrored(world)
        reordered = self._mirrored_any or any(b.transparent for b in self.batches)
        self._mirrored_any = flipped is not None and bool(flipped.any())
        if self._mirrored_any:  # rare: mirrored instances get batches of their own, and the rows are packed anew
            self._frame_batches = self._split_mirrored(flipped)
            rows = np.concatenate([b.rows for b in self._frame_batches])
            self._instances = pack_instances(world, rows, self._instances, origin)
            self._number_rows(rows)
        elif reordered:  # sorted blended batches, or mirrored ones merged back: instance rows moved
            self._number_rows(np.arange(len(world))[self._rows])
        return None
    # --8<-- [end:pack]

    def _pack_changed(self, world: np.ndarray, rows: np.ndarray | None, origin: np.ndarray,
                      positive_scales: bool = False) -> tuple[int, int] | None:
        """Pack the instance rows of the store ``rows`` written this frame; their span, or None when they must all
        be packed again (every row changed, or one of them turned mirrored)."""
        if rows is None:
            return None
        if not len(rows):
            return (0, 0)
        rows = rows[rows < len(self._instance_of_row)]
        at = self._instance_of_row[rows]
        drawn = at >= 0
        if not drawn.all():
            rows, at = rows[drawn], at[drawn]
        if not len(at):
            return (0, 0)
        m = world[rows, :3, :3]
        if positive_scales:
            positive = True
        elif len(rows) <= _FEW_INSTANCES:  # plain floats: cheaper than numpy calls on a handful of rows
            positive = all(a0 * (b1 * c2 - b2 * c1) + a1 * (b2 * c0 - b0 * c2) + a2 * (b0 * c1 - b1 * c0) > 0.0
                           for (a0, a1, a2), (b0, b1, b2), (c0, c1, c2) in m.tolist())
        else:
            positive = bool((np.einsum("ij,ij->i", m[:, :, 0], cross3(m[:, :, 1], m[:, :, 2])) > 0.0).all())
        if not positive:  # mirrored (or too small to tell): the full path decides and splits the batches
            return None
        pack_instance_rows(world, rows, self._instances, at, origin)
        return int(at.min()), int(at.max()) + 1

    # --8<-- [start:instance_pass]
    def _instance_pass(self, time: float) -> Any:
        """The hook for GPU work over the frame's instance rows before the draws read them (step 07's GPU-driven
        motion): the first enabled system with an ``instance_pass(render_system, time)`` gives this frame's pass,
        which the renderer runs (None: no such system, the draws read the rows as uploaded)."""
        for system in self.scene.systems:
            if system.enabled and hasattr(system, "instance_pass"):
                return system.instance_pass(self, time)
        return None

    def instance_order(self) -> tuple[np.ndarray, int, tuple[object, int]]:
        """What a pass over the instance rows needs: transform row -> instance row (-1: not drawn), the number of
        instance rows, and a key that changes whenever that order does."""
        return self._instance_of_row, len(self._instances), (self._token, self._order)
    # --8<-- [end:instance_pass]

    def _transforms(self) -> TransformSystem | None:
        """The scene's transform system (it says which world matrices it wrote), or None."""
        found = self._transform_system
        if found is None or found.scene is not self.scene:
            found = next((s for s in self.scene.systems if isinstance(s, TransformSystem)), None)
            self._transform_system = found
        return found

    def _current_plan_key(self) -> tuple[int, int]:
        # Batches change when this system's entities change, and row indices when any transform row moves.
        return (self.version, self.scene.store(TransformComponent).layout_version)

    def on_update_system(self, ts: float) -> None:
        data = self.frame_data(ts) if self.draws_scene else self.cleared_frame()
        self.renderer.render(data, self.scene.assets)

    def cleared_frame(self) -> FrameData:
        """A frame of the clear colour alone: no batches, lights, sky or shadows (see :attr:`draws_scene`)."""
        if self._blank_frame is None:
            self._blank_frame = pack_frame(np.eye(4), np.eye(4), np.zeros(3), 0.0, 0.0)
        return FrameData(clear_color=self.clear_color(), frame=self._blank_frame, lights=_NO_LIGHTS, batches=[],
                         instances=None)

    def frame_data(self, ts: float) -> FrameData:
        """Collect this frame's uniforms and instance data."""
        scene = self.scene
        if self._plan_key != self._current_plan_key():
            self.plan()
        view, projection, eye, reverse_z = self.camera()
        lo, hi = depth_range(self.renderer.depth_range_for(reverse_z))
        depth_ends = (hi, lo) if reverse_z else (lo, hi)
        app = scene.app
        # --8<-- [start:camera_relative]
        # Camera-relative: the GPU gets positions with the camera at the origin, made in float64 here.
        origin = eye
        relative_view = view.copy()
        relative_view[:3, 3] += view[:3, :3] @ origin
        frame = pack_frame(relative_view, projection, eye - origin, app.clock.time if app is not None else 0.0, ts,
                           depth_ends, origin)
        # --8<-- [end:camera_relative]
        batches = self.batches
        span: tuple[int, int] | None = None
        if batches:
            span = self._pack(scene.store(TransformComponent).columns["world"], view, origin)
            batches = self._frame_batches
        self._frames += 1
        instance_pass = self._instance_pass(app.clock.time if app is not None else 0.0) if batches else None
        light_systems = [s for s in scene.systems if isinstance(s, LightSystem)]
        # The light system knows the lights, the renderer the depth range their shadow projection needs.
        lights = (light_systems[0].relative(origin) + light_systems[0].shadow(self.renderer.depth_range, origin)
                  if light_systems else _NO_LIGHTS)
        shadows = bool(light_systems) and light_systems[0].casts_shadows
        skyboxes = self._skyboxes.components
        return FrameData(
            clear_color=self.clear_color(),
            frame=frame,
            lights=lights,
            batches=batches,
            instances=self._instances if batches else None,
            instance_span=span,
            instances_version=(self._token, self._frames),
            instances_since=(self._token, self._frames - 1),
            instance_pass=instance_pass,
            skybox=skyboxes[0][0].texture if skyboxes else None,
            reverse_z=reverse_z,
            shadows=shadows,
        )
