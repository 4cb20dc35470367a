"""Other tools' USD read right: float and half xform ops (``quatf`` orient, ``float3`` translate and scale) give
pxr's own ``ComputeLocalToWorldTransform`` to 1e-9; Z-up stages and ``metersPerUnit`` != 1 come into the engine's
Y-up metres; UsdLux lights keep their power: ``intensity · 2^exposure``, a ``SphereLight``'s size (or
``normalize``) and the inverse square, checked as pictures against lights of the same power in both APIs; a
``DistantLight``'s radiance over its angle (or, normalised, its intensity) is the directional light's irradiance,
a ``DomeLight``'s radiance the ambient light's, from a hand-written file.
The files are built with pxr in a temporary folder."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

pxr = pytest.importorskip("pxr")
from pxr import Gf, Usd, UsdGeom, UsdLux  # noqa: E402

from gandalf_core import Application, Scene  # noqa: E402
from gandalf_core.components import InfoComponent, LightComponent, TransformComponent  # noqa: E402
from gandalf_core.systems import TransformSystem  # noqa: E402
from step07_advanced.usd import load_scene  # noqa: E402

W, H = 64, 48


def new_stage(path: Path, up=UsdGeom.Tokens.y, metres: float = 1.0) -> Usd.Stage:
    stage = Usd.Stage.CreateNew(str(path))
    UsdGeom.SetStageUpAxis(stage, up)
    UsdGeom.SetStageMetersPerUnit(stage, metres)
    stage.SetDefaultPrim(UsdGeom.Xform.Define(stage, "/World").GetPrim())
    return stage


def exporter_ops(stage: Usd.Stage, orient: Gf.Quatf | None = None) -> None:
    """What many exporters write: translate/orient/scale in floats, two deep, under a double-precision parent.

    The child's ``quatf`` is exactly unit (0.5s): pxr builds its matrix from the quaternion as stored, without
    normalising, so only an exactly unit one lets the comparison hold to 1e-9 (see the rounded case below)."""
    parent = UsdGeom.Xform.Define(stage, "/World/parent")
    parent.AddTranslateOp().Set(Gf.Vec3d(1.5, -2.0, 0.25))
    parent.AddOrientOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Quatd(0.8, 0.2, 0.5, 0.1).GetNormalized())
    parent.AddScaleOp().Set(Gf.Vec3d(2.0, 2.0, 2.0))
    child = UsdGeom.Xform.Define(stage, "/World/parent/child")
    child.AddTranslateOp(UsdGeom.XformOp.PrecisionFloat).Set(Gf.Vec3f(0.1, 0.7, -3.3))
    child.AddOrientOp(UsdGeom.XformOp.PrecisionFloat).Set(orient or Gf.Quatf(0.5, Gf.Vec3f(0.5, -0.5, 0.5)))
    child.AddScaleOp(UsdGeom.XformOp.PrecisionFloat).Set(Gf.Vec3f(0.5, 1.25, 3.0))
    leaf = UsdGeom.Xform.Define(stage, "/World/parent/child/leaf")
    leaf.AddTranslateOp(UsdGeom.XformOp.PrecisionHalf).Set(Gf.Vec3h(0.5, 0.25, 2.0))
    leaf.AddOrientOp(UsdGeom.XformOp.PrecisionHalf).Set(Gf.Quath(1.0, 0.0, 0.0, 0.0))
    leaf.AddScaleOp(UsdGeom.XformOp.PrecisionFloat).Set(Gf.Vec3f(1.0, 1.0, 0.75))


def engine_worlds(scene: Scene) -> dict[str, np.ndarray]:
    scene.add_system(TransformSystem())
    scene.update(0.0)
    return {scene.get_component(e, InfoComponent).name: t.world.copy() for e, (t,) in scene.view(TransformComponent)}


def pxr_world(stage: Usd.Stage, path: str) -> np.ndarray:
    """pxr's world matrix in the engine's column-vector convention."""
    xf = UsdGeom.Xformable(stage.GetPrimAtPath(path))
    return np.array(xf.ComputeLocalToWorldTransform(Usd.TimeCode.Default()), dtype=np.float64).T


def to_engine(up: str, metres: float) -> np.ndarray:
    """The stage-to-engine matrix: metres per unit, and -90° about X for a Z-up stage."""
    c = np.eye(4)
    if up == UsdGeom.Tokens.z:
        c[:3, :3] = [[1, 0, 0], [0, 0, 1], [0, -1, 0]]
    c[:3, :3] *= metres
    return c


@pytest.mark.parametrize(("up", "metres"), [(UsdGeom.Tokens.y, 1.0), (UsdGeom.Tokens.z, 1.0),
                                            (UsdGeom.Tokens.y, 0.01), (UsdGeom.Tokens.z, 0.0254)])
def test_float_ops_up_axis_and_units_match_pxr(tmp_path, up, metres):
    path = tmp_path / "exported.usda"
    stage = new_stage(path, up, metres)
    exporter_ops(stage)
    stage.GetRootLayer().Save()
    worlds = engine_worlds(load_scene(path))
    for name in ("parent", "child", "leaf"):
        prim = {"parent": "/World/parent", "child": "/World/parent/child", "leaf": "/World/parent/child/leaf"}[name]
        expected = to_engine(up, metres) @ pxr_world(stage, prim)
        got = worlds[name]
        error = np.abs(got - expected).max() / max(1.0, np.abs(expected).max())
        assert error < 1e-9, f"{name} ({up}-up, {metres} m/unit): engine world differs from pxr's by {error:.2e}\n" \
                             f"got\n{got}\nexpected\n{expected}"


def test_a_rounded_quatf_agrees_to_float_precision(tmp_path):
    """A unit quaternion rounded to float (|q|² = 1 ± 1e-7) is a rotation for the engine (normalised, float64); pxr
    uses it unnormalised, so the two agree to float32's precision, not to 1e-9."""
    path = tmp_path / "rounded.usda"
    stage = new_stage(path)
    q = Gf.Quatf(0.3, Gf.Vec3f(-0.4, 0.7, 0.2)).GetNormalized()
    exporter_ops(stage, q)
    stage.GetRootLayer().Save()
    norm = math.sqrt(q.GetReal() ** 2 + sum(float(c) ** 2 for c in q.GetImaginary()))
    assert norm != 1.0, "the rounded quaternion is not exactly unit (else this case tests nothing new)"
    got, expected = engine_worlds(load_scene(path))["child"], pxr_world(stage, "/World/parent/child")
    assert np.abs(got - expected).max() / np.abs(expected).max() < 4e-7


