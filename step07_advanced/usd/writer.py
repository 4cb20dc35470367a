"""Saving a Scene as a USD stage (see :mod:`step07_advanced.usd.mapping` for the layout)."""

from __future__ import annotations

import math
import os
import uuid
import warnings
from pathlib import Path

import numpy as np
from pxr import Gf, Sdf, Usd, UsdGeom, UsdLux, UsdShade

from gandalf_core import components as core
from gandalf_core.ecs import Scene, System
from gandalf_core.resources import CubeTextureData, srgb_to_linear

from . import assets as asset_prims
from .atomic import StagedFiles
from .attributes import simple_value, write
from .errors import USDSceneError, USDSceneWarning
from .mapping import (
    ASSETS,
    BUILTIN_TYPES,
    DEFAULT_ASPECT,
    ENTITY_MESH,
    ENTITY_MESH_MARK,
    EXTENSIONS,
    FORMAT_VERSION,
    LIGHT_TYPES,
    MATERIALS,
    MESHES,
    ROOT,
    SYSTEMS,
    TEXTURES,
    VERTICAL_APERTURE_MM,
    texture_folder_name,
)
from .names import UniqueNames
from .registry import class_key, function_key, registration_for, system_registration_for

T = Sdf.ValueTypeNames


def file_format(path: Path) -> str:
    """'usda' or 'usdc' from the file extension; USDSceneError for anything else."""
    fmt = EXTENSIONS.get(path.suffix.lower())
    if fmt is None:
        raise USDSceneError(path, f"unsupported extension {path.suffix!r}: use .usda (text) or .usdc (binary)")
    return fmt


def save_scene(scene: Scene, path: str | Path, *, assets: bool = True) -> Path:
    """Write ``scene`` to ``path`` (.usda text or .usdc binary, chosen by the extension); return the file written.

    With ``assets=True`` every texture is written as PNG into ``<stem>_<ext>_textures/`` next to the file and
    referenced by a relative path; ``assets=False`` leaves textures out (meshes and materials are always
    saved). All files are written to temporary files and moved into place only when everything succeeded, so a
    failed save leaves the previous files as they were. Saving through a symbolic link writes its target (the
    link stays a link; the textures go next to the target). Components without a USD mapping are reported in one
    :class:`USDSceneWarning`. Raises :class:`USDSceneError` naming the file (and entity/field) on failure.
    """
    given = Path(path)
    file_format(given)
    path = Path(os.path.realpath(given)) if given.is_symlink() else given
    if not path.parent.is_dir():
        raise USDSceneError(path, f"the folder {str(path.parent)!r} does not exist")
    # --8<-- [start:staged]
    stage = Usd.Stage.CreateInMemory()
    writer = _Writer(scene, stage, path, assets)
    writer.write()
    try:
        with StagedFiles() as staged:
            for target, pixels in writer.images:
                _write_png(pixels, staged.temp_for(target))
            temp = staged.temp_for(path)
            if not stage.GetRootLayer().Export(str(temp)):
                raise OSError(f"USD could not write {temp}")
            staged.commit()
    except USDSceneError:
        raise
    except Exception as exc:  # OSError, or a Tf.ErrorException from USD's writer
        raise USDSceneError(path, f"cannot write the file: {exc}") from exc
    return path
    # --8<-- [end:staged]


def _write_png(pixels: np.ndarray, path: Path) -> None:
    from PIL import Image

    Image.fromarray(np.ascontiguousarray(pixels), mode="RGBA").save(path, format="PNG")


