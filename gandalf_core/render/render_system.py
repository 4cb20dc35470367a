"""The render system: the last system of a frame. Backend-neutral: it reads components, groups
entities into instanced batches, gathers their world matrices, and hands all of it to the renderer.

Batches are planned again only when components come or go; every frame costs one numpy gather
of the world matrices and one upload, whatever the number of entities.
"""

from __future__ import annotations

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
from ..systems.light_system import LightSystem, pack_lights
from .base import Renderer
from .color import srgb_rgba_to_linear
from .frame import DrawBatch, FrameData, pack_frame, pack_instances

DEFAULT_CLEAR = (0.0, 0.0, 0.0, 1.0)
_NO_LIGHTS = pack_lights([])


class RenderSystem(System):
    """Draws the scene with ``renderer`` once per frame."""

    def __init__(self, renderer: Renderer) -> None:
        super().__init__([TransformComponent, MeshComponent, MaterialComponent])
        self.renderer = renderer
        self._plan_version = -1
        self.batches: list[DrawBatch] = []
        self._rows: np.ndarray | slice = np.zeros(0, dtype=np.intp)
        self._instances: np.ndarray | None = None

    def on_create_system(self) -> None:
        scene = self.scene
        self._backgrounds = scene.query(ClearColorComponent)
        self._cameras = scene.query(CameraComponent, TransformComponent)
        self._skyboxes = scene.query(SkyboxComponent)

    # --8<-- [start:clear_color]
    def clear_color(self) -> np.ndarray:
        """The first ClearColorComponent's colour in linear light (black when the scene has none)."""
        comps = self._backgrounds.components
        return srgb_rgba_to_linear(comps[0][0].color if comps else DEFAULT_CLEAR)
    # --8<-- [end:clear_color]

    def primary_camera(self) -> tuple[object, CameraComponent, TransformComponent] | None:
        for entity, (camera, transform) in zip(self._cameras.entities, self._cameras.components):
            if camera.primary:
                return entity, camera, transform
        return None

    def camera(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
        """(view, projection, eye position, reverse_z) of the primary camera; identity when there is none.

        With no camera, positions are already clip-space coordinates (step 02 starts there).
        """
        chosen = self.primary_camera()
        if chosen is None:
            return np.eye(4), np.eye(4), np.zeros(3), False
        entity, camera, transform = chosen
        world = transform.world
        try:
            view = invert_affine(world)
        except ValueError as exc:
            raise ValueError(f"camera {self.scene.describe(entity)}: its world matrix is singular ({exc})") from None
        projection = camera.projection_matrix(self.renderer.depth_range, self.renderer.aspect)
        return view, projection, world[:3, 3].copy(), camera.reverse_z

    def plan(self) -> None:
        """Group entities by (material, mesh); sorted so that batches sharing a shader are adjacent."""
        groups: dict[tuple[str, str], list[int]] = {}
        for transform, mesh, material in self.components:
            groups.setdefault((material.material, mesh.mesh), []).append(transform._row)
        materials = self.scene.assets.materials
        self.batches = []
        first = 0
        for (material, mesh), rows in sorted(
            groups.items(), key=lambda kv: (getattr(materials.get(kv[0][0]), "shader", ""), kv[0])
        ):
            self.batches.append(DrawBatch(mesh, material, np.array(rows, dtype=np.intp), first))
            first += len(rows)
        rows = np.concatenate([b.rows for b in self.batches]) if self.batches else np.zeros(0, np.intp)
        # Consecutive rows (the common case: entities created together) are read as a slice, no gather.
        consecutive = len(rows) > 0 and rows[-1] - rows[0] == len(rows) - 1 and np.all(np.diff(rows) == 1)
        self._rows = slice(int(rows[0]), int(rows[-1]) + 1) if consecutive else rows
        self._plan_version = self.scene.membership_version

    def on_update_system(self, ts: float) -> None:
        self.renderer.render(self.frame_data(ts), self.scene.assets)

    def frame_data(self, ts: float) -> FrameData:
        """Collect this frame's uniforms and instance data."""
        scene = self.scene
        if self._plan_version != scene.membership_version:
            self.plan()
        view, projection, eye, reverse_z = self.camera()
        lo, hi = depth_range(self.renderer.depth_range)
        depth_ends = (hi, lo) if reverse_z else (lo, hi)
        app = scene.app
        frame = pack_frame(view, projection, eye, app.clock.time if app is not None else 0.0, ts, depth_ends)
        if self.batches:
            world = scene.store(TransformComponent).columns["world"]
            self._instances = pack_instances(world, self._rows, self._instances)
        light_systems = [s for s in scene.systems if isinstance(s, LightSystem)]
        lights = light_systems[0].data if light_systems else _NO_LIGHTS
        skyboxes = self._skyboxes.components
        return FrameData(
            clear_color=self.clear_color(),
            frame=frame,
            lights=lights,
            batches=self.batches,
            instances=self._instances if self.batches else None,
            skybox=skyboxes[0][0].texture if skyboxes else None,
            reverse_z=reverse_z,
        )
