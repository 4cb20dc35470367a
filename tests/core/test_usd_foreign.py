"""USD from other tools: scenes written with plain ``pxr`` (no gandalf attributes) load, and render right.

Tolerances: world matrices composed from any xform op stack match USD's own ``ComputeLocalToWorldTransform``
within 1e-9; tessellated gprims fill USD's extent within 1e-6 (cube, cylinder, cone, capsule, plane) or the
tessellation's chord error (sphere: 0.5 % of the radius); the pxr-built scene and the same scene built by
hand with the engine render the same picture in each API with PSNR >= 40 dB (96x72).
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from core_shaders import render_scene

from gandalf_core import Application, InfoComponent, LinkComponent, Scene, TransformComponent, TransformSystem
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent
from gandalf_core.math import quat_from_axis_angle, quat_mul
from gandalf_core.resources import MaterialData, MeshData, TextureData, checkerboard, cube, linear_to_srgb, uv_sphere
from gandalf_tools.testing import psnr
from step07_advanced.usd import USDSceneError, USDSceneWarning, load_scene
from step07_advanced.usd.foreign import PreviewSurface, decompose

pxr = pytest.importorskip("pxr")
from pxr import Gf, Sdf, Usd, UsdGeom, UsdLux, UsdShade, Vt  # noqa: E402

W, H = 96, 72
T = Sdf.ValueTypeNames


def test_preview_material(surface: PreviewSurface) -> MaterialData:
    """The test shaders: ``unlit`` (colour x texture) for textured surfaces, ``lit`` (Lambert) otherwise."""
    if surface.texture is not None:
        return MaterialData("unlit", [surface.texture], color=surface.color)
    return MaterialData("lit", color=surface.color)


test_preview_material.__test__ = False  # not a test


def load(path: Path, **kwargs) -> Scene:
    return load_scene(path, preview_material=test_preview_material, **kwargs)


def new_stage(path: Path) -> Usd.Stage:
    stage = Usd.Stage.CreateNew(str(path))
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    return stage


def names(scene: Scene) -> dict[str, object]:
    return {scene.get_component(e, InfoComponent).name: e for e in scene.entities}


def worlds(scene: Scene) -> dict[str, np.ndarray]:
    system = TransformSystem()
    scene.add_system(system)
    system.on_update_system(0.0)
    return {scene.get_component(e, InfoComponent).name: t.world.copy() for e, (t,) in scene.view(TransformComponent)}


# --- transforms -----------------------------------------------------------------------------------------
def op_stacks(stage: Usd.Stage) -> None:
    """Ordinary xform op stacks of DCC tools, nested two deep."""
    a = UsdGeom.Xform.Define(stage, "/World/a")
    a.AddTranslateOp().Set(Gf.Vec3d(1.0, -2.0, 0.5))
    a.AddRotateXYZOp().Set(Gf.Vec3f(10.0, 200.0, -35.0))
    a.AddScaleOp().Set(Gf.Vec3f(1.5, 0.5, 2.0))
    b = UsdGeom.Xform.Define(stage, "/World/a/b")
    b.AddRotateZYXOp().Set(Gf.Vec3f(30.0, -60.0, 15.0))
    b.AddTranslateOp(opSuffix="offset").Set(Gf.Vec3d(0.0, 3.0, 0.0))
    c = UsdGeom.Xform.Define(stage, "/World/c")
    c.AddRotateYOp().Set(90.0)
    c.AddRotateXOp().Set(-45.0)
    c.AddRotateZOp().Set(12.0)
    d = UsdGeom.Xform.Define(stage, "/World/d")  # Maya's pivot stack: translate, pivot, rotate, scale, inverse
    d.AddTranslateOp().Set(Gf.Vec3d(-1, 0, 2))
    pivot = d.AddTranslateOp(opSuffix="pivot")
    pivot.Set(Gf.Vec3d(0.5, 1.0, -0.25))
    d.AddRotateYXZOp().Set(Gf.Vec3f(5, 50, 70))
    d.AddScaleOp().Set(Gf.Vec3f(2, 2, 2))
    d.AddTranslateOp(opSuffix="pivot", isInverseOp=True)
    e = UsdGeom.Xform.Define(stage, "/World/d/e")
    matrix = Gf.Matrix4d().SetRotate(Gf.Rotation(Gf.Vec3d(1, 1, 0), 33.0)) * Gf.Matrix4d().SetTranslate((3, 2, 1))
    e.AddTransformOp().Set(Gf.Matrix4d().SetScale(Gf.Vec3d(0.5, 1.0, 3.0)) * matrix)
    f = UsdGeom.Xform.Define(stage, "/World/f")
    f.AddOrientOp(UsdGeom.XformOp.PrecisionFloat).Set(Gf.Quatf(0.8, Gf.Vec3f(0.0, 0.6, 0.0)))
    f.AddScaleOp().Set(Gf.Vec3f(-1.0, 1.0, 1.0))  # a mirror
    f.AddRotateXYZOp(opSuffix="twist").Set(Gf.Vec3f(0, 0, 90))


def test_any_xform_op_stack_gives_usds_world_matrix(tmp_path):
    stage = new_stage(tmp_path / "ops.usda")
    op_stacks(stage)
    stage.GetRootLayer().Save()
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no shear here: nothing to report
        scene = load(tmp_path / "ops.usda")
    engine = worlds(scene)
    for name in ("a", "b", "c", "d", "e", "f"):
        prim = next(p for p in stage.Traverse() if p.GetName() == name)
        usd = np.array(UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(Usd.TimeCode.Default())).T
        np.testing.assert_allclose(engine[name], usd, rtol=0, atol=1e-9,
                                   err_msg=f"{prim.GetPath()}: {UsdGeom.Xformable(prim).GetXformOpOrderAttr().Get()}")


def test_decompose_recovers_trs_and_measures_shear():
    rng = np.random.default_rng(5)
    for _ in range(50):
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        t, s = rng.uniform(-5, 5, 3), rng.uniform(0.1, 3, 3) * rng.choice([-1, 1], 3)
        component = TransformComponent(t, scale=s)
        component.quaternion = q
        matrix = component.local_matrix() if hasattr(component, "local_matrix") else None
        if matrix is None:
            scene = Scene("one")
            scene.create_entity(InfoComponent("x"), component)
            matrix = worlds(scene)["x"]
        t2, q2, s2, shear = decompose(matrix.T)
        rebuilt = TransformComponent(t2, scale=s2)
        rebuilt.quaternion = q2
        scene = Scene("two")
        scene.create_entity(InfoComponent("x"), rebuilt)
        np.testing.assert_allclose(worlds(scene)["x"], matrix, atol=1e-9)
        assert shear < 1e-9
    sheared = np.eye(4)
    sheared[1, 0] = 0.5  # row-vector USD matrix: y gains 0.5 x
    assert decompose(sheared)[3] > 0.1


def test_a_shear_is_listed_in_the_warning(tmp_path):
    stage = new_stage(tmp_path / "shear.usda")
    x = UsdGeom.Xform.Define(stage, "/World/sheared")
    x.AddTransformOp().Set(Gf.Matrix4d(1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1))
    stage.GetRootLayer().Save()
    with pytest.warns(USDSceneWarning, match=r"</World/sheared>: the transform has a shear"):
        scene = load(tmp_path / "shear.usda")
    assert "sheared" in names(scene)


# --- meshes ---------------------------------------------------------------------------------------------
HEX = [(math.cos(a), math.sin(a), 0.0) for a in np.linspace(0, 2 * math.pi, 7)[:-1]]


def hexagon(stage: Usd.Stage, path: str, st_interpolation: str | None) -> UsdGeom.Mesh:
    """A flat hexagon (one 6-gon) facing +Z, no normals, with ``st`` in the given interpolation."""
    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr(HEX)
    mesh.CreateFaceVertexCountsAttr([6])
    mesh.CreateFaceVertexIndicesAttr([0, 1, 2, 3, 4, 5])
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    st = [(0.5 + 0.5 * x, 0.5 + 0.5 * y) for x, y, _ in HEX]
    api = UsdGeom.PrimvarsAPI(mesh)
    if st_interpolation == "vertex":
        api.CreatePrimvar("st", T.TexCoord2fArray, UsdGeom.Tokens.vertex).Set(st)
    elif st_interpolation == "faceVarying":  # indexed, in reverse corner order through the indices
        pv = api.CreatePrimvar("st", T.TexCoord2fArray, UsdGeom.Tokens.faceVarying)
        pv.Set(st[::-1])
        pv.SetIndices(Vt.IntArray([5, 4, 3, 2, 1, 0]))
    elif st_interpolation == "constant":
        api.CreatePrimvar("st", T.TexCoord2fArray, UsdGeom.Tokens.constant).Set([(0.25, 0.75)])
    return mesh


@pytest.mark.parametrize("interpolation", ["vertex", "faceVarying", "constant", None])
def test_plain_ngon_mesh(tmp_path, interpolation):
    stage = new_stage(tmp_path / "m.usda")
    hexagon(stage, "/World/hex", interpolation)
    stage.GetRootLayer().Save()
    scene = load(tmp_path / "m.usda")
    data = scene.assets.meshes["/World/hex"]
    tris = data.triangles()
    assert len(tris) == 4, "a hexagon is 4 triangles"
    p = data.positions.astype(np.float64)
    cross = np.cross(p[tris[:, 1]] - p[tris[:, 0]], p[tris[:, 2]] - p[tris[:, 0]])
    assert np.all(cross[:, 2] > 0), "counter-clockwise (rightHanded) faces keep facing +Z"
    assert np.sum(np.linalg.norm(cross, axis=1)) / 2 == pytest.approx(3 * math.sqrt(3) / 2, rel=1e-6)
    np.testing.assert_allclose(data.normals, np.tile([0, 0, 1], (len(data.normals), 1)), atol=1e-6)
    if interpolation is None:
        assert data.uvs is None
        return
    expected = {tuple(np.round(q, 5)) for q in p[:, :2]}
    assert {tuple(np.round(q, 5)) for q in p[:, :2]} == expected
    if interpolation == "constant":
        np.testing.assert_allclose(data.uvs, np.tile([0.25, 0.25], (len(p), 1)), atol=1e-6)  # v = 1 - t
    else:  # each corner's st is 0.5 + 0.5 * its position, flipped to v = 1 - t
        np.testing.assert_allclose(data.uvs[:, 0], 0.5 + 0.5 * p[:, 0], atol=1e-6)
        np.testing.assert_allclose(data.uvs[:, 1], 0.5 - 0.5 * p[:, 1], atol=1e-6)
    if interpolation == "faceVarying":
        assert len(p) == 6 and data.indices is not None  # split per corner: 6 corners


def test_left_handed_uniform_colors_and_computed_smooth_normals(tmp_path):
    stage = new_stage(tmp_path / "m.usda")
    mesh = UsdGeom.Mesh.Define(stage, "/World/tent")  # two quads meeting at a ridge, clockwise (leftHanded)
    mesh.CreatePointsAttr([(-1, 0, 1), (-1, 0, -1), (0, 1, -1), (0, 1, 1), (1, 0, -1), (1, 0, 1)])
    mesh.CreateFaceVertexCountsAttr([4, 4])
    mesh.CreateFaceVertexIndicesAttr([0, 1, 2, 3, 3, 2, 4, 5])
    mesh.CreateOrientationAttr(UsdGeom.Tokens.leftHanded)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    mesh.CreateDisplayColorPrimvar(UsdGeom.Tokens.uniform).Set([(1, 0, 0), (0, 0, 1)])
    stage.GetRootLayer().Save()
    scene = load(tmp_path / "m.usda")
    data = scene.assets.meshes["/World/tent"]
    assert len(data.positions) == 8, "uniform colours split the vertices per face corner"
    p, tris = data.positions.astype(np.float64), data.triangles()
    cross = np.cross(p[tris[:, 1]] - p[tris[:, 0]], p[tris[:, 2]] - p[tris[:, 0]])
    assert np.all(cross[:, 1] > 0), "leftHanded faces wound clockwise still face up (+Y) after loading"
    ridge = np.isclose(p[:, 1], 1.0)
    np.testing.assert_allclose(data.normals[ridge], np.tile([0, 1, 0], (ridge.sum(), 1)), atol=1e-6,
                               err_msg="the ridge's computed normal is shared by both faces (smooth)")
    np.testing.assert_allclose(data.colors[:4, :3], np.tile([1, 0, 0], (4, 1)))
    np.testing.assert_allclose(data.colors[4:, :3], np.tile([0, 0, 1], (4, 1)))


GPRIM_EXTENT_TOLERANCE = {"Sphere": 0.005, "Cube": 1e-6, "Cylinder": 1e-6, "Cone": 1e-6, "Capsule": 1e-6,
                          "Plane": 1e-6}


@pytest.mark.parametrize("kind", list(GPRIM_EXTENT_TOLERANCE))
@pytest.mark.parametrize("axis", ["X", "Y", "Z"])
def test_gprims_fill_their_extent(tmp_path, kind, axis):
    if kind in ("Sphere", "Cube") and axis != "Y":
        pytest.skip("no axis")
    stage = new_stage(tmp_path / "g.usda")
    prim = stage.DefinePrim("/World/shape", kind)
    for attr, value in {"radius": 0.7, "height": 1.6, "size": 1.3, "width": 2.2, "length": 0.9}.items():
        if prim.GetAttribute(attr):
            prim.GetAttribute(attr).Set(value)
    if prim.GetAttribute("axis"):
        prim.GetAttribute("axis").Set(axis)
    stage.GetRootLayer().Save()
    scene = load(tmp_path / "g.usda")
    data = scene.assets.meshes["/World/shape"]
    extent = np.array(UsdGeom.Boundable.ComputeExtentFromPlugins(UsdGeom.Boundable(prim), Usd.TimeCode.Default()))
    lo, hi = data.positions.min(axis=0), data.positions.max(axis=0)
    tol = GPRIM_EXTENT_TOLERANCE[kind]
    np.testing.assert_allclose(lo, extent[0], atol=tol, err_msg=f"{kind} axis {axis}: minimum")
    np.testing.assert_allclose(hi, extent[1], atol=tol, err_msg=f"{kind} axis {axis}: maximum")
    # Outward normals: for a closed shape, each vertex normal points away from the centre.
    if kind != "Plane":
        p, n = data.positions.astype(np.float64), data.normals.astype(np.float64)
        assert np.all(np.einsum("ij,ij->i", p, n) > -1e-6), f"{kind}: a normal points inwards"
    tris = data.triangles()
    p = data.positions.astype(np.float64)
    cross = np.cross(p[tris[:, 1]] - p[tris[:, 0]], p[tris[:, 2]] - p[tris[:, 0]])
    centre = p[tris].mean(axis=1)
    if kind != "Plane":
        assert np.all(np.einsum("ij,ij->i", cross, centre) >= -1e-9), f"{kind}: a triangle faces inwards"


# --- what cannot be mapped, references, payloads, folders ----------------------------------------------
def test_unmapped_things_are_listed_in_one_warning(tmp_path):
    stage = new_stage(tmp_path / "u.usda")
    curves = UsdGeom.BasisCurves.Define(stage, "/World/hair")
    curves.CreatePointsAttr([(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 2, 0)])
    curves.CreateCurveVertexCountsAttr([4])
    UsdLux.RectLight.Define(stage, "/World/panel")
    mesh = hexagon(stage, "/World/hex", None)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.catmullClark)
    hidden = UsdGeom.Sphere.Define(stage, "/World/hidden")
    hidden.CreateVisibilityAttr(UsdGeom.Tokens.invisible)
    stage.GetRootLayer().Save()
    with pytest.warns(USDSceneWarning) as record:
        scene = load(tmp_path / "u.usda")
    assert len(record) == 1, [str(r.message) for r in record]
    message = str(record[0].message)
    for expected in ("</World/hair>: prim type 'BasisCurves'", "</World/panel>: a RectLight has no engine light",
                     "</World/hex>: subdivisionScheme 'catmullClark'", "</World/hidden>: invisible"):
        assert expected in message, f"{expected!r} not in {message}"
    assert {"hair", "panel", "hex", "hidden"} <= set(names(scene)), "listed things still load as entities"


def write_part(folder: Path, name: str = "part.usda") -> Path:
    stage = Usd.Stage.CreateNew(str(folder / name))
    part = UsdGeom.Xform.Define(stage, "/Part")
    stage.SetDefaultPrim(part.GetPrim())
    UsdGeom.Cube.Define(stage, "/Part/box").CreateSizeAttr(2.0)
    stage.GetRootLayer().Save()
    return folder / name


def test_references_payloads_and_sublayers_inside_the_folder(tmp_path):
    (tmp_path / "parts").mkdir()
    write_part(tmp_path / "parts")
    sub = Usd.Stage.CreateNew(str(tmp_path / "sub.usda"))
    UsdGeom.Sphere.Define(sub, "/World/from_sublayer")
    sub.GetRootLayer().Save()
    stage = new_stage(tmp_path / "main.usda")
    stage.GetRootLayer().subLayerPaths.append("./sub.usda")
    stage.DefinePrim("/World/ref").GetReferences().AddReference("./parts/part.usda")
    stage.DefinePrim("/World/pay").GetPayloads().AddPayload("./parts/part.usda")
    stage.GetRootLayer().Save()
    scene = load(tmp_path / "main.usda")
    meshes = set(scene.assets.meshes)
    assert {"/World/ref/box", "/World/pay/box", "/World/from_sublayer"} <= meshes


def test_missing_reference_or_sublayer_is_an_error(tmp_path):
    stage = new_stage(tmp_path / "main.usda")
    stage.DefinePrim("/World/ref").GetReferences().AddReference("./gone.usda")
    stage.GetRootLayer().Save()
    with pytest.raises(USDSceneError, match=r"main\.usda: .*reference or payload @\./gone\.usda@ is missing"):
        load(tmp_path / "main.usda")
    stage = new_stage(tmp_path / "second.usda")
    stage.GetRootLayer().subLayerPaths.append("./nolayer.usda")
    stage.GetRootLayer().Save()
    with pytest.raises(USDSceneError, match=r"second\.usda: .*sublayer @\./nolayer\.usda@ is missing"):
        load(tmp_path / "second.usda")


def test_files_outside_the_folder_are_refused_unless_allowed(tmp_path):
    (tmp_path / "scene").mkdir()
    write_part(tmp_path)
    stage = new_stage(tmp_path / "scene" / "main.usda")
    stage.DefinePrim("/World/ref").GetReferences().AddReference("../part.usda")
    stage.GetRootLayer().Save()
    with pytest.raises(USDSceneError, match=r"@\.\./part\.usda@ .* outside the scene's folder .* allow_outside"):
        load(tmp_path / "scene" / "main.usda")
    assert "/World/ref/box" in load(tmp_path / "scene" / "main.usda", allow_outside=True).assets.meshes
    # A texture outside the folder too.
    checkerboard(8, 2).save_png(tmp_path / "outside.png") if hasattr(TextureData, "save_png") else _png(
        tmp_path / "outside.png")
    stage = new_stage(tmp_path / "scene" / "tex.usda")
    hexagon(stage, "/World/hex", "vertex")
    preview(stage, "/World/Looks/M", "../outside.png", "/World/hex")
    stage.GetRootLayer().Save()
    with pytest.raises(USDSceneError, match=r"inputs:file.*outside\.png.* outside the scene's folder"):
        load(tmp_path / "scene" / "tex.usda")
    assert "/World/Looks/M" in load(tmp_path / "scene" / "tex.usda", allow_outside=True).assets.materials


def _png(path: Path) -> None:
    from PIL import Image

    Image.fromarray(checkerboard(8, 2).pixels).save(path)


def preview(stage: Usd.Stage, path: str, file: str | None, bind_to: str, color=(0.8, 0.8, 0.8)) -> UsdShade.Material:
    """A UsdPreviewSurface material (with a UsdUVTexture + st reader when ``file`` is given), bound to a prim."""
    material = UsdShade.Material.Define(stage, path)
    surface = UsdShade.Shader.Define(stage, f"{path}/Surface")
    surface.CreateIdAttr("UsdPreviewSurface")
    surface.CreateInput("roughness", T.Float).Set(0.4)
    if file is None:
        surface.CreateInput("diffuseColor", T.Color3f).Set(Gf.Vec3f(*color))
    else:
        reader = UsdShade.Shader.Define(stage, f"{path}/StReader")
        reader.CreateIdAttr("UsdPrimvarReader_float2")
        reader.CreateInput("varname", T.String).Set("st")
        texture = UsdShade.Shader.Define(stage, f"{path}/Texture")
        texture.CreateIdAttr("UsdUVTexture")
        texture.CreateInput("file", T.Asset).Set(file)
        texture.CreateInput("sourceColorSpace", T.Token).Set("sRGB")
        texture.CreateInput("scale", T.Float4).Set(Gf.Vec4f(*color, 1.0))
        texture.CreateInput("st", T.Float2).ConnectToSource(reader.ConnectableAPI(), "result")
        surface.CreateInput("diffuseColor", T.Color3f).ConnectToSource(texture.ConnectableAPI(), "rgb")
    material.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")
    UsdShade.MaterialBindingAPI.Apply(stage.GetPrimAtPath(bind_to)).Bind(material)
    return material


# --- the same picture ------------------------------------------------------------------------------------
FOCAL = 25.0  # mm, on a 24 mm vertical aperture
EYE = (0.0, 1.5, 6.0)
PITCH = -math.degrees(math.atan2(1.5, 6.0))
TINT = (0.9, 0.7, 0.5)  # linear, the texture's scale


def q_axis(axis, degrees) -> np.ndarray:
    return quat_from_axis_angle(np.array(axis, float), math.radians(degrees))


def q_xyz(x, y, z) -> np.ndarray:
    """USD's rotateXYZ: X first, then Y, then Z (column vectors: Rz·Ry·Rx)."""
    return quat_mul(q_axis((0, 0, 1), z), quat_mul(q_axis((0, 1, 0), y), q_axis((1, 0, 0), x)))


