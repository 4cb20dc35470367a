"""USD that other tools show, and save -> load -> save of every step's scene.

Each step's scene (steps 01-06 ``build_scene`` with the solutions, and step 07's showcase, parallax and PBR
model scenes) is saved and opened with plain ``pxr`` (no gandalf code): every entity with a mesh has a visible
``UsdGeom.Mesh`` child with a non-empty world bound (``UsdGeom.BBoxCache``) and a valid topology
(``UsdGeom.Mesh.ValidateTopology``), every material has a ``UsdPreviewSurface`` surface shader, and usd-core's
validators (all of ``UsdValidation.ValidationRegistry().GetOrLoadAllValidators()``) report no error or warning.

save -> load -> save gives the same .usda text, byte for byte, apart from the one stated field: the texture
folder's name (``<stem>_usda_textures``) in asset paths, which follows the file name; the PNG files are
byte-identical too.
"""

from __future__ import annotations

import importlib
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from gandalf_core import Scene
from gandalf_core.app.cli import load_impl
from gandalf_core.components import InfoComponent, MaterialComponent, MeshComponent
from gandalf_core.usd import load_scene, save_scene

pxr = pytest.importorskip("pxr")
from pxr import Sdf, Usd, UsdGeom, UsdShade, UsdValidation  # noqa: E402

STEPS = ("step01_window", "step02_triangle", "step03_textures", "step04_camera", "step05_scenegraph",
         "step06_lighting")


def _step(step: str) -> Callable[[], Scene]:
    return lambda: importlib.import_module(f"{step}.scene").build_scene(load_impl(step))


def _step07(technique: str, with_impl: bool) -> Callable[[], Scene]:
    def build() -> Scene:
        module = importlib.import_module(f"step07_advanced.{technique}.scene")
        return module.build_scene(load_impl("step07_advanced")) if with_impl else module.build_scene()

    return build


SCENES = {**{s: _step(s) for s in STEPS}, "step07_showcase": _step07("showcase", True),
          "step07_parallax": _step07("parallax", False), "step07_pbr_model": _step07("pbr_model", False)}


