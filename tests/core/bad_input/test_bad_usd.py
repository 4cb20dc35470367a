"""USD scenes: missing, malformed and wrongly named files; prims the engine cannot map (warned, listed by path and why);
other tools' meshes that are double-sided (drawn with a copy of their material that culls nothing) or given only as
time samples, a sphere's radius or a light's intensity too (read at the first sample, listed); references, payloads
and sublayers outside the scene's folder (refused unless ``allow_outside``) or missing (an error naming the layer);
attributes of the wrong type or with bad values (named by prim and attribute, and the component field); missing
texture files; duplicate asset names; saving through a symbolic link. Loading failures leave the open scene as it
was; saving failures leave the old file as it was."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

pxr = pytest.importorskip("pxr")
from pxr import Usd, UsdGeom, UsdLux  # noqa: E402

from gandalf_core import Scene  # noqa: E402
from gandalf_core.components import (  # noqa: E402
    CameraComponent,
    InfoComponent,
    LightComponent,
    MaterialComponent,
    MeshComponent,
    TransformComponent,
)
from gandalf_core.resources import MaterialData, checkerboard, cube  # noqa: E402
from step07_advanced.usd import USDSceneError, USDSceneWarning, load_scene, save_scene  # noqa: E402

from .catalogue import error, params, quietly, result, run, warning  # noqa: E402


def scene() -> Scene:
    s = Scene("catalogue")
    s.assets.mesh("box", cube())
    s.assets.texture("checker", checkerboard(8, 2))
    s.assets.material("red", MaterialData("gandalf.unlit", ["checker"], color=(1, 0, 0)))
    s.assets.material("blue", MaterialData("gandalf.unlit", ["checker"], color=(0, 0, 1)))
    s.create_entity(InfoComponent("crate"), TransformComponent(), MeshComponent("box"), MaterialComponent("red"))
    s.create_entity(InfoComponent("camera"), TransformComponent((0, 0, 5)), CameraComponent(50.0, 0.1, 100.0))
    s.create_entity(InfoComponent("bulb"), TransformComponent((0, 3, 0)), LightComponent("point", range=5.5))
    return s


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A saved scene (good.usda and its textures) and the foreign files the cases load, made once."""
    root = tmp_path_factory.mktemp("usd")
    save_scene(scene(), root / "good.usda")
    (root / "malformed.usda").write_text('#usda 1.0\ndef Xform "Scene" {\n  double x = "oops"\n}\n')
    (root / "garbage.usdc").write_bytes(b"\x00\x01 not usd")
    inside = root / "scene"
    inside.mkdir()
    part = Usd.Stage.CreateNew(str(root / "part.usda"))  # outside the folder of the scenes in scene/
    UsdGeom.Xform.Define(part, "/Part")
    part.SetDefaultPrim(part.GetPrimAtPath("/Part"))
    UsdGeom.Cube.Define(part, "/Part/box")
    part.GetRootLayer().Save()
    for name, edit in {
        "outside_reference": lambda st: st.DefinePrim("/World/ref").GetReferences().AddReference("../part.usda"),
        "outside_payload": lambda st: st.DefinePrim("/World/pay").GetPayloads().AddPayload("../part.usda"),
        "outside_sublayer": lambda st: st.GetRootLayer().subLayerPaths.append("../part.usda"),
        "missing_reference": lambda st: st.DefinePrim("/World/ref").GetReferences().AddReference("./gone.usda"),
        "missing_sublayer": lambda st: st.GetRootLayer().subLayerPaths.append("./nolayer.usda"),
        "unmapped": _unmapped,
        "clip_reversed": lambda st: UsdGeom.Camera.Define(st, "/World/cam").CreateClippingRangeAttr((10.0, 1.0)),
        "nan_points": _nan_points,
        "double_sided": _double_sided,
        "animated_mesh": _animated_mesh,
        "animated_ball": _animated_ball,
        "animated_sun": _animated_sun,
    }.items():
        stage = Usd.Stage.CreateNew(str(inside / f"{name}.usda"))
        UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
        stage.SetDefaultPrim(UsdGeom.Xform.Define(stage, "/World").GetPrim())
        edit(stage)
        stage.GetRootLayer().Save()
    return root


