"""USD scenes: save a Scene to .usda/.usdc and load it back, exactly, safely, and drawing the same picture.

Tolerances: float64 component data within 1e-12 (in practice bit-exact), float32 mesh data and texture
pixels exact, world matrices within 1e-12 after a TransformSystem update; the original and the re-loaded
scene must render byte-identical images in each backend.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
import uuid
from pathlib import Path

import numpy as np
import pytest
from core_shaders import render_scene

from gandalf_core import ClearColorComponent, InfoComponent, LinkComponent, Scene, TransformComponent, TransformSystem
from gandalf_core.components import CameraComponent, LightComponent, MaterialComponent, MeshComponent, SkyboxComponent
from gandalf_core.ecs import Component
from gandalf_core.math import look_at_rotation
from gandalf_core.resources import MaterialData, MeshData, TextureData, checkerboard, cube, sky_cube, uv_sphere
from step07_advanced.usd import (
    USDSceneError,
    USDSceneWarning,
    load_scene,
    register_component,
    save_scene,
    unregister_component,
)

pxr = pytest.importorskip("pxr")
from pxr import Sdf, Usd, UsdGeom  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


# --- scenes -------------------------------------------------------------------------------------------
def odd_mesh() -> MeshData:
    """A non-indexed mesh with colours, tangents and UVs whose flip is not exact in float32."""
    rng = np.random.default_rng(7)
    return MeshData(
        positions=rng.uniform(-1, 1, (6, 3)),
        normals=np.tile([0.0, 0.0, 1.0], (6, 1)),
        uvs=rng.uniform(0, 1, (6, 2)),
        tangents=np.tile([1.0, 0.0, 0.0, -1.0], (6, 1)),
        colors=rng.uniform(0, 1, (6, 4)),
        name="odd",
    )


def full_scene() -> Scene:
    scene = Scene("full")
    scene.assets.mesh("cube", cube())
    scene.assets.mesh("sphere", uv_sphere(segments=16, rings=8))
    scene.assets.mesh("odd", odd_mesh())
    scene.assets.texture("checker", checkerboard(16, 4))
    ramp = np.arange(96, dtype=np.uint8).reshape(4, 8, 3)
    scene.assets.texture("ramp.png", TextureData.from_array(ramp, srgb=False, wrap="clamp", filter="nearest",
                                                            mipmaps=False, name="ramp.png"))
    scene.assets.texture("sky", sky_cube(16))
    scene.assets.material("Tex", MaterialData("unlit", ["checker"], color=(1.0, 0.6, 0.3)))
    scene.assets.material("Lit", MaterialData("lit", color=(0.9, 0.6, 0.3)))
    scene.assets.material("Params", MaterialData("lit", ["ramp.png"], color=(0.1, 0.2, 0.3, 0.5),
                                                 params={"shininess": 32.0, "tint": (1.0, 0.5, 0.25), "one": [2.0]},
                                                 cull="none", depth_write=False, blend="alpha", name="fancy"))
    scene.create_entity(InfoComponent("background", tag="env"), ClearColorComponent((0.2, 0.3, 0.4)),
                        SkyboxComponent("sky"))
    root = scene.create_entity(InfoComponent("root"), TransformComponent((0.5, 0.0, 0.0), (0, 20, 0), 1.2),
                               MeshComponent("cube"), MaterialComponent("Tex"))
    arm = scene.create_entity(InfoComponent("arm"), LinkComponent(root),
                              TransformComponent((1.5, 0.3, 0.0), (10, 0, 30), (0.5, 0.7, 0.5)),
                              MeshComponent("sphere"), MaterialComponent("Lit"))
    scene.create_entity(InfoComponent("hand"), LinkComponent(arm), TransformComponent((0.0, 1.2, 0.1), (0, 0, 45)),
                        MeshComponent("cube"), MaterialComponent("Tex"))
    scene.create_entity(InfoComponent("left"), TransformComponent((-2.0, -0.5, 0.0), (-30, 0, 0)),
                        MeshComponent("sphere"), MaterialComponent("Lit"))
    eye = np.array([0.0, 1.5, 6.0])
    scene.create_entity(InfoComponent("camera"), TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0, 0))),
                        CameraComponent(50.0, 0.1, 100.0))
    scene.create_entity(InfoComponent("top"), TransformComponent((0, 10, 0), (-90, 0, 0)),
                        CameraComponent(near=0.5, far=20.0, projection="orthographic", height=8.0, aspect=1.5,
                                        primary=False, reverse_z=True))
    scene.create_entity(InfoComponent("sun"), TransformComponent(rotation=(-45, 30, 0)),
                        LightComponent("directional", (1.0, 0.95, 0.9), 0.7, cast_shadows=True, shadow_extent=7.5,
                                       shadow_depth=30.0))
    scene.create_entity(InfoComponent("bulb"), TransformComponent((0, 2, 2)), LightComponent("point", (1, .5, .2), 2.0,
                                                                                              range=5.5))
    scene.create_entity(InfoComponent("sky light"), TransformComponent(), LightComponent("ambient", (0.2, 0.2, 0.3)))
    scene.create_entity(InfoComponent("hidden", tag="empty"))  # no transform: stays without one
    return scene


def by_name(scene: Scene) -> dict[str, uuid.UUID]:
    names = {scene.get_component(e, InfoComponent).name: e for e in scene.entities}
    assert len(names) == len(scene), "test scenes give every entity a distinct name"
    return names


def fields(component: Component, scene: Scene) -> dict[str, object]:
    """A component's comparable data (entity ids replaced by names)."""
    if isinstance(component, TransformComponent):
        return {k: getattr(component, k).copy() for k in ("translation", "quaternion", "scale")}
    if isinstance(component, LinkComponent):
        name = lambda e: None if e is None else scene.get_component(e, InfoComponent).name  # noqa: E731
        return {"parent": name(component.parent), "children": [name(c) for c in component.children]}
    if isinstance(component, (MeshComponent, MaterialComponent)):
        return {"name": repr(component)}
    return dict(vars(component))


