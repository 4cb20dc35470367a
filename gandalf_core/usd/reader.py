"""Loading a Scene from a USD file written by :func:`gandalf_core.usd.save_scene` (or a compatible one).

USD files hold data only: nothing in them is executed. The file is parsed into a private layer (never a
cached one, so a file rewritten since an earlier load is read afresh) and turned into a brand-new Scene;
a problem anywhere raises :class:`USDSceneError` before the caller sees any of it.
"""

from __future__ import annotations

import math
import uuid
import warnings
from pathlib import Path
from typing import Any

import numpy as np
from pxr import Sdf, Usd, UsdGeom

from ..components import (
    CameraComponent,
    ClearColorComponent,
    InfoComponent,
    LightComponent,
    LinkComponent,
    MaterialComponent,
    MeshComponent,
    SkyboxComponent,
    TransformComponent,
)
from ..ecs import Component, Scene
from ..resources import linear_to_srgb
from . import assets as asset_prims
from .attributes import FileContext, authored, read, read_float, read_floats
from .errors import USDSceneError, USDSceneWarning
from .mapping import ENTITY_MESH_MARK, FORMAT_VERSION, LIGHT_KINDS, MATERIALS, MESHES, TEXTURES
from .registry import registration_named
from .writer import file_format

_XFORM_OPS = ["xformOp:translate", "xformOp:orient", "xformOp:scale"]


def load_scene(path: str | Path, *, name: str | None = None, strict: bool = True) -> Scene:
    """Read a .usda/.usdc file into a NEW Scene (named ``name``, else the saved scene name).

    Every problem (missing or unreadable file, wrong extension, a missing attribute or one of the wrong type,
    invalid component values, an unknown component) raises :class:`USDSceneError` naming the file, prim and
    attribute. Components of classes not registered with ``register_component`` are an error, or with
    ``strict=False`` a :class:`USDSceneWarning` and left out.
    """
    path = Path(path)
    file_format(path)
    ctx = FileContext(str(path))
    if not path.is_file():
        raise USDSceneError(path, "no such file")
    try:
        layer = Sdf.Layer.OpenAsAnonymous(str(path))
    except Exception as exc:  # Tf.ErrorException carries the parser's line and column
        raise USDSceneError(path, f"not a valid USD file: {_parser_message(exc)}") from None
    if layer is None:
        raise USDSceneError(path, "not a valid USD file")
    try:
        stage = Usd.Stage.Open(layer)
    except Exception as exc:
        raise USDSceneError(path, f"cannot open the USD stage: {str(exc).strip()}") from None
    return _Reader(ctx, stage, path, strict).scene_named(name)


def _parser_message(exc: Exception) -> str:
    """The parser's own words (with line and column) from a USD error, without its C++ source location."""
    last = str(exc).strip().split("Error in ")[-1]
    return last.split(" : ", 1)[-1].strip().strip("'").strip()


