"""Loading a Scene from a USD file written by :func:`step07_advanced.usd.save_scene` (or a compatible one).

USD files hold data only: nothing in them is executed. The file is parsed into a private layer (never a
cached one, so a file rewritten since an earlier load is read afresh) and turned into a brand-new Scene;
a problem anywhere raises :class:`USDSceneError` before the caller sees any of it.
"""

from __future__ import annotations

import dataclasses
import math
import uuid
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
from pxr import Sdf, Usd, UsdGeom, UsdLux, UsdShade

from gandalf_core.components import (
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
from gandalf_core.ecs import Component, Scene
from gandalf_core.resources import MaterialData, ResourceError, TextureData, linear_to_srgb

from . import assets as asset_prims
from . import foreign, units
from .attributes import FileContext, authored, mesh_attribute, read, read_float, read_floats
from .errors import USDSceneError, USDSceneWarning
from .foreign import PreviewSurface, default_preview_material, inside
from .mapping import ASSETS, ENTITY_MESH_MARK, FORMAT_VERSION, LIGHT_KINDS, MATERIALS, MESHES, SYSTEMS, TEXTURES
from .registry import Registration, resolve_component, resolve_function, resolve_system
from .writer import file_format

_XFORM_OPS = ["xformOp:translate", "xformOp:orient", "xformOp:scale"]


def load_scene(path: str | Path, *, name: str | None = None, strict: bool = True, allow_outside: bool = False,
               preview_material: Callable[[PreviewSurface], MaterialData] | None = None) -> Scene:
    """Read a .usda/.usdc file into a NEW Scene (named ``name``, else the saved scene name or the file stem).

    Every problem (missing or unreadable file, wrong extension, a missing attribute or one of the wrong type,
    invalid component values, an unknown component, a missing sublayer, reference or payload) raises
    :class:`USDSceneError` naming the file, prim and attribute. Components of classes not registered with
    ``register_component`` are an error, or with ``strict=False`` a :class:`USDSceneWarning` and left out.

    Files from other tools load too (see :mod:`step07_advanced.usd.foreign`): every prim becomes an entity named
    after it, any xform op stack becomes its transform, plain meshes and gprims are converted, and bound
    ``UsdPreviewSurface`` materials become engine materials through ``preview_material`` (default:
    :func:`~step07_advanced.usd.foreign.default_preview_material`, the built-in ``gandalf.blinn_phong``).
    What cannot be mapped is listed, prim by prim, in ONE :class:`USDSceneWarning`. Sublayers, references,
    payloads and texture files must lie inside the file's folder unless ``allow_outside=True``.
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
    if layer.GetCompositionAssetDependencies():
        # Relative sublayers and references resolve against the layer's own file: open it by its path, read
        # afresh (Reload) when it or a layer it uses changed on disk since an earlier load.
        check_dependencies(path, allow_outside)
        layer = Sdf.Layer.FindOrOpen(str(path))
        layer.Reload()
    try:
        stage = Usd.Stage.Open(layer, Usd.Stage.LoadAll)
        for used in stage.GetUsedLayers():
            if not used.anonymous and used is not layer:
                used.Reload()
        errors = stage.GetCompositionErrors()
    except Exception as exc:
        raise USDSceneError(path, f"cannot open the USD stage: {str(exc).strip()}") from None
    if errors:
        raise USDSceneError(path, "composition errors: " + "; ".join(str(e).strip() for e in errors))
    return _Reader(ctx, stage, path, strict, allow_outside, preview_material).scene_named(name)


def check_dependencies(path: Path, allow_outside: bool) -> None:
    """Every sublayer, reference and payload (recursively) exists, and lies in ``path``'s folder unless allowed."""
    folder = path.parent.resolve()
    seen: set[Path] = set()
    todo = [path.resolve()]
    while todo:
        current = todo.pop()
        if current in seen:
            continue
        seen.add(current)
        try:
            layer = Sdf.Layer.OpenAsAnonymous(str(current))
        except Exception as exc:
            raise USDSceneError(path, f"layer {str(current)!r}: not a valid USD file: {_parser_message(exc)}") from None
        sublayers = set(layer.subLayerPaths)
        for dep in layer.GetCompositionAssetDependencies():
            if not dep:
                continue
            kind = "sublayer" if dep in sublayers else "reference or payload"
            target = Path(dep) if Path(dep).is_absolute() else current.parent / dep
            target = target.resolve()
            if not allow_outside and not inside(folder, target):
                raise USDSceneError(path, f"{current.name}: the {kind} @{dep}@ ({target}) lies outside the scene's "
                                          f"folder {folder}: refused (load_scene(..., allow_outside=True) allows it)")
            if not target.is_file():
                raise USDSceneError(path, f"{current.name}: the {kind} @{dep}@ is missing ({target})")
            todo.append(target)


def _parser_message(exc: Exception) -> str:
    """The parser's own words (with line and column) from a USD error, without its C++ source location."""
    last = str(exc).strip().split("Error in ")[-1]
    return last.split(" : ", 1)[-1].strip().strip("'").strip()


_SKIPPED_TYPES = ("Material", "Shader", "NodeGraph", "GeomSubset")  # shading data and subsets: not entities
_PLAIN_TYPES = ("", "Xform", "Scope", "Camera", "Mesh", *LIGHT_KINDS)


def _only_shading(prim: Usd.Prim) -> bool:
    """A Scope (such as ``Looks``) that holds nothing but materials: shading data, not an entity."""
    if str(prim.GetTypeName()) != "Scope" or not prim.GetChildren():
        return False
    return all(str(c.GetTypeName()) in _SKIPPED_TYPES or _only_shading(c) for c in prim.GetChildren())


class _Reader:
    def __init__(self, ctx: FileContext, stage: Usd.Stage, path: Path, strict: bool, allow_outside: bool = False,
                 preview_material: Callable[[PreviewSurface], MaterialData] | None = None) -> None:
        self.ctx = ctx
        self.stage = stage
        self.path = path
        self.strict = strict
        self.allow_outside = allow_outside
        self.preview_material = preview_material or default_preview_material
        self.entity_of: dict[str, uuid.UUID] = {}
        self.notes: foreign.Notes = []
        self.foreign = False
        self.scene: Scene | None = None
        self.foreign_materials: dict[str, tuple[str, str]] = {}  # material prim -> (engine name, st primvar)
        self._textures: dict[str, str] = {}
        self._cameras_seen = 0
        self._layer_assets: dict[str, object] = {}  # referenced gandalf files' assets, by layer
        self.system_prims: dict[int, Usd.Prim] = {}
        #: (rotation quaternion, metres per unit) taking the stage's up axis and unit to the engine's Y-up metres,
        #: applied to every root entity; None for a Y-up stage in metres (gandalf's own files).
        self.stage_to_engine = units.stage_frame(stage)

    def scene_named(self, name: str | None) -> Scene:
        ctx, stage = self.ctx, self.stage
        root = stage.GetDefaultPrim()
        self.foreign = not (root and authored(root, "gandalf:version"))
        if not self.foreign:
            version = read(ctx, root, "gandalf:version", "int", FORMAT_VERSION)
            if version > FORMAT_VERSION:
                raise ctx.fail(root, "gandalf:version",
                               f"format {version} is newer than this gandalf ({FORMAT_VERSION})")
            scene = Scene(name or read(ctx, root, "gandalf:sceneName", "string", self.path.stem))
            tops = list(root.GetChildren())
        else:  # another tool's file: every prim on the stage (outside gandalf's asset scope) is an entity
            scene = Scene(name or self.path.stem)
            foreign.pin_first_samples(stage, self.notes)
            tops = [p for p in stage.GetPseudoRoot().GetChildren() if str(p.GetPath()) not in (ASSETS, SYSTEMS)]
        self.scene = scene
        self.read_assets(scene)
        prims = []  # parents before children, in authored order; an entity's visible mesh prim is not an entity
        for top in tops:
            # Instance proxies too: the prims under an instanceable reference are part of the picture.
            it = iter(Usd.PrimRange(top, Usd.TraverseInstanceProxies(Usd.PrimDefaultPredicate)))
            for prim in it:
                if prim.IsA(UsdGeom.PointInstancer):
                    it.PruneChildren()  # its prototypes are drawn only through it
                    self.notes.append((str(prim.GetPath()), "a PointInstancer: its instances and prototypes are "
                                                            "not drawn"))
                    prims.append(prim)
                    continue
                if authored(prim, ENTITY_MESH_MARK) or str(prim.GetTypeName()) in _SKIPPED_TYPES or (
                        self.foreign and _only_shading(prim)):
                    it.PruneChildren()
                    if str(prim.GetTypeName()) == "GeomSubset" and UsdShade.MaterialBindingAPI(prim).GetDirectBinding(
                    ).GetMaterialPath():
                        self.notes.append((str(prim.GetPath()), "a material bound to a GeomSubset (per-face "
                                                                "materials) is not mapped: the mesh's own is used"))
                    continue
                prims.append(prim)
        for prim in prims:
            self.entity_of[str(prim.GetPath())] = scene.enroll_entity()
        for prim in prims:
            entity = self.entity_of[str(prim.GetPath())]
            for component in self.components(prim):
                self.add(scene, entity, prim, component)
        for prim in prims:
            entity = self.entity_of[str(prim.GetPath())]
            for component in self.registered(prim):
                self.add(scene, entity, prim, component)
        if not self.foreign:
            self.read_root_components(scene, root)
            for system in self.systems():
                try:
                    scene.add_system(system)
                except Exception as exc:  # noqa: BLE001 - a system's on_create hooks may fail on the loaded data
                    raise ctx.fail(self.system_prims[id(system)], "gandalf:system",
                                   f"adding {type(system).__name__} to the scene failed: {type(exc).__name__}: "
                                   f"{exc}") from None
        if self.notes:
            lines = "; ".join(f"<{p}>: {why}" for p, why in self.notes)
            warnings.warn(f"{self.path}: not everything could be mapped: {lines}", USDSceneWarning, stacklevel=4)
        return scene

    def add(self, scene: Scene, entity: uuid.UUID, prim: Usd.Prim, component: Component) -> None:
        try:
            scene.add_component(entity, component)
        except (ValueError, TypeError, KeyError) as exc:
            raise self.ctx.fail(prim, None, f"cannot add {type(component).__name__}: {exc}") from None

    # --- assets ---------------------------------------------------------------------------------------
    def read_assets(self, scene: Scene) -> None:
        for kind, folder, read_one, register in (
            ("mesh", MESHES, asset_prims.read_mesh, scene.assets.mesh),
            ("material", MATERIALS, asset_prims.read_material, scene.assets.material),
            ("texture", TEXTURES,
             lambda ctx, p: asset_prims.read_texture(ctx, p, self.path.parent, self.allow_outside),
             scene.assets.texture),
        ):
            parent = self.stage.GetPrimAtPath(folder)
            first: dict[str, str] = {}
            for prim in parent.GetChildren() if parent else ():
                name, data = read_one(self.ctx, prim)
                if name in first:  # one would silently replace the other
                    raise self.ctx.fail(prim, "gandalf:name", f"two {kind} prims are both named {name!r} (the other "
                                                              f"is <{first[name]}>)")
                first[name] = str(prim.GetPath())
                register(name, data)

    # --- components of one prim ---------------------------------------------------------------------
    def components(self, prim: Usd.Prim) -> list[Component]:
        ctx = self.ctx
        out: list[Component] = []
        name = read(ctx, prim, "gandalf:name", "string", None)
        if name is not None:
            out.append(InfoComponent(name, read(ctx, prim, "gandalf:tag", "string", "")))
        elif self.foreign or prim.IsA(UsdGeom.Gprim):  # another tool's prim: named after it
            out.append(InfoComponent(prim.GetName()))
        transform, resets = self.transform(prim)
        parent = prim.GetParent()
        parent_entity = None if resets else self.entity_of.get(str(parent.GetPath()))
        if parent_entity is None and transform is not None and self.stage_to_engine is not None:
            transform = units.to_engine_frame(transform, *self.stage_to_engine)  # a root: into Y-up metres
        if parent_entity is not None or read(ctx, prim, "gandalf:link", "bool", False):
            out.append(LinkComponent(parent_entity))
        if transform is not None:
            out.append(transform)
        if prim.GetTypeName() == "Camera":
            out.append(self.camera(prim))
        light = self.light(prim)
        if light is not None:
            out.append(light)
        elif prim.HasAPI(UsdLux.LightAPI) or prim.IsA(UsdLux.BoundableLightBase) or prim.IsA(
                UsdLux.NonboundableLightBase):
            self.notes.append((str(prim.GetPath()), f"a {prim.GetTypeName()} has no engine light: left out"))
        mesh = read(ctx, prim, "gandalf:mesh", "string", None)
        material = read(ctx, prim, "gandalf:material", "string", None)
        if (mesh is not None and mesh not in self.scene.assets.meshes) or (
                material is not None and material not in self.scene.assets.materials):
            # An entity of a gandalf file referenced into this one: its assets are in that file's /Assets.
            mesh, material = self.referenced_assets(prim, mesh, material)
        if mesh is not None:
            out.append(self.guard(prim, "gandalf:mesh", lambda: MeshComponent(mesh)))
        if material is not None:
            out.append(self.guard(prim, "gandalf:material", lambda: MaterialComponent(material)))
        if mesh is None and prim.IsA(UsdGeom.Gprim):
            out.extend(self.foreign_geometry(prim))
        elif mesh is None and self.foreign and str(prim.GetTypeName()) not in _PLAIN_TYPES and not prim.HasAPI(
                UsdLux.LightAPI) and not prim.IsA(UsdGeom.PointInstancer):
            self.notes.append((str(prim.GetPath()), f"prim type '{prim.GetTypeName()}' has no engine mapping: "
                                                    "loaded as an empty entity"))
        return out

    # --- other tools' geometry and materials ------------------------------------------------------------
    def foreign_geometry(self, prim: Usd.Prim) -> list[Component]:
        path = str(prim.GetPath())
        scene = self.scene
        imageable = UsdGeom.Imageable(prim)
        if imageable.ComputeVisibility() == UsdGeom.Tokens.invisible:
            self.notes.append((path, "invisible: not drawn"))
            return []
        purpose = imageable.ComputePurpose()
        if purpose in (UsdGeom.Tokens.guide, UsdGeom.Tokens.proxy):
            self.notes.append((path, f"purpose '{purpose}': not drawn"))
            return []
        material_prim, _ = UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial()
        material_name, st_name = self.foreign_material(material_prim) if material_prim else (None, "st")
        constant = None
        try:
            if prim.IsA(UsdGeom.Mesh):
                data, constant = foreign.mesh_from_usd(UsdGeom.Mesh(prim), st_name, self.notes)
            else:
                data = foreign.gprim_mesh(prim, self.notes)
                color = UsdGeom.Gprim(prim).GetDisplayColorPrimvar()
                if color and color.HasAuthoredValue() and len(color.ComputeFlattened() or []):
                    constant = np.array([*color.ComputeFlattened()[0], 1.0])
                if data is None:
                    self.notes.append((path, f"prim type '{prim.GetTypeName()}' is not drawn (no engine mapping)"))
        except ResourceError as exc:
            raise self.ctx.fail(prim, mesh_attribute(exc.field), exc.detail) from None
        if data is None:
            return []
        scene.assets.mesh(path, data)
        if material_name is None:
            material_name = self.display_color_material(constant)
        if UsdGeom.Gprim(prim).GetDoubleSidedAttr().Get():
            material_name = self.double_sided(material_name)
        return [MeshComponent(path), MaterialComponent(material_name)]

    def double_sided(self, name: str) -> str:
        """The material ``name`` for a gprim drawn from both sides (``doubleSided``): itself when it culls nothing,
        else its copy that does not cull (``<name> (double-sided)``), registered once beside it."""
        data = self.scene.assets.materials[name]
        if data.cull == "none":
            return name
        twin = f"{name} (double-sided)"
        if twin not in self.scene.assets.materials:
            self.scene.assets.material(twin, dataclasses.replace(data, cull="none"))
        return twin

    def referenced_assets(self, prim: Usd.Prim, mesh: str | None, material: str | None) -> tuple[str | None,
                                                                                                   str | None]:
        """The engine names of a referenced gandalf entity's mesh and material, read from its own file's /Assets.

        The assets are registered as ``<file relative to the scene folder>:<name>`` (textures too); names that
        the referenced file does not hold either are returned unchanged (the renderer will name them).
        """
        attr = prim.GetAttribute("gandalf:mesh" if mesh is not None else "gandalf:material")
        stack = attr.GetPropertyStack(Usd.TimeCode.Default())
        layer = stack[0].layer if stack else None
        if layer is None or layer.anonymous or not layer.realPath:
            return mesh, material
        source = Path(layer.realPath)
        if source.resolve() == self.path.resolve():
            return mesh, material
        assets = self._layer_assets.get(layer.identifier)
        if assets is None:
            reader = _Reader(FileContext(str(source)), Usd.Stage.Open(layer), source, self.strict,
                             self.allow_outside, self.preview_material)
            holder = Scene("referenced")
            reader.read_assets(holder)
            assets = self._layer_assets[layer.identifier] = holder.assets
        folder = self.path.parent.resolve()
        prefix = (source.resolve().relative_to(folder).as_posix() if inside(folder, source) else str(source)) + ":"
        table = self.scene.assets
        if mesh is not None and mesh in assets.meshes:
            if prefix + mesh not in table.meshes:
                table.mesh(prefix + mesh, assets.meshes[mesh])
            mesh = prefix + mesh
        if material is not None and material in assets.materials:
            data = assets.materials[material]
            for texture in data.textures:
                if texture in assets.textures and prefix + texture not in table.textures:
                    table.texture(prefix + texture, assets.textures[texture])
            if prefix + material not in table.materials:
                renamed = [prefix + t if t in assets.textures else t for t in data.textures]
                table.material(prefix + material, dataclasses.replace(data, textures=renamed))
            material = prefix + material
        return mesh, material

    def display_color_material(self, linear_rgba: np.ndarray | None) -> str:
        """A material for geometry with no bound material: its constant displayColor, else 18% grey."""
        rgba = np.array([0.18, 0.18, 0.18, 1.0]) if linear_rgba is None else np.asarray(linear_rgba, np.float64)
        srgb = (*map(float, linear_to_srgb(np.clip(rgba[:3], 0.0, 1.0))), float(rgba[3]))
        name = "displayColor(" + ", ".join(f"{c:.6g}" for c in srgb) + ")"
        if name not in self.scene.assets.materials:
            self.scene.assets.material(name, self.map_surface(PreviewSurface(name, srgb), name))
        return name

    def map_surface(self, surface: PreviewSurface, where: str) -> MaterialData:
        try:
            material = self.preview_material(surface)
        except ResourceError as exc:
            raise self.ctx.fail(where, exc.field, exc.detail) from None
        if not isinstance(material, MaterialData):
            raise self.ctx.fail(where, None, f"preview_material returned {type(material).__name__}, "
                                             "expected MaterialData")
        return material

    def foreign_material(self, material: UsdShade.Material) -> tuple[str, str]:
        path = str(material.GetPath())
        if path in self.foreign_materials:
            return self.foreign_materials[path]
        if authored(material.GetPrim(), "inputs:gandalf:shader"):  # a gandalf material, referenced in
            name, data = asset_prims.read_material(self.ctx, material.GetPrim())
            if all(t in self.scene.assets.textures for t in data.textures):  # else: through its preview network
                name = path if name in self.scene.assets.materials else name
                self.scene.assets.material(name, data)
                self.foreign_materials[path] = (name, "st")
                return name, "st"
        surface, st_name = foreign.preview_surface(material, self.foreign_texture, self.notes)
        self.scene.assets.material(path, self.map_surface(surface, path))
        self.foreign_materials[path] = (path, st_name)
        return path, st_name

    def foreign_texture(self, shader: UsdShade.Shader, _file: str) -> str | None:
        """Load a UsdUVTexture's file as an engine texture (named by its path in the scene's folder)."""
        where = str(shader.GetPath())
        asset = shader.GetInput("file").Get()
        folder = self.path.parent.resolve()
        if asset.resolvedPath:
            file = Path(asset.resolvedPath)
        else:
            file = Path(asset.path) if Path(asset.path).is_absolute() else self.path.parent / asset.path
        file = file.resolve()
        if not self.allow_outside and not inside(folder, file):
            raise self.ctx.fail(where, "inputs:file", f"the texture @{asset.path}@ ({file}) lies outside the scene's "
                                                      f"folder {folder}: refused (allow_outside=True allows it)")
        if not file.is_file():
            raise self.ctx.fail(where, "inputs:file", f"the texture @{asset.path}@ is missing ({file})")
        name = file.relative_to(folder).as_posix() if inside(folder, file) else str(file)
        space = shader.GetInput("sourceColorSpace").Get() if shader.GetInput("sourceColorSpace") else None
        wraps = {str(shader.GetInput(w).Get()) for w in ("wrapS", "wrapT") if shader.GetInput(w)
                 and shader.GetInput(w).Get() is not None}
        wrap = "clamp" if wraps == {"clamp"} else "mirror" if wraps == {"mirror"} else "repeat"
        if len(wraps) > 1 or wraps - {"clamp", "mirror", "repeat", "useMetadata"}:
            self.notes.append((where, f"wrap modes {sorted(wraps)}: 'repeat' is used"))
        key = f"{name}|{space}|{wrap}"
        if key not in self._textures:
            texture_name = name if name not in self.scene.assets.textures else key
            try:
                texture = TextureData.from_file(file, srgb=space != "raw", wrap=wrap, name=texture_name)
            except ResourceError as exc:
                raise self.ctx.fail(where, "inputs:file", exc.detail) from None
            except ValueError as exc:
                raise self.ctx.fail(where, "inputs:file", str(exc)) from None
            self.scene.assets.texture(texture_name, texture)
            self._textures[key] = texture_name
        return self._textures[key]

    def guard(self, prim: Usd.Prim, attribute: str, build: Any) -> Any:
        """``build()``, with a component constructor's ValueError/TypeError turned into a USDSceneError."""
        try:
            return build()
        except USDSceneError:
            raise
        except (ValueError, TypeError) as exc:
            raise self.ctx.fail(prim, attribute, str(exc)) from None

    def transform(self, prim: Usd.Prim) -> tuple[TransformComponent | None, bool]:
        """The prim's transform (None: it has none) and whether it resets its parents' transforms."""
        ctx = self.ctx
        order = read(ctx, prim, "xformOpOrder", "token[]", None)
        if order is None or len(order) == 0:
            if (self.foreign or prim.IsA(UsdGeom.Gprim)) and not authored(prim, "gandalf:name"):
                return TransformComponent(), False  # an identity, so children compose through it
            return None, False
        if list(order) != _XFORM_OPS:
            return self.any_transform(prim), UsdGeom.Xformable(prim).GetResetXformStack()
        # Doubles as gandalf writes them, or the floats (and halves) many exporters write: widened exactly.
        t = read_floats(ctx, prim, "xformOp:translate", ("double3", "float3", "half3"), 3)
        q = read(ctx, prim, "xformOp:orient", ("quatd", "quatf", "quath"))
        quat = np.array([q.GetReal(), *q.GetImaginary()], dtype=np.float64)  # USD real-first = gandalf (w, x, y, z)
        if not np.isfinite(quat).all() or float(quat @ quat) < 1e-24:
            raise ctx.fail(prim, "xformOp:orient", f"must be a finite, non-zero quaternion, got {quat.tolist()}")
        s = read_floats(ctx, prim, "xformOp:scale", ("double3", "float3", "half3"), 3)
        component = TransformComponent(t, scale=s)
        component.quaternion = quat  # exactly as saved (the constructor would renormalise)
        return component, False

    # --8<-- [start:any_transform]
    def any_transform(self, prim: Usd.Prim) -> TransformComponent:
        """Any xform op stack (rotations, matrix ops, pivots ...), composed by USD and split into T, R, S."""
        xformable = UsdGeom.Xformable(prim)
        if not xformable:
            raise self.ctx.fail(prim, "xformOpOrder", f"a {prim.GetTypeName()} prim cannot carry xform ops")
        try:
            matrix, _ = foreign.local_matrix(xformable, self.notes)
        except Exception as exc:  # an op of the wrong type, an op named in the order but missing
            raise self.ctx.fail(prim, "xformOpOrder", f"cannot compose the xform ops: {str(exc).strip()}") from None
        t, q, s, shear = foreign.decompose(matrix)
        if not (np.isfinite(t).all() and np.isfinite(q).all() and np.isfinite(s).all()):
            raise self.ctx.fail(prim, "xformOpOrder", "the composed transform is not finite")
        if shear > foreign.SHEAR_TOLERANCE:
            self.notes.append((str(prim.GetPath()), f"the transform has a shear (|R^T R - I| = {shear:.3g}) that "
                                                    "translation/rotation/scale cannot hold: the nearest rotation "
                                                    "is used"))
        component = TransformComponent(t, scale=s)
        component.quaternion = q
        return component
    # --8<-- [end:any_transform]

    def camera(self, prim: Usd.Prim) -> CameraComponent:
        ctx = self.ctx
        usd = UsdGeom.Camera(prim)
        projection = read(ctx, prim, "projection", "token", "perspective")
        clip = usd.GetClippingRangeAttr().Get()
        aperture = usd.GetVerticalApertureAttr().Get()
        # Files from other tools lack the exact gandalf: values; fall back to the standard camera attributes
        # (read only then: a gandalf file's own values must not depend on them).
        # Each field's source in this file, so an error names the attribute the file holds.
        source = {"fov": "gandalf:fov" if authored(prim, "gandalf:fov") else "focalLength",
                  "near": "gandalf:near" if authored(prim, "gandalf:near") else "clippingRange",
                  "far": "gandalf:far" if authored(prim, "gandalf:far") else "clippingRange",
                  "height": "gandalf:height" if authored(prim, "gandalf:height") else "verticalAperture",
                  "aspect": "gandalf:aspect", "projection": "projection", "primary": "gandalf:primary",
                  "reverse_z": "gandalf:reverseZ"}
        if authored(prim, "gandalf:fov"):
            fov = read_float(ctx, prim, "gandalf:fov")
        else:
            focal = usd.GetFocalLengthAttr().Get()
            if not (focal and focal > 0 and aperture and aperture > 0):
                raise ctx.fail(prim, "focalLength", f"needs a positive focal length and aperture, got {focal}, "
                                                    f"{aperture}")
            fov = math.degrees(2.0 * math.atan(aperture / 2.0 / focal))
        values = dict(
            fov=fov,
            near=read_float(ctx, prim, "gandalf:near", float(clip[0])),
            far=read_float(ctx, prim, "gandalf:far", float(clip[1]), allow_inf=True),
            projection=str(projection),
            height=read_float(ctx, prim, "gandalf:height", aperture / 10.0),
            aspect=read_float(ctx, prim, "gandalf:aspect", None),
            # Another tool's file: its first camera is the primary one.
            primary=read(ctx, prim, "gandalf:primary", "bool", self._first_camera()),
            reverse_z=read(ctx, prim, "gandalf:reverseZ", "bool", False),
        )
        try:
            return CameraComponent(**values)
        except (ValueError, TypeError) as exc:
            # The first field the message names (a far below near names both: CameraComponent.far first).
            message = str(exc)
            named = sorted((message.find(f"CameraComponent.{f}"), f) for f in source
                           if f"CameraComponent.{f}" in message)
            attribute = source[named[0][1]] if named else "projection"
            raise ctx.fail(prim, attribute, message) from None

    def _first_camera(self) -> bool:
        first = not self._cameras_seen
        self._cameras_seen += 1
        return first

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
            light_range = read_float(ctx, prim, "gandalf:range", 0.0)
            if authored(prim, "gandalf:intensity"):
                intensity = read_float(ctx, prim, "gandalf:intensity")
            else:  # another tool's light: its power, and a range where it has faded below what 8 bits show
                fallback = units.schema_fallback(prim, "inputs:intensity", 1.0)  # a DistantLight's: 50000
                intensity, light_range = units.lux_intensity(
                    prim, read_float(ctx, prim, "inputs:intensity", fallback),
                    read_float(ctx, prim, "inputs:exposure", 0.0),
                    self.stage_to_engine[1] if self.stage_to_engine else 1.0, self.notes)
                if authored(prim, "gandalf:range"):
                    light_range = read_float(ctx, prim, "gandalf:range")
            return LightComponent(
                kind, color, intensity, light_range,
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
            reg, why = resolve_component(name)
            if reg is None:
                detail = (f"unknown component '{name}' ({why}): register its class with "
                          "step07_advanced.usd.register_component")
                if self.strict:
                    raise ctx.fail(prim, "gandalf:components", detail)
                warnings.warn(str(ctx.fail(prim, "gandalf:components", detail + "; left out")), USDSceneWarning,
                              stacklevel=4)
                continue
            out.append(self.guard(prim, "gandalf:components", lambda: self.component(prim, reg)))  # noqa: B023
        return out

    def component(self, prim: Usd.Prim, reg: Registration) -> Component:
        """A registered component: ``cls()`` (else ``cls(**constructor fields)``) with each saved field assigned."""
        name = reg.cls.__name__
        component = reg.cls() if reg.default_constructible else None
        values = {}
        for field in reg.fields:
            attr = f"gandalf:{name}:{field}"
            values[field] = self.field_value(prim, attr, getattr(component, field, None))
        if component is None:
            component = reg.cls(**{f: values[f] for f in reg.constructor_fields})
        for field, value in values.items():  # exactly as saved (a constructor may normalise or derive)
            self.guard(prim, f"gandalf:{name}:{field}", lambda: setattr(component, field, value))  # noqa: B023
        return component

    def field_value(self, prim: Usd.Prim, attr: str, template: Any) -> Any:
        """A registered field's saved value, converted to the type of the field's default value."""
        ctx = self.ctx
        rel = prim.GetRelationship(attr)
        if template is None and not rel and not authored(prim, attr):  # an optional field saved unset
            return None
        if rel and not prim.GetAttribute(attr):  # another entity
            targets = rel.GetTargets()
            entity = self.entity_of.get(str(targets[0])) if len(targets) == 1 else None
            if entity is None:
                raise ctx.fail(prim, attr, f"must name one entity prim of this scene, got {[str(t) for t in targets]}")
            return entity
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
        return self.plain_value(prim, attr)

    def plain_value(self, prim: Usd.Prim, attr: str) -> Any:
        """A saved value typed by its USD type alone (bool, int, float, str, or a float array as numpy)."""
        value = read(self.ctx, prim, attr, ("bool", "int64", "double", "string", "double[]"))
        if str(prim.GetAttribute(attr).GetTypeName()) == "double[]":
            return read_floats(self.ctx, prim, attr, ("double[]",), None)
        return value

    # --- systems ------------------------------------------------------------------------------------
    def systems(self) -> list[Any]:
        """The saved systems, in update order, built from the allow-list only (see :mod:`.registry`)."""
        ctx = self.ctx
        holder = self.stage.GetPrimAtPath(SYSTEMS)
        out = []
        for prim in holder.GetChildren() if holder else ():
            key = read(ctx, prim, "gandalf:system", "string")
            reg, why = resolve_system(key)
            if reg is not None and reg.unsaveable is not None:
                reg, why = None, f"it cannot be loaded: {reg.unsaveable}"
            if reg is None:
                detail = f"system '{key}' is not allowed ({why})"
                if self.strict:
                    raise ctx.fail(prim, "gandalf:system", detail)
                warnings.warn(str(ctx.fail(prim, "gandalf:system", detail + "; left out")), USDSceneWarning,
                              stacklevel=4)
                continue
            settings: dict[str, Any] = {}
            for prop in prim.GetAuthoredAttributes():
                attr = prop.GetName()
                for prefix in ("gandalf:settings:", "gandalf:functions:"):
                    if not attr.startswith(prefix):
                        continue
                    setting = attr[len(prefix):]
                    if setting not in reg.settings:
                        raise ctx.fail(prim, attr, f"{reg.cls.__name__} declares no setting '{setting}' (its "
                                                   f"settings: {list(reg.settings) or 'none'})")
                    if prefix == "gandalf:functions:":
                        name = read(ctx, prim, attr, "string")
                        fn, why = resolve_function(name)
                        if fn is None:
                            raise ctx.fail(prim, attr, f"function '{name}' is not allowed ({why})")
                        settings[setting] = fn
                    else:
                        settings[setting] = self.plain_value(prim, attr)
            missing = [s for s in reg.settings if s not in settings]
            if missing:
                raise ctx.fail(prim, None, f"{reg.cls.__name__}: settings {missing} are missing")
            try:
                system = reg.cls(**settings)
            except Exception as exc:  # noqa: BLE001 - any failure of the constructor names the prim
                raise ctx.fail(prim, "gandalf:system", f"{reg.cls.__name__}(**{settings}) failed: "
                                                       f"{type(exc).__name__}: {exc}") from None
            system.enabled = bool(read(ctx, prim, "gandalf:enabled", "bool", True))
            self.system_prims[id(system)] = prim
            out.append(system)
        return out

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