def pxr_scene(folder: Path) -> Path:
    """Ordinary xform ops, a plain n-gon mesh, gprims, preview-surface materials with a texture, UsdLux lights."""
    from PIL import Image

    (folder / "textures").mkdir()
    Image.fromarray(checkerboard(32, 4).pixels).save(folder / "textures" / "checker.png")
    stage = new_stage(folder / "scene.usda")
    camera = UsdGeom.Camera.Define(stage, "/World/camera")
    camera.AddTranslateOp().Set(Gf.Vec3d(*EYE))
    camera.AddRotateXYZOp().Set(Gf.Vec3f(PITCH, 0, 0))
    camera.CreateFocalLengthAttr(FOCAL)
    camera.CreateVerticalApertureAttr(24.0)
    camera.CreateHorizontalApertureAttr(32.0)
    camera.CreateClippingRangeAttr(Gf.Vec2f(0.1, 100.0))
    sun = UsdLux.DistantLight.Define(stage, "/World/sun")
    sun.AddRotateXYZOp().Set(Gf.Vec3f(-45, 30, 0))
    sun.CreateIntensityAttr(0.9)
    sun.CreateNormalizeAttr(True)  # the intensity is then the irradiance (lux), whatever the sun's angle
    sun.CreateColorAttr(Gf.Vec3f(1.0, 0.9, 0.8))
    dome = UsdLux.DomeLight.Define(stage, "/World/sky")
    dome.CreateIntensityAttr(1.0)
    dome.CreateColorAttr(Gf.Vec3f(0.2, 0.2, 0.25))
    group = UsdGeom.Xform.Define(stage, "/World/group")
    group.AddTranslateOp().Set(Gf.Vec3d(0.5, 0.0, 0.0))
    group.AddRotateYOp().Set(20.0)
    group.AddScaleOp().Set(Gf.Vec3f(1.2, 1.2, 1.2))
    ball = UsdGeom.Sphere.Define(stage, "/World/group/ball")
    ball.AddTranslateOp().Set(Gf.Vec3d(-2.0, 0.0, 0.0))
    ball.CreateRadiusAttr(0.6)
    ball.CreateDisplayColorPrimvar().Set([(0.8, 0.1, 0.1)])
    box = UsdGeom.Cube.Define(stage, "/World/group/box")
    box.AddTranslateOp().Set(Gf.Vec3d(0.5, 0.0, 0.0))
    box.AddTranslateOp(opSuffix="pivot").Set(Gf.Vec3d(0.0, -0.5, 0.0))
    box.AddRotateXYZOp().Set(Gf.Vec3f(10, 35, 0))
    box.AddTranslateOp(opSuffix="pivot", isInverseOp=True)
    box.CreateSizeAttr(1.0)
    hexagon(stage, "/World/hex", "faceVarying")
    hexagon_xf = UsdGeom.Xformable(stage.GetPrimAtPath("/World/hex"))
    hexagon_xf.AddTransformOp().Set(Gf.Matrix4d().SetScale(0.8) * Gf.Matrix4d().SetTranslate((1.6, 1.3, -1.0)))
    preview(stage, "/World/Looks/Checker", "./textures/checker.png", "/World/group/box", TINT)
    stage.GetPrimAtPath("/World/hex").ApplyAPI(UsdShade.MaterialBindingAPI)
    UsdShade.MaterialBindingAPI(stage.GetPrimAtPath("/World/hex")).Bind(
        UsdShade.Material(stage.GetPrimAtPath("/World/Looks/Checker")))
    stage.GetRootLayer().Save()
    return folder / "scene.usda"