def _unmapped(stage: Usd.Stage) -> None:
    curves = UsdGeom.BasisCurves.Define(stage, "/World/hair")
    curves.CreatePointsAttr([(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 2, 0)])
    curves.CreateCurveVertexCountsAttr([4])
    UsdLux.RectLight.Define(stage, "/World/panel")
    UsdGeom.Sphere.Define(stage, "/World/ball")


def _nan_points(stage: Usd.Stage) -> None:
    mesh = UsdGeom.Mesh.Define(stage, "/World/tri")
    mesh.CreatePointsAttr([(0, 0, 0), (1, float("nan"), 0), (0, 1, 0)])
    mesh.CreateFaceVertexCountsAttr([3])
    mesh.CreateFaceVertexIndicesAttr([0, 1, 2])


def _triangle(stage: Usd.Stage, path: str) -> UsdGeom.Mesh:
    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr([(0, 0, 0), (1, 0, 0), (0, 1, 0)])
    mesh.CreateFaceVertexCountsAttr([3])
    mesh.CreateFaceVertexIndicesAttr([0, 1, 2])
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    return mesh


def _double_sided(stage: Usd.Stage) -> None:
    """Two grey triangles, one drawn from both sides (a leaf, a sheet of paper): they share the grey."""
    _triangle(stage, "/World/leaf").CreateDoubleSidedAttr(True)
    _triangle(stage, "/World/wall")


def _animated_mesh(stage: Usd.Stage) -> None:
    """A triangle whose points are time samples only (a mesh baked from a simulation): no default value."""
    mesh = _triangle(stage, "/World/flag")
    points = mesh.GetPointsAttr()
    points.Clear()
    points.Set([(0, 0, 0), (2, 0, 0), (0, 2, 0)], 1.0)
    points.Set([(0, 0, 0), (4, 0, 0), (0, 4, 0)], 10.0)


def _animated_ball(stage: Usd.Stage) -> None:
    """A sphere whose radius is time samples only: USD's fallback radius (1) is not its size."""
    radius = UsdGeom.Sphere.Define(stage, "/World/ball").GetRadiusAttr()
    radius.Set(3.0, 2.0)
    radius.Set(6.0, 8.0)


def _animated_sun(stage: Usd.Stage) -> None:
    """A normalised DistantLight whose intensity is time samples only: UsdLux's fallback (50000 lux) is not it."""
    sun = UsdLux.DistantLight.Define(stage, "/World/sun")
    sun.CreateNormalizeAttr(True)
    sun.CreateIntensityAttr().Set(3.0, 0.0)
    sun.GetIntensityAttr().Set(9.0, 5.0)


def light_intensity(loaded) -> float:
    return next(loaded.get_component(e, LightComponent).intensity for e in loaded.entities
                if loaded.has_component(e, LightComponent))


def culls(name: str):
    """The cull mode of the material the loaded entity ``name`` draws with."""
    def check(loaded):
        entity = next(e for e in loaded.entities if loaded.get_component(e, InfoComponent).name == name)
        return loaded.assets.materials[loaded.get_component(entity, MaterialComponent).material].cull
    return check


def extent(name: str):
    """The largest coordinate of the mesh the loaded entity ``name`` draws."""
    def check(loaded) -> float:
        entity = next(e for e in loaded.entities if loaded.get_component(e, InfoComponent).name == name)
        return float(loaded.assets.meshes[loaded.get_component(entity, MeshComponent).mesh].positions.max())
    return check


def float_ops(folder: Path) -> Path:
    """good.usda with every orient a quatf and every translate and scale a float3 (what many exporters write)."""
    path = edited("gandalf:sceneName", "gandalf:sceneName", "float_ops.usda")(folder)
    text = path.read_text()
    for old, new in (("quatd xformOp:orient", "quatf xformOp:orient"),
                     ("double3 xformOp:scale", "float3 xformOp:scale"),
                     ("double3 xformOp:translate", "float3 xformOp:translate")):
        assert old in text
        text = text.replace(old, new)
    path.write_text(text)
    return path


def corrupt_texture_file(folder: Path) -> Path:
    path = edited("gandalf:sceneName", "gandalf:sceneName", "bad_png.usda")(folder)
    (folder / "bad_png_usda_textures" / "checker.png").write_bytes(b"not a png")
    return path