def assert_same_value(a: object, b: object, where: str) -> None:
    if isinstance(a, (np.ndarray, float, tuple, list)) and not isinstance(a, str) and a is not None:
        a_arr, b_arr = np.asarray(a), np.asarray(b)
        assert a_arr.shape == b_arr.shape, where
        if a_arr.dtype == np.float32:
            assert b_arr.dtype == np.float32 and np.array_equal(a_arr, b_arr), where
        elif a_arr.dtype.kind == "f":
            np.testing.assert_allclose(b_arr, a_arr, rtol=0, atol=1e-12, err_msg=where)
        else:
            assert a_arr.tolist() == b_arr.tolist(), where
        assert type(a) is type(b), f"{where}: {type(a).__name__} became {type(b).__name__}"
    else:
        assert a == b, f"{where}: {a!r} != {b!r}"


def assert_same_scene(original: Scene, loaded: Scene) -> None:
    a_names, b_names = by_name(original), by_name(loaded)
    assert sorted(a_names) == sorted(b_names)
    for name, a in a_names.items():
        b = b_names[name]
        a_comps = {type(c): c for c in original.components_of(a)}
        b_comps = {type(c): c for c in loaded.components_of(b)}
        assert set(a_comps) == set(b_comps), name
        for t, comp in a_comps.items():
            fa, fb = fields(comp, original), fields(b_comps[t], loaded)
            assert fa.keys() == fb.keys()
            for key in fa:
                assert_same_value(fa[key], fb[key], f"{name}.{t.__name__}.{key}")
    assert_same_assets(original, loaded)