def hand_scene(folder: Path) -> Scene:
    """The same scene with the engine's own calls (quaternions composed by hand, the hexagon fanned by hand)."""
    scene = Scene("by hand")
    scene.assets.texture("checker", TextureData.from_file(folder / "textures" / "checker.png"))
    srgb = lambda c: tuple(float(x) for x in linear_to_srgb(np.array(c)))  # noqa: E731
    scene.assets.material("checker", MaterialData("unlit", ["checker"], color=srgb(TINT)))
    scene.assets.material("red", MaterialData("lit", color=srgb((0.8, 0.1, 0.1))))
    scene.assets.mesh("ball", uv_sphere(0.6, 32, 16))
    scene.assets.mesh("box", cube(1.0))
    corners = np.array(HEX)
    scene.assets.mesh("hex", MeshData(corners, normals=np.tile([0.0, 0.0, 1.0], (6, 1)),
                                      uvs=np.stack([0.5 + 0.5 * corners[:, 0], 0.5 - 0.5 * corners[:, 1]], 1),
                                      indices=[0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5]))
    fov = math.degrees(2 * math.atan(12.0 / FOCAL))
    scene.create_entity(InfoComponent("camera"), TransformComponent(EYE, quaternion=q_axis((1, 0, 0), PITCH)),
                        CameraComponent(fov, 0.1, 100.0))
    scene.create_entity(InfoComponent("sun"), TransformComponent(quaternion=q_xyz(-45, 30, 0)),
                        LightComponent("directional", srgb((1.0, 0.9, 0.8)), 0.9))
    scene.create_entity(InfoComponent("sky"), TransformComponent(), LightComponent("ambient", srgb((0.2, 0.2, 0.25))))
    group_transform = TransformComponent((0.5, 0, 0), quaternion=q_axis((0, 1, 0), 20), scale=1.2)
    group = scene.create_entity(InfoComponent("group"), group_transform)
    scene.create_entity(InfoComponent("ball"), LinkComponent(group), TransformComponent((-2.0, 0, 0)),
                        MeshComponent("ball"), MaterialComponent("red"))
    # translate (0.5, 0, 0) then a rotation about the pivot (0, -0.5, 0): t = T + p - R·p.
    q = q_xyz(10, 35, 0)
    scene_tmp = Scene("rot")
    scene_tmp.create_entity(InfoComponent("r"), TransformComponent(quaternion=q))
    rot = worlds(scene_tmp)["r"][:3, :3]
    pivot = np.array([0.0, -0.5, 0.0])
    scene.create_entity(InfoComponent("box"), LinkComponent(group),
                        TransformComponent(np.array([0.5, 0, 0]) + pivot - rot @ pivot, quaternion=q),
                        MeshComponent("box"), MaterialComponent("checker"))
    scene.create_entity(InfoComponent("hex"), TransformComponent((1.6, 1.3, -1.0), scale=0.8), MeshComponent("hex"),
                        MaterialComponent("checker"))
    return scene