def test_a_z_up_point_lands_where_y_up_puts_it(tmp_path):
    """A marker 2 units up a Z-up stage in centimetres is 0.02 m up the engine's Y."""
    path = tmp_path / "zup.usda"
    stage = new_stage(path, UsdGeom.Tokens.z, 0.01)
    UsdGeom.Xform.Define(stage, "/World/marker").AddTranslateOp().Set(Gf.Vec3d(0.0, 0.0, 2.0))
    stage.GetRootLayer().Save()
    np.testing.assert_allclose(engine_worlds(load_scene(path))["marker"][:3, 3], (0.0, 0.02, 0.0), atol=1e-15)


# --- light power ------------------------------------------------------------------------------------------
def lit_file(path: Path, *, intensity: float, radius: float = 0.1, exposure: float = 0.0, normalize: bool = False,
             metres: float = 1.0) -> Path:
    """A grey floor lit by one SphereLight 2 m above it, seen by a camera (lengths in metres, written in the
    stage's units)."""
    stage = new_stage(path, metres=metres)
    u = 1.0 / metres
    floor = UsdGeom.Mesh.Define(stage, "/World/floor")
    floor.CreatePointsAttr([(-3 * u, 0, -3 * u), (3 * u, 0, -3 * u), (3 * u, 0, 3 * u), (-3 * u, 0, 3 * u)])
    floor.CreateFaceVertexCountsAttr([4])
    floor.CreateFaceVertexIndicesAttr([0, 3, 2, 1])
    floor.CreateDisplayColorAttr([(0.5, 0.5, 0.5)])
    floor.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    camera = UsdGeom.Camera.Define(stage, "/World/camera")
    camera.AddTranslateOp().Set(Gf.Vec3d(0.0, 3.0 * u, 4.0 * u))
    camera.AddRotateXOp().Set(-35.0)
    camera.CreateClippingRangeAttr(Gf.Vec2f(0.1 * u, 100.0 * u))
    light = UsdLux.SphereLight.Define(stage, "/World/bulb")
    light.AddTranslateOp().Set(Gf.Vec3d(0.0, 2.0 * u, 0.0))
    light.CreateIntensityAttr(intensity)
    light.CreateRadiusAttr(radius * u)
    light.CreateExposureAttr(exposure)
    if normalize:
        light.CreateNormalizeAttr(True)
    stage.GetRootLayer().Save()
    return path


def picture(scene: Scene, backend: str) -> np.ndarray:
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        app.add_scene(scene)
        app.run(frames=1)
        return app.capture()[..., :3].astype(np.int64)