def assert_same_assets(original: Scene, loaded: Scene) -> None:
    a, b = original.assets, loaded.assets
    assert a.meshes.keys() == b.meshes.keys() and a.materials.keys() == b.materials.keys()
    for name, mesh in a.meshes.items():
        other = b.meshes[name]
        for f in ("positions", "normals", "uvs", "tangents", "colors", "indices", "name"):
            x, y = getattr(mesh, f), getattr(other, f)
            if x is None or y is None:
                assert x is None and y is None, f"mesh {name}.{f}"
            elif isinstance(x, str):
                assert x == y
            else:
                assert x.dtype == y.dtype and np.array_equal(x, y), f"mesh {name}.{f} (must be exact)"
    for name, material in a.materials.items():
        other = b.materials[name]
        for f in ("shader", "textures", "color", "cull", "depth_test", "depth_write", "blend", "name"):
            assert getattr(material, f) == getattr(other, f), f"material {name}.{f}"
        assert dict(material.params) == dict(other.params), f"material {name}.params"
    assert a.textures.keys() == b.textures.keys()
    for name, tex in a.textures.items():
        other = b.textures[name]
        assert type(tex) is type(other)
        assert np.array_equal(tex.pixels, other.pixels), f"texture {name} pixels (must be exact)"
        for f in ("srgb", "filter", "mipmaps", "name", "wrap"):
            assert getattr(tex, f, None) == getattr(other, f, None), f"texture {name}.{f}"


def world_matrices(scene: Scene) -> dict[str, np.ndarray]:
    system = TransformSystem()
    scene.add_system(system)
    system.on_update_system(0.0)
    return {
        scene.get_component(e, InfoComponent).name: t.world.copy()
        for e, (t,) in scene.view(TransformComponent)
    }


# --- round trips -----------------------------------------------------------------------------------------
@pytest.mark.parametrize("suffix", [".usda", ".usdc"])
def test_round_trip_is_exact(tmp_path, suffix):
    original = full_scene()
    path = save_scene(original, tmp_path / f"level{suffix}")
    assert path == tmp_path / f"level{suffix}"
    loaded = load_scene(path)
    assert loaded is not original and loaded.name == "full"
    assert_same_scene(original, loaded)
    a, b = world_matrices(original), world_matrices(loaded)
    assert a.keys() == b.keys()
    for name in a:
        np.testing.assert_allclose(b[name], a[name], rtol=0, atol=1e-12, err_msg=name)
    assert load_scene(path, name="copy").name == "copy"
    if suffix == ".usdc":
        assert path.read_bytes()[:8] == b"PXR-USDC"


def test_usd_itself_computes_the_same_world_matrices(tmp_path):
    """USD's own evaluation of the xformOps (w-first quaternions, T·R·S order) matches gandalf's."""
    original = full_scene()
    save_scene(original, tmp_path / "s.usda")
    worlds = world_matrices(original)
    stage = Usd.Stage.Open(Sdf.Layer.OpenAsAnonymous(str(tmp_path / "s.usda")))
    checked = 0
    for prim in Usd.PrimRange(stage.GetPrimAtPath("/Scene")):
        name = prim.GetAttribute("gandalf:name").Get()
        if name in worlds:
            usd = np.array(UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(Usd.TimeCode.Default()))
            np.testing.assert_allclose(usd.T, worlds[name], rtol=0, atol=1e-12, err_msg=name)  # USD: row vectors
            checked += 1
    assert checked == len(worlds)


def test_usda_text_has_the_expected_prims(tmp_path):
    save_scene(full_scene(), tmp_path / "s.usda")
    text = (tmp_path / "s.usda").read_text(encoding="utf-8")
    for expected in (
        'def Xform "Scene"', 'def Xform "root"', 'def Xform "arm"', 'def Xform "hand"', 'def Camera "camera"',
        'def Camera "top"', 'token projection = "orthographic"', 'def DistantLight "sun"', 'def SphereLight "bulb"',
        "custom double gandalf:range = 5.5", 'def DomeLight "sky_light"', 'custom string gandalf:name = "sky light"',
        'def Scope "Assets"', 'def Mesh "cube"', 'def Mesh "sphere"', 'def Material "Params"',
        "texCoord2f[] primvars:st", "texCoord2d[] primvars:st", "float4[] primvars:tangents",
        "color3f[] primvars:displayColor", '@./s_usda_textures/ramp_png.png@', "custom double4 gandalf:clearColor",
        'custom string gandalf:skybox = "sky"', '"xformOp:translate", "xformOp:orient", "xformOp:scale"',
        "rel material:binding = </Assets/Materials/Tex>",
    ):
        assert expected in text, expected
    # Nesting follows the Links: hand inside arm inside root.
    assert text.index('def Xform "root"') < text.index('def Xform "arm"') < text.index('def Xform "hand"')
    assert sorted(p.name for p in (tmp_path / "s_usda_textures").iterdir()) == [
        "checker.png", "ramp_png.png", *(f"sky_{s}.png" for s in ("nx", "ny", "nz", "px", "py", "pz"))
    ]