def test_pxr_scene_renders_like_the_same_scene_built_by_hand(tmp_path, backend):
    path = pxr_scene(tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # everything in this scene maps: no warning
        loaded = load(path)
    by_hand = render_scene(backend, hand_scene(tmp_path))
    got = render_scene(backend, loaded)
    colours = len(np.unique(by_hand[..., :3].reshape(-1, 3), axis=0))
    assert colours > 20, f"{backend}: the scene draws something ({colours} colours)"
    value = psnr(by_hand[..., :3], got[..., :3])
    assert value >= 40.0, (f"{backend}: the pxr-built scene differs from the one built by hand: PSNR {value:.1f} dB "
                           f"< 40 dB, largest difference {np.abs(by_hand.astype(int) - got).max()}")


def test_a_gprim_added_to_a_gandalf_file_by_another_tool_loads(tmp_path):
    from step07_advanced.usd import save_scene

    scene = Scene("mine")
    scene.create_entity(InfoComponent("camera"), TransformComponent((0, 0, 5)), CameraComponent())
    path = save_scene(scene, tmp_path / "mine.usda")
    stage = Usd.Stage.Open(str(path))
    ball = UsdGeom.Sphere.Define(stage, "/Scene/added_ball")
    ball.AddTranslateOp().Set(Gf.Vec3d(1, 2, 3))
    stage.GetRootLayer().Save()
    loaded = load(path)
    entity = names(loaded)["added_ball"]
    assert loaded.get_component(entity, MeshComponent).mesh == "/Scene/added_ball"
    np.testing.assert_allclose(loaded.get_component(entity, TransformComponent).translation, (1, 2, 3))
    assert loaded.get_component(entity, MaterialComponent).material in loaded.assets.materials


def test_a_big_plain_mesh_loads_quickly(tmp_path):
    import time

    n = 200  # a 200 x 200 quad grid: 40k faces
    stage = new_stage(tmp_path / "big.usda")
    mesh = UsdGeom.Mesh.Define(stage, "/World/grid")
    u, v = np.meshgrid(np.arange(n + 1), np.arange(n + 1))
    mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(np.stack([u, np.zeros_like(u), v], -1).reshape(-1, 3)
                                                  .astype(np.float32)))
    i = (np.arange(n)[:, None] * (n + 1) + np.arange(n)[None, :]).reshape(-1)
    quads = np.stack([i, i + n + 1, i + n + 2, i + 1], 1).astype(np.int32)
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(quads), 4, np.int32)))
    mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(quads.reshape(-1)))
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    stage.GetRootLayer().Save()
    start = time.perf_counter()
    data = load(tmp_path / "big.usda").assets.meshes["/World/grid"]
    took = time.perf_counter() - start
    assert len(data.triangles()) == 2 * n * n
    np.testing.assert_allclose(data.normals, np.tile([0, 1, 0], (len(data.normals), 1)), atol=1e-6)
    assert took < 5.0, f"40k quads took {took:.2f} s"