class _Writer:
    def __init__(self, scene: Scene, stage: Usd.Stage, path: Path, assets: bool) -> None:
        self.scene = scene
        self.stage = stage
        self.path = path
        self.assets = assets
        self.images: list[tuple[Path, np.ndarray]] = []
        self.mesh_paths: dict[str, str] = {}
        self.material_paths: dict[str, str] = {}
        self.unsaved: list[str] = []
        self.prim_of: dict[uuid.UUID, str] = {}

    def fail(self, entity: uuid.UUID, detail: str, prim: str | None = None) -> USDSceneError:
        return USDSceneError(self.path, f"{self.scene.describe(entity)}: {detail}", prim=prim)

    # --- whole scene --------------------------------------------------------------------------------
    def write(self) -> None:
        self.check_systems()  # before anything else: a scene that cannot be saved says why at once
        stage = self.stage
        UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
        UsdGeom.SetStageMetersPerUnit(stage, 1.0)
        root = UsdGeom.Xform.Define(stage, ROOT).GetPrim()
        stage.SetDefaultPrim(root)
        write(root, "gandalf:sceneName", T.String, self.scene.name)
        write(root, "gandalf:version", T.Int, FORMAT_VERSION)
        self.write_assets()
        names: dict[str, UniqueNames] = {}
        for entity in self.ordered_entities():
            if _editor_owned(self.scene, entity):
                continue  # the editor's panels are part of the tool, not of the scene
            parent = self.scene.parent_of(entity)
            parent_path = self.prim_of[parent] if parent is not None else ROOT
            scope = names.setdefault(parent_path, UniqueNames(reserved=(ENTITY_MESH,)))
            info = self.scene.try_component(entity, core.InfoComponent)
            prim_path = f"{parent_path}/{scope.take(info.name if info else 'entity')}"
            self.prim_of[entity] = prim_path
            self.write_entity(entity, prim_path, root)
        # After every entity prim exists: a field may name another entity.
        for entity, prim_path in self.prim_of.items():
            self.write_registered(entity, self.stage.GetPrimAtPath(prim_path))
        self.write_systems()
        if self.unsaved:
            warnings.warn(
                f"{self.path}: parts with no USD mapping were not saved (a step declares them in its saved.py, "
                f"a program registers them with step07_advanced.usd.register_component / register_system): "
                f"{'; '.join(self.unsaved)}",
                USDSceneWarning,
                stacklevel=3,
            )

    def ordered_entities(self) -> list[uuid.UUID]:
        """Every entity, parents before children (roots in scene order, children in Link order)."""
        scene = self.scene
        order = [e for e in scene.entities if scene.parent_of(e) is None]
        for entity in order:  # grows while iterating: a breadth-first walk without recursion
            link = scene.try_component(entity, core.LinkComponent)
            if link is not None:
                order.extend(link.children)
        return order

    def write_assets(self) -> None:
        stage, scene = self.stage, self.scene
        UsdGeom.Scope.Define(stage, ASSETS).MakeInvisible()  # asset meshes are data; entities reference them
        # Textures first: a material's preview network names its first texture's file.
        texture_prims: list[tuple[str, str, object, list[str]]] = []
        texture_file: dict[str, tuple[str, bool]] = {}
        if self.assets:
            unique = UniqueNames()
            folder_name = texture_folder_name(self.path)
            for name, texture in scene.assets.textures.items():
                stem = unique.take(name, "texture")
                files = asset_prims.texture_files(stem, texture)
                relative = [f"./{folder_name}/{f}" for f in files]
                texture_prims.append((stem, name, texture, relative))
                if not isinstance(texture, CubeTextureData):
                    texture_file[name] = (relative[0], bool(texture.srgb))
                for f, pixels in zip(files, asset_prims.texture_images(texture)):
                    self.images.append((self.path.parent / folder_name / f, pixels))

        def material(stage_: Usd.Stage, path: str, name: str, data: object) -> None:
            first = texture_file.get(data.textures[0]) if data.textures else None
            asset_prims.write_material(stage_, path, name, data, first)

        for folder, table, write_one, paths in (
            (MESHES, scene.assets.meshes, asset_prims.write_mesh, self.mesh_paths),
            (MATERIALS, scene.assets.materials, material, self.material_paths),
        ):
            UsdGeom.Scope.Define(stage, folder)
            unique = UniqueNames()
            for name, data in table.items():
                paths[name] = f"{folder}/{unique.take(name, 'asset')}"
                try:
                    write_one(stage, paths[name], name, data)
                except (ValueError, TypeError) as exc:
                    raise USDSceneError(self.path, str(exc), prim=paths[name]) from exc
        if not self.assets:
            return
        UsdGeom.Scope.Define(stage, TEXTURES)
        for stem, name, texture, relative in texture_prims:
            asset_prims.write_texture(stage, f"{TEXTURES}/{stem}", name, texture, relative)

    # --- one entity ---------------------------------------------------------------------------------
    def write_entity(self, entity: uuid.UUID, path: str, root: Usd.Prim) -> None:
        comps = {type(c): c for c in self.scene.components_of(entity)}
        camera, light = comps.get(core.CameraComponent), comps.get(core.LightComponent)
        type_name = "Camera" if camera else LIGHT_TYPES[light.kind] if light else "Xform"
        prim = self.stage.DefinePrim(path, type_name)
        info = comps.get(core.InfoComponent)
        if info is not None:
            write(prim, "gandalf:name", T.String, info.name)
            write(prim, "gandalf:tag", T.String, info.tag)
        if core.LinkComponent in comps:
            write(prim, "gandalf:link", T.Bool, True)
        if core.TransformComponent in comps:
            transform = comps[core.TransformComponent]
            for field in ("translation", "quaternion", "scale"):
                # A field's live view can hold NaN, or a zero quaternion: refuse what the reader would refuse.
                value = getattr(transform, field)
                if not np.isfinite(value).all() or (field == "quaternion" and not np.any(value)):
                    raise USDSceneError(self.path, f"{self.scene.describe(entity)}: TransformComponent.{field} "
                                                   f"cannot be saved: {value.tolist()}", prim=path)
            self.write_transform(prim, transform)
        if camera is not None:
            self.write_camera(prim, camera)
        if light is not None:
            self.write_light(prim, light, schema=type_name != "Camera")
        mesh_prim = None
        if core.MeshComponent in comps:
            name = comps[core.MeshComponent].mesh
            write(prim, "gandalf:mesh", T.String, name)
            if name in self.mesh_paths:
                prim.CreateRelationship("gandalf:meshAsset", custom=True).SetTargets([self.mesh_paths[name]])
                # The visible geometry: a Mesh child that references the asset (its data is stored once).
                mesh_prim = self.stage.DefinePrim(f"{path}/{ENTITY_MESH}", "Mesh")
                mesh_prim.GetReferences().AddInternalReference(self.mesh_paths[name])
                write(mesh_prim, ENTITY_MESH_MARK, T.Bool, True)
        if core.MaterialComponent in comps:
            name = comps[core.MaterialComponent].material
            write(prim, "gandalf:material", T.String, name)
            if name in self.material_paths and mesh_prim is not None:  # the standard binding, on the geometry
                material = UsdShade.Material(self.stage.GetPrimAtPath(self.material_paths[name]))
                UsdShade.MaterialBindingAPI.Apply(mesh_prim).Bind(material)
        for component_type, attr, type_name_, value in (
            (core.ClearColorComponent, "gandalf:clearColor", T.Double4, lambda c: Gf.Vec4d(*map(float, c.color))),
            (core.SkyboxComponent, "gandalf:skybox", T.String, lambda c: c.texture),
        ):
            if component_type in comps:
                rel = root.GetRelationship(attr + "Entity")
                if rel:
                    extra = f"{component_type.__name__} (a scene saves only the first)"
                    self.unsaved.append(f"{self.scene.describe(entity)}: {extra}")
                    continue
                write(root, attr, type_name_, value(comps[component_type]))
                root.CreateRelationship(attr + "Entity", custom=True).SetTargets([path])

    # --8<-- [start:transform]
    def write_transform(self, prim: Usd.Prim, t: core.TransformComponent) -> None:
        xform = UsdGeom.Xformable(prim)
        w, x, y, z = (float(v) for v in t.quaternion)  # gandalf stores (w, x, y, z); Gf.Quatd takes real first
        xform.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*map(float, t.translation)))
        xform.AddOrientOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Quatd(w, Gf.Vec3d(x, y, z)))
        xform.AddScaleOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*map(float, t.scale)))
    # --8<-- [end:transform]

    def write_camera(self, prim: Usd.Prim, c: core.CameraComponent) -> None:
        usd = UsdGeom.Camera(prim)
        aspect = DEFAULT_ASPECT if c.aspect is None else c.aspect
        usd.CreateProjectionAttr(c.projection)
        usd.CreateClippingRangeAttr(Gf.Vec2f(c.near, c.far))
        if c.projection == "orthographic":
            # USD gives orthographic apertures in tenths of a scene unit.
            usd.CreateVerticalApertureAttr(c.height * 10.0)
            usd.CreateHorizontalApertureAttr(c.height * 10.0 * aspect)
        else:
            usd.CreateVerticalApertureAttr(VERTICAL_APERTURE_MM)
            usd.CreateHorizontalApertureAttr(VERTICAL_APERTURE_MM * aspect)
            usd.CreateFocalLengthAttr(VERTICAL_APERTURE_MM / (2.0 * math.tan(math.radians(c.fov) / 2.0)))
        # USD's float attributes would round these; the exact values travel as doubles.
        for name, value in (("fov", c.fov), ("near", c.near), ("far", c.far), ("height", c.height)):
            write(prim, f"gandalf:{name}", T.Double, float(value))
        if c.aspect is not None:
            write(prim, "gandalf:aspect", T.Double, float(c.aspect))
        write(prim, "gandalf:primary", T.Bool, bool(c.primary))
        write(prim, "gandalf:reverseZ", T.Bool, bool(c.reverse_z))

    # --8<-- [start:light]
    def write_light(self, prim: Usd.Prim, light: core.LightComponent, schema: bool) -> None:
        if schema:  # the standard UsdLux inputs (linear colour), for other USD tools (units: usd/units.py)
            api = UsdLux.LightAPI(prim)
            api.CreateColorAttr(Gf.Vec3f(*map(float, srgb_to_linear(light.color))))
            # Normalised, a DistantLight's intensity is the irradiance it gives (the engine's directional
            # intensity) and a point SphereLight's is its power / π, 4 x the engine's (power / 4π).
            api.CreateIntensityAttr(4.0 * light.intensity if light.kind == "point" else light.intensity)
            if light.kind != "ambient":
                api.CreateNormalizeAttr(True)
            if light.kind == "point":
                UsdLux.SphereLight(prim).CreateTreatAsPointAttr(True)
        write(prim, "gandalf:lightKind", T.String, light.kind)
        write(prim, "gandalf:lightColor", T.Double3, Gf.Vec3d(*map(float, light.color)))
        write(prim, "gandalf:intensity", T.Double, light.intensity)
        write(prim, "gandalf:range", T.Double, light.range)
        write(prim, "gandalf:castShadows", T.Bool, bool(light.cast_shadows))
        write(prim, "gandalf:shadowExtent", T.Double, light.shadow_extent)
        write(prim, "gandalf:shadowDepth", T.Double, light.shadow_depth)
        write(prim, "gandalf:shadowBias", T.Double, light.shadow_bias)
    # --8<-- [end:light]

    def write_registered(self, entity: uuid.UUID, prim: Usd.Prim) -> None:
        saved: list[str] = []
        names: dict[str, str] = {}
        for component in self.scene.components_of(entity):
            component_type = type(component)
            if component_type in BUILTIN_TYPES:
                continue
            reg = registration_for(component_type)
            if reg is None:
                self.unsaved.append(f"{self.scene.describe(entity)}: {component_type.__name__}")
                continue
            name = component_type.__name__
            if name in names:  # the attributes are named by the class name: two such classes would mix
                raise self.fail(entity, f"two registered components are both called {name} ({names[name]} and "
                                        f"{reg.key}): rename one", str(prim.GetPath()))
            names[name] = reg.key
            for field in reg.fields:
                self.write_field(entity, prim, f"gandalf:{name}:{field}", f"{name}.{field}",
                                 getattr(component, field, _MISSING))
            saved.append(reg.key)
        if saved:
            write(prim, "gandalf:components", T.StringArray, saved)

    def write_field(self, entity: uuid.UUID, prim: Usd.Prim, attr: str, label: str, value: object) -> None:
        if value is _MISSING:
            raise self.fail(entity, f"{label}: the component has no such attribute", str(prim.GetPath()))
        if value is None:  # an optional field left unset: nothing is written, the loader keeps the default
            return
        if isinstance(value, uuid.UUID):  # another entity: a relationship to its prim
            if value not in self.prim_of:
                raise self.fail(entity, f"{label}: names entity {value}, which is not saved", str(prim.GetPath()))
            prim.CreateRelationship(attr, custom=True).SetTargets([self.prim_of[value]])
            return
        try:
            type_name, usd_value = simple_value(value)
        except (TypeError, ValueError) as exc:
            raise self.fail(entity, f"{label}: {exc}", str(prim.GetPath())) from None
        write(prim, attr, type_name, usd_value)

    # --- systems --------------------------------------------------------------------------------------
    def check_systems(self) -> None:
        for system in self.scene.systems:
            reg = None if _tool_owned(system) else system_registration_for(type(system))
            if reg is not None and reg.unsaveable is not None:
                raise USDSceneError(self.path, f"scene '{self.scene.name}': system {type(system).__name__} "
                                               f"({reg.key}) cannot be saved: {reg.unsaveable}")

    def write_systems(self) -> None:
        """Every system the scene's own code added, in update order; the app's and the editor's are left out."""
        systems = [s for s in self.scene.systems if not _tool_owned(s)]
        if not systems:
            return
        UsdGeom.Scope.Define(self.stage, SYSTEMS)
        unique = UniqueNames()
        for system in systems:
            name = type(system).__name__
            reg = system_registration_for(type(system))
            if reg is None:
                self.unsaved.append(f"system {name} ({class_key(type(system))}; register it with "
                                    "step07_advanced.usd.register_system)")
                continue
            path = f"{SYSTEMS}/{unique.take(name, 'system')}"
            prim = UsdGeom.Scope.Define(self.stage, path).GetPrim()
            write(prim, "gandalf:system", T.String, reg.key)
            write(prim, "gandalf:enabled", T.Bool, bool(system.enabled))
            for setting in reg.settings:
                value = getattr(system, setting, _MISSING)
                label = f"system {name}: setting '{setting}'"
                if value is _MISSING:
                    raise USDSceneError(self.path, f"{label}: the system has no attribute of that name", prim=path)
                if callable(value) and not isinstance(value, type):
                    key = function_key(value)
                    if key is None:
                        raise USDSceneError(self.path, f"{label}: the function {value!r} is not registered "
                                                       "(step07_advanced.usd.register_function)", prim=path)
                    write(prim, f"gandalf:functions:{setting}", T.String, key)
                    continue
                try:
                    type_name, usd_value = simple_value(value)
                except (TypeError, ValueError) as exc:
                    raise USDSceneError(self.path, f"{label}: {exc}", prim=path) from None
                write(prim, f"gandalf:settings:{setting}", type_name, usd_value)


_MISSING = object()


# --8<-- [start:tool_owned]
def _tool_owned(system: System) -> bool:
    """The render system (the app adds it) and an editor's panels are parts of the tool, not of the scene."""
    return not type(system).saved


def _editor_owned(scene: Scene, entity: uuid.UUID) -> bool:
    """An entity that holds a tool's own component (an editor panel) is not part of the scene."""
    return any(not type(c).saved for c in scene.components_of(entity))
# --8<-- [end:tool_owned]