def test_camera_attributes_match_the_field_of_view(tmp_path):
    save_scene(full_scene(), tmp_path / "s.usda")
    stage = Usd.Stage.Open(Sdf.Layer.OpenAsAnonymous(str(tmp_path / "s.usda")))
    camera = UsdGeom.Camera(stage.GetPrimAtPath("/Scene/camera")).GetCamera(Usd.TimeCode.Default())
    assert camera.GetFieldOfView(camera.FOVVertical) == pytest.approx(50.0, abs=1e-4)  # float attributes
    assert camera.clippingRange.GetMin() == pytest.approx(0.1) and camera.clippingRange.GetMax() == pytest.approx(100)


def test_without_assets_no_texture_files_are_written(tmp_path):
    scene = full_scene()
    save_scene(scene, tmp_path / "s.usda", assets=False)
    assert not (tmp_path / "s_usda_textures").exists()
    loaded = load_scene(tmp_path / "s.usda")
    assert loaded.assets.textures == {} and loaded.assets.meshes.keys() == scene.assets.meshes.keys()


def test_reloaded_scene_renders_the_same_picture(tmp_path, backend):
    original = full_scene()
    save_scene(original, tmp_path / "s.usdc")
    before = render_scene(backend, original)
    after = render_scene(backend, load_scene(tmp_path / "s.usdc"))
    assert len(np.unique(before[..., :3].reshape(-1, 3), axis=0)) > 20, "the scene draws something"
    assert np.array_equal(before, after), f"{backend}: largest difference {np.abs(before.astype(int) - after).max()}"


# --- names ------------------------------------------------------------------------------------------
def test_names_are_sanitized_unique_and_kept(tmp_path):
    scene = Scene("names")
    raw = ["my cube", "my cube", "my_cube", "Würfel ☃", "3d", "", "Assets", "a/b.c"]
    for name in raw:
        scene.create_entity(InfoComponent(name), TransformComponent())
    parent = scene.create_entity(InfoComponent("parent"))
    for _ in range(3):
        scene.create_entity(InfoComponent("child"), LinkComponent(parent))
    save_scene(scene, tmp_path / "n.usda")
    stage = Usd.Stage.Open(Sdf.Layer.OpenAsAnonymous(str(tmp_path / "n.usda")))
    prims = list(stage.GetPrimAtPath("/Scene").GetChildren())
    for prim in prims:
        assert prim.GetName().isascii() and Sdf.Path.IsValidIdentifier(prim.GetName())
    assert len({p.GetName().lower() for p in prims}) == len(prims)
    children = [p.GetName() for p in stage.GetPrimAtPath("/Scene/parent").GetChildren()]
    assert children == ["child", "child_1", "child_2"]
    loaded = load_scene(tmp_path / "n.usda")
    assert sorted(loaded.get_component(e, InfoComponent).name for e in loaded.entities) == sorted(
        raw + ["parent"] + ["child"] * 3
    )


def test_a_thousand_entities(tmp_path):
    scene = Scene("big")
    scene.assets.mesh("cube", cube())
    rng = np.random.default_rng(3)
    parent = None
    for i in range(1000):
        parts = [InfoComponent(f"e{i}"), TransformComponent(rng.uniform(-5, 5, 3), rng.uniform(-180, 180, 3)),
                 MeshComponent("cube")]
        if i % 10:  # chains of ten
            parts.append(LinkComponent(parent))
        parent = scene.create_entity(*parts)
    start = time.perf_counter()
    save_scene(scene, tmp_path / "big.usdc")
    saved = time.perf_counter()
    loaded = load_scene(tmp_path / "big.usdc")
    print(f"1000 entities: save {saved - start:.3f} s, load {time.perf_counter() - saved:.3f} s")
    assert_same_scene(scene, loaded)


# --- registered components -----------------------------------------------------------------------------
class Spin(Component):
    def __init__(self) -> None:
        self.speed = 1.0
        self.axis = (0.0, 1.0, 0.0)
        self.turns = 0
        self.label = "spin"
        self.active = True
        self.offsets = np.zeros(2)