def test_a_gandalf_file_referenced_into_another_stage(tmp_path):
    """A prop saved by gandalf, referenced by a layout file: its meshes, materials and textures come back exactly,
    read from the prop file's own /Assets (USD does not carry prims outside the referenced default prim)."""
    from step07_advanced.usd import save_scene

    (tmp_path / "props").mkdir()
    prop = Scene("prop")
    prop.assets.mesh("cube", cube())
    prop.assets.texture("checker", checkerboard(16, 4))
    prop.assets.material("plain", MaterialData("lit", color=(0.2, 0.4, 0.6)))
    prop.assets.material("textured", MaterialData("unlit", ["checker"], color=(1.0, 0.5, 0.25)))
    prop.create_entity(InfoComponent("a"), TransformComponent((1, 0, 0)), MeshComponent("cube"),
                       MaterialComponent("plain"))
    prop.create_entity(InfoComponent("b"), TransformComponent((-1, 0, 0)), MeshComponent("cube"),
                       MaterialComponent("textured"))
    save_scene(prop, tmp_path / "props" / "prop.usda")
    stage = new_stage(tmp_path / "layout.usda")
    placed = UsdGeom.Xform.Define(stage, "/World/prop")
    placed.AddTranslateOp().Set(Gf.Vec3d(0, 0, -3))
    placed.GetPrim().GetReferences().AddReference("./props/prop.usda")
    stage.GetRootLayer().Save()
    scene = load(tmp_path / "layout.usda")
    found = names(scene)
    a, b = found["a"], found["b"]
    mesh = scene.assets.meshes[scene.get_component(a, MeshComponent).mesh]
    assert np.array_equal(mesh.positions, cube().positions) and np.array_equal(mesh.uvs, cube().uvs)
    assert scene.get_component(a, MeshComponent).mesh == "props/prop.usda:cube"
    plain = scene.assets.materials[scene.get_component(a, MaterialComponent).material]
    assert plain.shader == "lit" and plain.color == (0.2, 0.4, 0.6, 1.0)
    textured = scene.assets.materials[scene.get_component(b, MaterialComponent).material]
    assert textured.shader == "unlit" and textured.textures == ("props/prop.usda:checker",)
    assert textured.color == (1.0, 0.5, 0.25, 1.0)
    assert np.array_equal(scene.assets.textures[textured.textures[0]].pixels, checkerboard(16, 4).pixels)
    np.testing.assert_allclose(worlds(scene)["a"][:3, 3], (1, 0, -3), atol=1e-12)