def quiet_save(scene: Scene, path: Path) -> Path:
    """Save; step components without a USD registration are reported in a warning, which is not tested here."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return save_scene(scene, path)


def open_plain(path: Path) -> Usd.Stage:
    return Usd.Stage.Open(str(path))


def validation_problems(stage: Usd.Stage) -> list[str]:
    validators = UsdValidation.ValidationRegistry().GetOrLoadAllValidators()
    context = UsdValidation.ValidationContext(validators)
    out = []
    for error in context.Validate(stage):
        if error.GetType() in (UsdValidation.ValidationErrorType.Error, UsdValidation.ValidationErrorType.Warn):
            sites = [str(s.GetPrim().GetPath()) if s.GetPrim() else "" for s in error.GetSites()]
            out.append(f"{error.GetValidator().GetMetadata().name}: {error.GetMessage()} at {sites}")
    return out


@pytest.fixture(scope="module")
def saved_steps(tmp_path_factory) -> dict[str, tuple[Scene, Path]]:
    folder = tmp_path_factory.mktemp("steps")
    out = {}
    for name, build in SCENES.items():
        scene = build()
        out[name] = (scene, quiet_save(scene, folder / f"{name}.usda"))
    return out


@pytest.mark.parametrize("name", list(SCENES))
def test_other_tools_see_meshes_materials_and_no_validation_problem(saved_steps, name):
    scene, path = saved_steps[name]
    stage = open_plain(path)
    problems = validation_problems(stage)
    assert not problems, f"{name}: usd-core's validators report:\n" + "\n".join(problems)
    cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [UsdGeom.Tokens.default_])
    drawn = [e for e in scene.entities if scene.try_component(e, MeshComponent) is not None]
    visible = [p for p in stage.Traverse() if p.IsA(UsdGeom.Mesh)
               and UsdGeom.Imageable(p).ComputeVisibility() != UsdGeom.Tokens.invisible]
    assert len(visible) == len(drawn), f"{name}: {len(drawn)} entities draw a mesh, {len(visible)} visible Mesh prims"
    for prim in visible:
        mesh = UsdGeom.Mesh(prim)
        ok, why = UsdGeom.Mesh.ValidateTopology(mesh.GetFaceVertexIndicesAttr().Get(),
                                                mesh.GetFaceVertexCountsAttr().Get(), len(mesh.GetPointsAttr().Get()))
        assert ok, f"{name}: {prim.GetPath()}: {why}"
        box = cache.ComputeWorldBound(prim).ComputeAlignedRange()
        assert not box.IsEmpty() and max(box.GetSize()) > 0, f"{name}: {prim.GetPath()} has an empty bound {box}"
        entity = prim.GetParent()
        if entity.GetAttribute("gandalf:material").HasAuthoredValue():
            material, _ = UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial()
            assert material, f"{name}: {prim.GetPath()} has no bound material"
    materials = [p for p in stage.Traverse() if p.IsA(UsdShade.Material)]
    assert len(materials) == len(scene.assets.materials)
    for prim in materials:
        surface = UsdShade.Material(prim).ComputeSurfaceSource()[0]
        assert surface and surface.GetIdAttr().Get() == "UsdPreviewSurface", f"{name}: {prim.GetPath()}"


def test_preview_surface_network_of_a_textured_material(saved_steps):
    scene, path = saved_steps["step03_textures"]
    stage = open_plain(path)
    textured = [(n, m) for n, m in scene.assets.materials.items()
                if m.textures and m.textures[0] in scene.assets.textures
                and scene.assets.textures[m.textures[0]].__class__.__name__ == "TextureData"]
    assert textured, "step 03 has textured materials"
    name, data = textured[0]
    material = next(UsdShade.Material(p) for p in stage.Traverse() if p.IsA(UsdShade.Material)
                    and p.GetAttribute("gandalf:name").Get() == name)
    surface = material.ComputeSurfaceSource()[0]
    source = surface.GetInput("diffuseColor").GetConnectedSources()[0][0].source
    texture = UsdShade.Shader(source.GetPrim())
    assert texture.GetIdAttr().Get() == "UsdUVTexture"
    file = texture.GetInput("file").Get()
    assert Path(file.resolvedPath).is_file(), f"{file} resolves to a file"
    reader = UsdShade.Shader(texture.GetInput("st").GetConnectedSources()[0][0].source.GetPrim())
    assert reader.GetIdAttr().Get() == "UsdPrimvarReader_float2" and reader.GetInput("varname").Get() == "st"


@pytest.mark.parametrize("name", list(SCENES))
def test_save_load_save_gives_the_same_file(saved_steps, tmp_path, name):
    scene, first = saved_steps[name]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        loaded = load_scene(first, strict=False)
    second = quiet_save(loaded, tmp_path / f"{name}.usda")
    a = first.read_text("utf-8").replace(f"{first.stem}_usda_textures", "TEXTURES")
    b = second.read_text("utf-8").replace(f"{second.stem}_usda_textures", "TEXTURES")
    if a != b:
        diff = [f"{x!r} != {y!r}" for x, y in zip(a.splitlines(), b.splitlines()) if x != y][:5]
        pytest.fail(f"{name}: the second save differs: {diff}")
    tex_a, tex_b = first.parent / f"{first.stem}_usda_textures", tmp_path / f"{name}_usda_textures"
    if tex_a.exists():
        files = sorted(p.name for p in tex_a.iterdir())
        assert files == sorted(p.name for p in tex_b.iterdir())
        for f in files:
            assert (tex_a / f).read_bytes() == (tex_b / f).read_bytes(), f"{name}: texture {f}"
    # The loaded scene holds the same entities with the same meshes and materials.
    def summary(s: Scene) -> list[tuple]:
        rows = []
        for e in s.entities:
            info, mesh = s.try_component(e, InfoComponent), s.try_component(e, MeshComponent)
            mat = s.try_component(e, MaterialComponent)
            rows.append((info.name if info else "", mesh.mesh if mesh else "", mat.material if mat else ""))
        return sorted(rows)

    assert summary(loaded) == summary(scene)


def test_old_files_without_mesh_prims_still_load(tmp_path):
    """A file written before entities had visible Mesh children (no `mesh` child) loads the same."""
    scene = SCENES["step04_camera"]()
    path = quiet_save(scene, tmp_path / "s.usda")
    layer = Sdf.Layer.OpenAsAnonymous(str(path))
    stage = Usd.Stage.Open(layer)
    marked = [p.GetPath() for p in stage.Traverse() if p.GetAttribute("gandalf:entityMesh").HasAuthoredValue()]
    assert marked
    for prim_path in marked:
        stage.RemovePrim(prim_path)
    layer.Export(str(path))
    assert "gandalf:entityMesh" not in path.read_text("utf-8")
    loaded = load_scene(path, strict=False)
    assert len(loaded) == len(scene)
    assert np.array_equal(sorted(loaded.assets.meshes), sorted(scene.assets.meshes))


def test_cube_texture_mip_levels_round_trip(tmp_path):
    """Explicit cube mip levels (a prefiltered environment) are saved as 6 PNGs per level and come back exactly."""
    from gandalf_core.resources import CubeTextureData, sky_cube

    sky = sky_cube(16)
    rng = np.random.default_rng(2)
    levels = tuple(rng.integers(0, 256, (6, 16 >> k, 16 >> k, 4), dtype=np.uint8) for k in (1, 2, 3, 4))
    scene = Scene("levels")
    scene.assets.texture("prefiltered", CubeTextureData(sky.faces, levels=levels, name="prefiltered"))
    scene.assets.texture("plain", sky)
    path = save_scene(scene, tmp_path / "l.usda")
    loaded = load_scene(path).assets.textures
    assert len(loaded["prefiltered"].levels) == 4
    for k, (a, b) in enumerate(zip(levels, loaded["prefiltered"].levels), start=1):
        assert np.array_equal(a, b), f"mip level {k} (must be exact)"
    assert loaded["plain"].levels is None
    assert len(list((tmp_path / "l_usda_textures").glob("prefiltered_mip*_*.png"))) == 24