class _Reader:
    def __init__(self, ctx: FileContext, stage: Usd.Stage, path: Path, strict: bool) -> None:
        self.ctx = ctx
        self.stage = stage
        self.path = path
        self.strict = strict
        self.entity_of: dict[str, uuid.UUID] = {}

    def scene_named(self, name: str | None) -> Scene:
        ctx, stage = self.ctx, self.stage
        root = stage.GetDefaultPrim()
        if not root:
            raise ctx.fail(None, None, "the file has no default prim (the scene root)")
        version = read(ctx, root, "gandalf:version", "int", FORMAT_VERSION)
        if version > FORMAT_VERSION:
            raise ctx.fail(root, "gandalf:version", f"format {version} is newer than this gandalf ({FORMAT_VERSION})")
        scene = Scene(name or read(ctx, root, "gandalf:sceneName", "string", self.path.stem))
        self.read_assets(scene)
        prims = []  # parents before children, in authored order; an entity's visible mesh prim is not an entity
        it = iter(Usd.PrimRange(root))
        next(it)
        for prim in it:
            if authored(prim, ENTITY_MESH_MARK):
                it.PruneChildren()
                continue
            prims.append(prim)
        for prim in prims:
            self.entity_of[str(prim.GetPath())] = scene.enroll_entity()
        for prim in prims:
            entity = self.entity_of[str(prim.GetPath())]
            for component in self.components(prim):
                self.add(scene, entity, prim, component)
        self.read_root_components(scene, root)
        return scene

    def add(self, scene: Scene, entity: uuid.UUID, prim: Usd.Prim, component: Component) -> None:
        try:
            scene.add_component(entity, component)
        except (ValueError, TypeError, KeyError) as exc:
            raise self.ctx.fail(prim, None, f"cannot add {type(component).__name__}: {exc}") from None

    # --- assets ---------------------------------------------------------------------------------------
    def read_assets(self, scene: Scene) -> None:
        for folder, read_one, register in (
            (MESHES, asset_prims.read_mesh, scene.assets.mesh),
            (MATERIALS, asset_prims.read_material, scene.assets.material),
            (TEXTURES, lambda ctx, p: asset_prims.read_texture(ctx, p, self.path.parent), scene.assets.texture),
        ):
            parent = self.stage.GetPrimAtPath(folder)
            for prim in parent.GetChildren() if parent else ():
                name, data = read_one(self.ctx, prim)
                register(name, data)

    # --- components of one prim ---------------------------------------------------------------------
    def components(self, prim: Usd.Prim) -> list[Component]:
        ctx = self.ctx
        out: list[Component] = []
        name = read(ctx, prim, "gandalf:name", "string", None)
        if name is not None:
            out.append(InfoComponent(name, read(ctx, prim, "gandalf:tag", "string", "")))
        parent = prim.GetParent()
        parent_entity = self.entity_of.get(str(parent.GetPath()))
        if parent_entity is not None or read(ctx, prim, "gandalf:link", "bool", False):
            out.append(LinkComponent(parent_entity))
        transform = self.transform(prim)
        if transform is not None:
            out.append(transform)
        if prim.GetTypeName() == "Camera":
            out.append(self.guard(prim, "gandalf:fov", lambda: self.camera(prim)))
        light = self.light(prim)
        if light is not None:
            out.append(light)
        mesh = read(ctx, prim, "gandalf:mesh", "string", None)
        if mesh is not None:
            out.append(self.guard(prim, "gandalf:mesh", lambda: MeshComponent(mesh)))
        material = read(ctx, prim, "gandalf:material", "string", None)
        if material is not None:
            out.append(self.guard(prim, "gandalf:material", lambda: MaterialComponent(material)))
        out.extend(self.registered(prim))
        return out

    def guard(self, prim: Usd.Prim, attribute: str, build: Any) -> Any:
        """``build()``, with a component constructor's ValueError/TypeError turned into a USDSceneError."""
        try:
            return build()
        except USDSceneError:
            raise
        except (ValueError, TypeError) as exc:
            raise self.ctx.fail(prim, attribute, str(exc)) from None

    def transform(self, prim: Usd.Prim) -> TransformComponent | None:
        ctx = self.ctx
        order = read(ctx, prim, "xformOpOrder", "token[]", None)
        if order is None or len(order) == 0:
            return None
        if list(order) != _XFORM_OPS:
            raise ctx.fail(prim, "xformOpOrder", f"expected {_XFORM_OPS}, got {list(order)}")
        t = read_floats(ctx, prim, "xformOp:translate", ("double3",), 3)
        q = read(ctx, prim, "xformOp:orient", "quatd")
        quat = np.array([q.GetReal(), *q.GetImaginary()], dtype=np.float64)  # USD real-first = gandalf (w, x, y, z)
        if not np.isfinite(quat).all() or float(quat @ quat) < 1e-24:
            raise ctx.fail(prim, "xformOp:orient", f"must be a finite, non-zero quaternion, got {quat.tolist()}")
        s = read_floats(ctx, prim, "xformOp:scale", ("double3",), 3)
        component = TransformComponent(t, scale=s)
        component.quaternion = quat  # exactly as saved (the constructor would renormalise)
        return component

    def camera(self, prim: Usd.Prim) -> CameraComponent:
        ctx = self.ctx
        usd = UsdGeom.Camera(prim)
        projection = read(ctx, prim, "projection", "token", "perspective")
        clip = usd.GetClippingRangeAttr().Get()
        aperture = usd.GetVerticalApertureAttr().Get()
        # Files from other tools lack the exact gandalf: values; fall back to the standard camera attributes
        # (read only then: a gandalf file's own values must not depend on them).
        if authored(prim, "gandalf:fov"):
            fov = read_float(ctx, prim, "gandalf:fov")
        else:
            focal = usd.GetFocalLengthAttr().Get()
            if not (focal and focal > 0 and aperture and aperture > 0):
                raise ctx.fail(prim, "focalLength", f"needs a positive focal length and aperture, got {focal}, "
                                                    f"{aperture}")
            fov = math.degrees(2.0 * math.atan(aperture / 2.0 / focal))
        return CameraComponent(
            fov,
            read_float(ctx, prim, "gandalf:near", float(clip[0])),
            read_float(ctx, prim, "gandalf:far", float(clip[1]), allow_inf=True),
            projection=str(projection),
            height=read_float(ctx, prim, "gandalf:height", aperture / 10.0),
            aspect=read_float(ctx, prim, "gandalf:aspect", None),
            primary=read(ctx, prim, "gandalf:primary", "bool", True),
            reverse_z=read(ctx, prim, "gandalf:reverseZ", "bool", False),
        )

    def light(self, prim: Usd.Prim) -> LightComponent | None:
        ctx = self.ctx
        kind = read(ctx, prim, "gandalf:lightKind", "string", LIGHT_KINDS.get(str(prim.GetTypeName())))
        if kind is None:
            return None

        def build() -> LightComponent:
            if authored(prim, "gandalf:lightColor"):
                color = read_floats(ctx, prim, "gandalf:lightColor", ("double3",), 3)
            else:  # another tool's light: the standard (linear) colour
                color = linear_to_srgb(read_floats(ctx, prim, "inputs:color", ("color3f",), 3, np.ones(3)))
            if authored(prim, "gandalf:intensity"):
                intensity = read_float(ctx, prim, "gandalf:intensity")
            else:
                intensity = read_float(ctx, prim, "inputs:intensity", 1.0)
            return LightComponent(
                kind, color, intensity, read_float(ctx, prim, "gandalf:range", 0.0),
                cast_shadows=read(ctx, prim, "gandalf:castShadows", "bool", False),
                shadow_extent=read_float(ctx, prim, "gandalf:shadowExtent", 10.0),
                shadow_depth=read_float(ctx, prim, "gandalf:shadowDepth", 50.0),
                shadow_bias=read_float(ctx, prim, "gandalf:shadowBias", 1.0),
            )

        return self.guard(prim, "gandalf:lightKind", build)

    def registered(self, prim: Usd.Prim) -> list[Component]:
        ctx = self.ctx
        out = []
        for name in read(ctx, prim, "gandalf:components", "string[]", []):
            reg = registration_named(name)
            if reg is None:
                detail = (f"unknown component '{name}': register its class with "
                          "gandalf_core.usd.register_component before loading")
                if self.strict:
                    raise ctx.fail(prim, "gandalf:components", detail)
                warnings.warn(str(ctx.fail(prim, "gandalf:components", detail + "; left out")), USDSceneWarning,
                              stacklevel=4)
                continue
            component = reg.cls()
            for field in reg.fields:
                attr = f"gandalf:{name}:{field}"
                value = self.field_value(prim, attr, getattr(component, field, None))
                self.guard(prim, attr, lambda: setattr(component, field, value))  # noqa: B023 (called at once)
            out.append(component)
        return out

    def field_value(self, prim: Usd.Prim, attr: str, template: Any) -> Any:
        """A registered field's saved value, converted to the type of the field's default value."""
        ctx = self.ctx
        if isinstance(template, (bool, np.bool_)):
            return bool(read(ctx, prim, attr, "bool"))
        if isinstance(template, (int, np.integer)):
            return int(read(ctx, prim, attr, "int64"))
        if isinstance(template, (float, np.floating)):
            if str(prim.GetAttribute(attr).GetTypeName()) == "int64":  # a float field that held an int
                return float(read(ctx, prim, attr, "int64"))
            return read_float(ctx, prim, attr)
        if isinstance(template, str):
            return str(read(ctx, prim, attr, "string"))
        if isinstance(template, (list, tuple, np.ndarray)):
            values = read_floats(ctx, prim, attr, ("double[]",), len(template))
            return values if isinstance(template, np.ndarray) else type(template)(values.tolist())
        value = read(ctx, prim, attr, ("bool", "int64", "double", "string", "double[]"))
        return tuple(value) if str(prim.GetAttribute(attr).GetTypeName()) == "double[]" else value

    def read_root_components(self, scene: Scene, root: Usd.Prim) -> None:
        ctx = self.ctx
        for attr, build in (
            ("gandalf:clearColor", lambda: ClearColorComponent(read_floats(ctx, root, "gandalf:clearColor",
                                                                           ("double4",), 4))),
            ("gandalf:skybox", lambda: SkyboxComponent(read(ctx, root, "gandalf:skybox", "string"))),
        ):
            if not root.GetAttribute(attr).HasAuthoredValue():
                continue
            rel = root.GetRelationship(attr + "Entity")
            targets = rel.GetTargets() if rel else []
            entity = self.entity_of.get(str(targets[0])) if len(targets) == 1 else None
            if entity is None:
                raise ctx.fail(root, attr + "Entity", "must name exactly one entity prim under the scene root")
            prim = self.stage.GetPrimAtPath(targets[0])
            self.add(scene, entity, prim, self.guard(root, attr, build))