def test_cameras_and_lights_of_another_tool(tmp_path):
    stage = new_stage(tmp_path / "c.usda")
    for name in ("main", "side"):
        camera = UsdGeom.Camera.Define(stage, f"/World/{name}")
        camera.CreateFocalLengthAttr(24.0)
        camera.CreateVerticalApertureAttr(24.0)
    light = UsdLux.SphereLight.Define(stage, "/World/bulb")
    light.CreateIntensityAttr(3.0)
    light.CreateExposureAttr(2.0)
    light.CreateColorAttr(Gf.Vec3f(1.0, 0.5, 0.0))
    stage.GetRootLayer().Save()
    scene = load(tmp_path / "c.usda")
    found = names(scene)
    main, side = (scene.get_component(found[n], CameraComponent) for n in ("main", "side"))
    assert main.primary and not side.primary, "the first camera of another tool's file is the primary one"
    assert main.fov == pytest.approx(2 * math.degrees(math.atan(0.5)), abs=1e-9)
    bulb = scene.get_component(found["bulb"], LightComponent)
    # intensity x 2^exposure, from a sphere of UsdLux's default radius 0.5: power / 4π = π · 12 · 0.5²
    assert bulb.kind == "point" and bulb.intensity == pytest.approx(math.pi * 12.0 * 0.25), "intensity x 2^exposure"
    assert bulb.range > 10.0, "another tool's point light falls off with the inverse square"
    np.testing.assert_allclose(bulb.color, linear_to_srgb(np.array([1.0, 0.5, 0.0])), atol=1e-6)