def bulb(scene: Scene) -> LightComponent:
    return next(light for _, (light,) in scene.view(LightComponent))


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_lights_of_equal_power_draw_the_same_picture(tmp_path, backend):
    """Intensity 30 from a sphere of radius 0.1 m has the power of 7.5 from 0.2 m, of 15 with exposure 1, of 30 in
    centimetres, and of a normalised light of intensity 30·π·0.1²·4; each draws the reference point light's
    picture (intensity π·30·0.1², the inverse square), which is lit but not washed out."""
    reference_power = math.pi * 30.0 * 0.1 ** 2
    files = {
        "reference": lit_file(tmp_path / "a.usda", intensity=30.0, radius=0.1),
        "twice-the-radius": lit_file(tmp_path / "b.usda", intensity=7.5, radius=0.2),
        "exposure": lit_file(tmp_path / "c.usda", intensity=15.0, radius=0.1, exposure=1.0),
        "centimetres": lit_file(tmp_path / "d.usda", intensity=30.0, radius=0.1, metres=0.01),
        "normalised": lit_file(tmp_path / "e.usda", intensity=4.0 * reference_power, radius=0.7, normalize=True),
    }
    scenes = {name: load_scene(path) for name, path in files.items()}
    for name, scene in scenes.items():
        assert bulb(scene).intensity == pytest.approx(reference_power, rel=1e-6), name
    # The reference light built by hand: the engine's point light of that power, and the same range.
    by_hand = load_scene(files["reference"])
    light = bulb(by_hand)
    light.intensity, light.range = reference_power, math.sqrt(512.0 * reference_power)
    expected = picture(by_hand, backend)
    lit = expected.mean()
    assert 20.0 < lit < 200.0, f"the floor is lit but not washed out (mean {lit:.1f})"
    for name, scene in scenes.items():
        got = picture(scene, backend)
        assert np.abs(got - expected).max() <= 1, f"{name}: differs from the reference light by " \
                                                  f"{np.abs(got - expected).max()}"
    # Ten times the power is brighter: the test can fail.
    brighter = load_scene(lit_file(tmp_path / "f.usda", intensity=300.0, radius=0.1))
    assert picture(brighter, backend).mean() > lit + 10.0


# --- distant and dome lights ------------------------------------------------------------------------------
#: A file as another tool writes it, by hand: UsdLux's radiance (intensity · 2^exposure) over a disc of the
#: light's angle, or the irradiance itself when normalised, and a dome of uniform radiance.
HAND_WRITTEN_LIGHTS = """#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Y"
)

def Xform "World"
{
    def DistantLight "sun"
    {
    }

    def DistantLight "lux"
    {
        float inputs:angle = 10
        float inputs:exposure = 1
        float inputs:intensity = 2
        bool inputs:normalize = 1
    }

    def DistantLight "wide"
    {
        float inputs:angle = 60
        float inputs:intensity = 3
    }

    def DistantLight "parallel"
    {
        float inputs:angle = 0
        float inputs:intensity = 1.5
    }

    def DistantLight "beyond_a_hemisphere"
    {
        float inputs:angle = 270
        float inputs:intensity = 1
        bool inputs:normalize = 1
    }

    def DomeLight "sky"
    {
        float inputs:exposure = 2
        float inputs:intensity = 0.25
        bool inputs:normalize = 1
    }
}
"""


def lights_by_name(scene: Scene) -> dict[str, LightComponent]:
    return {scene.get_component(e, InfoComponent).name: light for e, (light,) in scene.view(LightComponent)}


def test_distant_and_dome_lights_follow_usdlux_units(tmp_path):
    path = tmp_path / "lights.usda"
    path.write_text(HAND_WRITTEN_LIGHTS)
    lights = lights_by_name(load_scene(path))
    disc = lambda degrees: math.pi * math.sin(math.radians(degrees) / 2) ** 2  # noqa: E731 - cos-weighted solid angle
    expected = {
        "sun": 50000.0 * disc(0.53),  # UsdLux's fallback sun: 50000 nits over 0.53°, about 3.4 lux
        "lux": 2.0 * 2.0,  # normalised: the intensity (times 2^exposure) is the irradiance, whatever the angle
        "wide": 3.0 * disc(60.0),  # 3 nits over a disc 60° across: 3·π/4
        "parallel": 1.5,  # angle 0: a parallel light, its intensity is the irradiance
        "beyond_a_hemisphere": 1.0 * math.pi / ((2.0 - 0.5) * math.pi),  # θ = 135°: sin² = 1/2, facing a hemisphere
        "sky": 0.25 * 4.0,  # the surround's radiance; normalize does not apply to a dome
    }
    assert set(lights) == set(expected)
    for name, value in expected.items():
        assert lights[name].intensity == pytest.approx(value, rel=1e-6), (name, lights[name].intensity, value)
    assert lights["sky"].kind == "ambient" and lights["sun"].kind == "directional"