class Secret(Component):
    def __init__(self) -> None:
        self.payload = {"not": "saveable"}


@pytest.fixture
def spin_registered():
    register_component(Spin, fields=["speed", "axis", "turns", "label", "active", "offsets"])
    yield
    unregister_component(Spin)


def spin_scene() -> Scene:
    scene = Scene("spin")
    spin = Spin()
    spin.speed, spin.axis, spin.turns, spin.label, spin.active = 0.1 + 0.2, (0.6, 0.0, 0.8), -3, "ü", False
    spin.offsets = np.array([1e-300, -7.5])
    scene.create_entity(InfoComponent("top"), TransformComponent(), spin)
    return scene


def test_registered_component_round_trip(tmp_path, spin_registered):
    scene = spin_scene()
    save_scene(scene, tmp_path / "s.usda")
    assert 'custom double gandalf:Spin:speed = 0.30000000000000004' in (tmp_path / "s.usda").read_text("utf-8")
    loaded = load_scene(tmp_path / "s.usda")
    assert_same_scene(scene, loaded)


def test_unknown_component_strict_and_not(tmp_path, spin_registered):
    save_scene(spin_scene(), tmp_path / "s.usda")
    unregister_component(Spin)
    with pytest.raises(USDSceneError, match=r"s\.usda: prim </Scene/top>: attribute 'gandalf:components': "
                                            r"unknown component '(\w+\.)*Spin' \(its package '\w+' is not on the "
                                            r"allow-list"):
        load_scene(tmp_path / "s.usda")
    with pytest.warns(USDSceneWarning, match=r"unknown component '(\w+\.)*Spin'"):
        loaded = load_scene(tmp_path / "s.usda", strict=False)
    (entity,) = loaded.entities
    assert {type(c) for c in loaded.components_of(entity)} == {InfoComponent, TransformComponent}


def test_unregistered_component_is_reported_on_save(tmp_path):
    scene = spin_scene()
    with pytest.warns(USDSceneWarning, match=r"entity 'top' \(.*\): Spin"):
        save_scene(scene, tmp_path / "s.usda")
    assert "Spin" not in (tmp_path / "s.usda").read_text("utf-8")


def test_registry_rejects_bad_registrations():
    with pytest.raises(ValueError, match="built-in"):
        register_component(TransformComponent, ["translation"])
    with pytest.raises(ValueError, match="not an ASCII identifier"):
        register_component(Spin, ["speed", "bad field"])

    class NeedsArgs(Component):
        def __init__(self, x: float) -> None:
            self.x = x

    with pytest.raises(TypeError, match=r"NeedsArgs\(\) to work without arguments, or NeedsArgs\(\*\*fields\)"):
        register_component(NeedsArgs, ["y"])
    register_component(NeedsArgs, ["x"])  # rebuilt as NeedsArgs(x=...)
    unregister_component(NeedsArgs)


# --- failures -------------------------------------------------------------------------------------------
def snapshot(scene: Scene) -> list:
    return [(e, [repr(c) for c in scene.components_of(e)]) for e in scene.entities]


@pytest.fixture
def saved(tmp_path) -> Path:
    path = tmp_path / "good.usda"
    save_scene(full_scene(), path)
    return path


def assert_load_fails(path: Path, pattern: str) -> None:
    open_scene = full_scene()
    before = snapshot(open_scene)
    with pytest.raises(USDSceneError, match=pattern):
        load_scene(path)
    assert snapshot(open_scene) == before


def test_missing_malformed_and_wrong_extension(tmp_path, saved):
    assert_load_fails(tmp_path / "nope.usda", r"nope\.usda: no such file")
    bad = tmp_path / "bad.usda"
    bad.write_text('#usda 1.0\ndef Xform "Scene" {\n  double x = "oops"\n}\n', encoding="utf-8")
    assert_load_fails(bad, r"bad\.usda: not a valid USD file: .*bad\.usda:3")
    garbage = tmp_path / "garbage.usdc"
    garbage.write_bytes(b"\x00\x01 not usd")
    assert_load_fails(garbage, r"garbage\.usdc: not a valid USD file")
    assert_load_fails(tmp_path / "scene.json", r"scene\.json: unsupported extension '\.json'")
    with pytest.raises(USDSceneError, match=r"scene\.obj: unsupported extension"):
        save_scene(full_scene(), tmp_path / "scene.obj")
    assert not (tmp_path / "scene.obj").exists()
    assert issubclass(USDSceneError, ValueError)