def test_default_material_mapping_draws_with_the_builtin_blinn_phong_in_both_apis(tmp_path):
    """Without ``preview_material`` the preview surfaces become the built-in ``gandalf.blinn_phong`` (no shader to
    build); the loaded scene draws and both APIs agree (PSNR >= 35 dB)."""
    path = pxr_scene(tmp_path)
    pictures = {}
    for backend in ("opengl", "webgpu"):
        scene = load_scene(path)
        materials = list(scene.assets.materials.values())
        assert {m.shader for m in materials} == {"gandalf.blinn_phong"}
        assert sorted(len(m.textures) for m in materials) == [0, 1]
        with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
            app.add_scene(scene)
            app.run(frames=2)
            pictures[backend] = app.capture()
    colours = len(np.unique(pictures["opengl"][..., :3].reshape(-1, 3), axis=0))
    assert colours > 20, f"the scene draws something ({colours} colours)"
    value = psnr(pictures["opengl"][..., :3], pictures["webgpu"][..., :3])
    assert value >= 35.0, f"OpenGL and WebGPU differ: PSNR {value:.1f} dB < 35 dB"


def test_instanceable_references_and_point_instancers(tmp_path):
    write_part(tmp_path)
    stage = new_stage(tmp_path / "i.usda")
    for k in range(2):
        copy = UsdGeom.Xform.Define(stage, f"/World/copy{k}")
        copy.AddTranslateOp().Set(Gf.Vec3d(3.0 * k, 0, 0))
        copy.GetPrim().GetReferences().AddReference("./part.usda")
        copy.GetPrim().SetInstanceable(True)
    instancer = UsdGeom.PointInstancer.Define(stage, "/World/scatter")
    UsdGeom.Sphere.Define(stage, "/World/scatter/prototypes/ball")
    instancer.CreatePrototypesRel().SetTargets(["/World/scatter/prototypes/ball"])
    instancer.CreateProtoIndicesAttr([0, 0])
    instancer.CreatePositionsAttr([(0, 0, 0), (1, 0, 0)])
    stage.GetRootLayer().Save()
    with pytest.warns(USDSceneWarning, match=r"</World/scatter>: a PointInstancer"):
        scene = load(tmp_path / "i.usda")
    assert {"/World/copy0/box", "/World/copy1/box"} <= set(scene.assets.meshes), "instance proxies are drawn"
    assert not any(m.startswith("/World/scatter/") for m in scene.assets.meshes), "prototypes are not drawn alone"
    matrices = worlds(scene)
    np.testing.assert_allclose([matrices[n][0, 3] for n in ("copy0", "copy1")], [0.0, 3.0])