def edited(old: str, new: str, name: str):
    """good.usda with one text edit, saved as ``name`` (with a copy of its textures folder)."""
    def make(folder: Path) -> Path:
        text = (folder / "good.usda").read_text()
        assert old in text, f"the saved file has no {old!r}"
        target = folder / name
        target.write_text(text.replace(old, new, 1).replace("good_usda_textures", f"{target.stem}_usda_textures"))
        textures = folder / f"{target.stem}_usda_textures"
        if not textures.exists():
            shutil.copytree(folder / "good_usda_textures", textures)
        return target
    return make


def calm(name: str):
    """Load ``scene/<name>.usda`` with its USDSceneWarning silenced (the warning has its own case)."""
    return quietly(loads(f"scene/{name}.usda"), USDSceneWarning)


def loads(make, **kwargs):
    """Load what ``make(folder)`` gives; an open scene must stay as it was when the load fails."""
    def action(folder: Path):
        path = make(folder) if callable(make) else folder / make
        open_scene = scene()
        before = [(e, [repr(c) for c in open_scene.components_of(e)]) for e in open_scene.entities]
        try:
            return load_scene(path, **kwargs)
        finally:
            after = [(e, [repr(c) for c in open_scene.components_of(e)]) for e in open_scene.entities]
            assert after == before, "a failed load changed the open scene"
    return action


def saves(name: str, **kwargs):
    def action(folder: Path):
        return save_scene(scene(), folder / name, **kwargs)
    return action


def missing_texture_file(folder: Path) -> Path:
    path = edited("gandalf:sceneName", "gandalf:sceneName", "no_texture.usda")(folder)
    (folder / "no_texture_usda_textures" / "checker.png").unlink()
    return path


def through_a_link(folder: Path):
    real, link = folder / "real.usda", folder / "link.usda"
    save_scene(Scene("old"), real, assets=False)
    link.symlink_to(real)
    save_scene(scene(), link, assets=False)
    return link.is_symlink(), "crate" in real.read_text()