def sun_file(path: Path, **inputs: float) -> Path:
    """A grey floor under one DistantLight straight above it, with ``inputs`` (angle, intensity, exposure,
    normalize), seen by a camera."""
    lines = "\n".join(f"        {'bool' if k == 'normalize' else 'float'} inputs:{k} = {v}" for k, v in inputs.items())
    path.write_text(f"""#usda 1.0
(
    defaultPrim = "World"
    upAxis = "Y"
)

def Xform "World"
{{
    def Mesh "floor"
    {{
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 3, 2, 1]
        point3f[] points = [(-3, 0, -3), (3, 0, -3), (3, 0, 3), (-3, 0, 3)]
        color3f[] primvars:displayColor = [(0.5, 0.5, 0.5)]
        uniform token subdivisionScheme = "none"
    }}

    def Camera "camera"
    {{
        float2 clippingRange = (0.1, 100)
        double3 xformOp:translate = (0, 3, 4)
        float xformOp:rotateX = -35
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateX"]
    }}

    def DistantLight "sun"
    {{
{lines}
        float xformOp:rotateX = -90
        uniform token[] xformOpOrder = ["xformOp:rotateX"]
    }}
}}
""")
    return path


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_distant_lights_of_equal_irradiance_draw_the_same_picture(tmp_path, backend):
    """Irradiance 0.6 as a normalised sun of 20°, as 0.3 with exposure 1, and as the radiance 0.6 / (π·sin²10°)
    over a 20° disc unnormalised: each draws the picture of the engine's directional light of intensity 0.6."""
    irradiance = 0.6
    files = {
        "normalised": sun_file(tmp_path / "a.usda", angle=20, intensity=irradiance, normalize=1),
        "exposure": sun_file(tmp_path / "b.usda", angle=20, intensity=irradiance / 2, exposure=1, normalize=1),
        "radiance": sun_file(tmp_path / "c.usda", angle=20,
                             intensity=irradiance / (math.pi * math.sin(math.radians(10.0)) ** 2)),
    }
    scenes = {name: load_scene(path) for name, path in files.items()}
    by_hand = load_scene(files["normalised"])
    bulb(by_hand).intensity = irradiance
    expected = picture(by_hand, backend)
    assert 20.0 < expected.mean() < 200.0, f"the floor is lit but not washed out (mean {expected.mean():.1f})"
    for name, scene in scenes.items():
        assert bulb(scene).intensity == pytest.approx(irradiance, rel=1e-5), name
        got = picture(scene, backend)
        assert np.abs(got - expected).max() <= 1, f"{name}: differs by {np.abs(got - expected).max()}"
    # The radiance taken as the irradiance (the old reading) is far brighter: the test can fail.
    misread = load_scene(files["radiance"])
    bulb(misread).intensity = irradiance / (math.pi * math.sin(math.radians(10.0)) ** 2)
    assert picture(misread, backend).mean() > expected.mean() + 10.0


def test_lights_written_for_other_tools_read_back_by_their_usdlux_inputs_alone(tmp_path):
    """The engine writes UsdLux inputs that mean its own lights: read back without the gandalf:* attributes,
    each light has its intensity again."""
    from step07_advanced.usd import save_scene

    scene = Scene("lights")
    for name, kind, intensity in (("sun", "directional", 0.7), ("bulb", "point", 2.5), ("sky", "ambient", 0.3)):
        scene.create_entity(InfoComponent(name), TransformComponent((0.0, 1.0, 0.0)), LightComponent(kind,
                                                                                                      intensity=intensity))
    path = save_scene(scene, tmp_path / "out.usda", assets=False)
    stage = Usd.Stage.Open(str(path))
    for prim in stage.Traverse():
        for attribute in prim.GetAttributes():
            if attribute.GetName() in ("gandalf:intensity", "gandalf:lightColor", "gandalf:range"):
                prim.RemoveProperty(attribute.GetName())
    stage.GetRootLayer().Save()
    lights = lights_by_name(load_scene(path))
    assert {name: light.intensity for name, light in lights.items()} == pytest.approx(
        {"sun": 0.7, "bulb": 2.5, "sky": 0.3}, rel=1e-6)


def test_a_textured_dome_says_its_texture_is_not_read(tmp_path):
    from step07_advanced.usd import USDSceneWarning

    path = tmp_path / "dome.usda"
    path.write_text('#usda 1.0\n(\n    defaultPrim = "World"\n)\n\ndef Xform "World"\n{\n'
                    '    def DomeLight "sky"\n    {\n        asset inputs:texture:file = @sky.exr@\n'
                    '        float inputs:intensity = 0.5\n    }\n}\n')
    with pytest.warns(USDSceneWarning, match=r"</World/sky>: a DomeLight's texture is not read"):
        scene = load_scene(path)
    assert lights_by_name(scene)["sky"].intensity == pytest.approx(0.5)