@pytest.mark.parametrize("old,new,pattern", [
    ("custom double gandalf:range = 5.5", 'custom string gandalf:range = "far"',
     r"prim </Scene/bulb>: attribute 'gandalf:range': has type string, expected double"),
    ("double3 xformOp:scale = (0.5, 0.7, 0.5)", "double2 xformOp:scale = (0.5, 0.7)",
     r"prim </Scene/root/arm>: attribute 'xformOp:scale': has type double2, expected double3"),
    ("custom double gandalf:fov = 50", "custom double gandalf:fov = -5",
     r"prim </Scene/camera>: attribute 'gandalf:fov': .*CameraComponent\.fov"),
    ('custom string gandalf:lightKind = "point"', 'custom string gandalf:lightKind = "laser"',
     r"prim </Scene/bulb>: attribute 'gandalf:lightKind': LightComponent\.kind"),
    ('string inputs:gandalf:cull = "none"', 'string inputs:gandalf:cull = "sideways"',
     r"prim </Assets/Materials/Params>: attribute 'inputs:gandalf:cull'"),
])
def test_bad_attribute_is_named(saved, old, new, pattern):
    text = saved.read_text(encoding="utf-8")
    assert old in text
    saved.write_text(text.replace(old, new, 1), encoding="utf-8")
    assert_load_fails(saved, rf"good\.usda: {pattern}")


def test_missing_texture_file_is_named(saved):
    (saved.parent / "good_usda_textures" / "checker.png").unlink()
    assert_load_fails(saved, r"prim </Assets/Textures/checker>: attribute 'gandalf:files': .*checker\.png")


def temp_leftovers(folder: Path) -> list[str]:
    return [p.name for p in folder.rglob("*") if ".tmp" in p.name]


def test_unsaveable_value_keeps_the_old_file(saved):
    before = saved.read_bytes()
    textures = {p.name: p.read_bytes() for p in (saved.parent / "good_usda_textures").iterdir()}
    scene = full_scene()
    scene.create_entity(InfoComponent("vault"), Secret())
    register_component(Secret, ["payload"])
    try:
        with pytest.raises(USDSceneError, match=r"good\.usda: .*entity 'vault' .*Secret\.payload: dict values"):
            save_scene(scene, saved)
    finally:
        unregister_component(Secret)
    assert saved.read_bytes() == before
    assert {p.name: p.read_bytes() for p in (saved.parent / "good_usda_textures").iterdir()} == textures
    assert temp_leftovers(saved.parent) == []


def test_unwritable_targets_keep_the_old_file_and_leave_no_temp(tmp_path, saved):
    before = saved.read_bytes()
    blocker = tmp_path / "not_a_folder"
    blocker.write_text("x")
    with pytest.raises(USDSceneError, match="does not exist"):
        save_scene(full_scene(), blocker / "s.usda")
    # The final rename fails (the target is a folder): the temporary files written so far are removed.
    (tmp_path / "taken.usda").mkdir()
    (tmp_path / "taken.usda" / "keep").write_text("x")
    with pytest.raises(USDSceneError, match=r"taken\.usda: cannot write the file"):
        save_scene(full_scene(), tmp_path / "taken.usda", assets=False)
    assert temp_leftovers(tmp_path) == [] and saved.read_bytes() == before


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="permissions do not bind root")
def test_read_only_folder(tmp_path, saved):
    before = saved.read_bytes()
    tmp_path.chmod(0o555)
    try:
        with pytest.raises(USDSceneError, match=r"good\.usda: cannot write the file"):
            save_scene(full_scene(), saved)
    finally:
        tmp_path.chmod(0o755)
    assert saved.read_bytes() == before and temp_leftovers(tmp_path) == []


def test_importing_the_package_does_not_import_usd():
    code = "import sys, step07_advanced.usd; print('pxr' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