CASES = [
    error("load-missing-file", loads("nope.usda"), USDSceneError, "nope.usda", "no such file"),
    error("load-malformed-text", loads("malformed.usda"), USDSceneError, "malformed.usda", "not a valid USD file"),
    error("load-garbage-binary", loads("garbage.usdc"), USDSceneError, "garbage.usdc", "not a valid USD file"),
    error("load-wrong-extension", loads("scene.json"), USDSceneError, "scene.json", "unsupported extension '.json'"),
    error("save-wrong-extension", saves("scene.obj"), USDSceneError, "scene.obj", "unsupported extension"),
    error("save-into-missing-folder", saves("no/such/folder/s.usda"), USDSceneError, "s.usda", "does not exist"),
    warning("unknown-prim-types-warned", loads("scene/unmapped.usda"), USDSceneWarning, "</World/hair>",
            "prim type 'BasisCurves'", "</World/panel>", "RectLight"),
    result("unknown-prims-still-entities", calm("unmapped"),
           lambda s: {"hair", "panel", "ball"} <= {s.get_component(e, InfoComponent).name for e in s.entities}),
    error("reference-outside-folder", loads("scene/outside_reference.usda"), USDSceneError, "outside_reference.usda",
          "@../part.usda@", "outside the scene's folder", "allow_outside"),
    error("payload-outside-folder", loads("scene/outside_payload.usda"), USDSceneError, "@../part.usda@",
          "outside the scene's folder"),
    error("sublayer-outside-folder", loads("scene/outside_sublayer.usda"), USDSceneError, "@../part.usda@",
          "outside the scene's folder"),
    result("outside-allowed-when-asked", loads("scene/outside_reference.usda", allow_outside=True),
           lambda s: "/World/ref/box" in s.assets.meshes),
    error("missing-reference", loads("scene/missing_reference.usda"), USDSceneError, "missing_reference.usda",
          "@./gone.usda@ is missing"),
    error("missing-sublayer", loads("scene/missing_sublayer.usda"), USDSceneError, "missing_sublayer.usda",
          "sublayer @./nolayer.usda@ is missing"),
    error("attribute-wrong-type", loads(edited("custom double gandalf:range = 5.5",
                                               'custom string gandalf:range = "far"', "range_type.usda")),
          USDSceneError, "range_type.usda", "prim </Scene/bulb>", "attribute 'gandalf:range'", "has type string"),
    error("attribute-wrong-arity", loads(edited("double3 xformOp:scale = (1, 1, 1)",
                                                "double2 xformOp:scale = (1, 1)", "scale_arity.usda")),
          USDSceneError, "scale_arity.usda", "attribute 'xformOp:scale'", "double2", "expected double3"),
    error("camera-fov-out-of-range", loads(edited("custom double gandalf:fov = 50",
                                                  "custom double gandalf:fov = -5", "fov.usda")),
          USDSceneError, "fov.usda", "prim </Scene/camera>", "attribute 'gandalf:fov'", "CameraComponent.fov"),
    error("light-kind-unknown", loads(edited('custom string gandalf:lightKind = "point"',
                                             'custom string gandalf:lightKind = "laser"', "laser.usda")),
          USDSceneError, "prim </Scene/bulb>", "attribute 'gandalf:lightKind'", "LightComponent.kind"),
    error("translation-nan", loads(edited("double3 xformOp:translate = (0, 3, 0)",
                                          "double3 xformOp:translate = (nan, 3, 0)", "nan.usda")),
          USDSceneError, "nan.usda", "prim </Scene/bulb>", "xformOp:translate"),
    error("camera-clipping-range-reversed", loads("scene/clip_reversed.usda"), USDSceneError, "</World/cam>",
          "attribute 'clippingRange'", "CameraComponent.far"),
    error("mesh-points-nan", calm("nan_points"), USDSceneError, "</World/tri>",
          "attribute 'points'", "nan"),
    error("mesh-index-out-of-range", loads(edited("int[] faceVertexIndices = [0, 1, 2,",
                                                  "int[] faceVertexIndices = [0, 1, 999,", "index.usda")),
          USDSceneError, "index.usda", "attribute 'faceVertexIndices'", "999"),
    error("texture-file-not-an-image", loads(corrupt_texture_file), USDSceneError, "prim </Assets/Textures/checker>",
          "attribute 'gandalf:files'"),
    result("float-xform-ops-accepted", loads(float_ops),
           lambda s: [float(s.get_component(e, TransformComponent).translation[1]) for e in s.entities
                      if s.get_component(e, InfoComponent).name == "bulb"] == [3.0]),
    error("missing-texture-file", loads(missing_texture_file), USDSceneError, "prim </Assets/Textures/checker>",
          "checker.png"),
    error("duplicate-asset-names", loads(edited('gandalf:name = "blue"', 'gandalf:name = "red"', "dup.usda")),
          USDSceneError, "dup.usda", "'red'", "two material prims"),
    result("double-sided-mesh-culls-nothing", calm("double_sided"),
           lambda s: culls("leaf")(s) == "none"),
    result("one-sided-mesh-still-culls-back", calm("double_sided"),
           lambda s: culls("wall")(s) == "back"),
    result("mesh-with-time-samples-only-drawn-at-its-first", calm("animated_mesh"),
           lambda s: extent("flag")(s) == 2.0),
    result("sphere-with-an-animated-radius-drawn-at-its-first", calm("animated_ball"),
           lambda s: abs(extent("ball")(s) - 3.0) < 1e-6),
    warning("sphere-with-an-animated-radius-warned", loads("scene/animated_ball.usda"), USDSceneWarning,
            "</World/ball>", "animated radius: the first time sample (time 2) is used"),
    result("light-with-an-animated-intensity-drawn-at-its-first", calm("animated_sun"),
           lambda s: abs(light_intensity(s) - 3.0) < 1e-9),
    warning("light-with-an-animated-intensity-warned", loads("scene/animated_sun.usda"), USDSceneWarning,
            "</World/sun>", "animated inputs:intensity: the first time sample (time 0)"),
    warning("mesh-with-time-samples-only-warned", loads("scene/animated_mesh.usda"), USDSceneWarning,
            "</World/flag>", "animated points: the first time sample (time 1) is used (no animation)"),
    result("save-through-a-symlink-writes-its-target", through_a_link,
           lambda value: value == (True, True)),
]


@pytest.mark.parametrize("case", params(CASES))
def test_usd(case, folder):
    run(case, folder)
