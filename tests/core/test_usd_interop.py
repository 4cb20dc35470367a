"""USD that other tools show.

Each step's scene (the savable ones of ``test_usd_behaviour``, and step 07's showcase without its compute-driven
particle system) is saved and opened with plain ``pxr`` (no gandalf code): every entity with a mesh has a visible
``UsdGeom.Mesh`` child with a non-empty world bound (``UsdGeom.BBoxCache``) and a valid topology
(``UsdGeom.Mesh.ValidateTopology``), every material has a ``UsdPreviewSurface`` surface shader, and usd-core's
validators (all of ``UsdValidation.ValidationRegistry().GetOrLoadAllValidators()``) report no error or warning.

save -> load -> save of every step's scene (with its systems, and the animation afterwards) is tested in
``test_usd_behaviour``.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
from test_usd_behaviour import SAVABLE, UNSAVEABLE, build  # the same folder: pytest puts it on sys.path

from gandalf_core import Scene
from gandalf_core.components import MeshComponent
from step07_advanced.usd import load_scene, save_scene

pxr = pytest.importorskip("pxr")
from pxr import Sdf, Usd, UsdGeom, UsdShade, UsdValidation  # noqa: E402


def _showcase_without_particles() -> Scene:
    """The showcase with its compute-driven particle system taken out (that system cannot be saved; see
    test_usd_behaviour): the rest of the scene is what other tools must show."""
    from step07_advanced.showcase.particles import ParticleSystem

    scene = UNSAVEABLE["step07_showcase"][0]()
    scene.remove_system(scene.get_system(ParticleSystem))
    return scene


SCENES = {**SAVABLE, "step07_showcase": _showcase_without_particles}


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
    for name, make in SCENES.items():
        try:
            scene = build(name) if name in SAVABLE else make()
            out[name] = (scene, quiet_save(scene, folder / f"{name}.usda"))
        except pytest.skip.Exception as skip:  # a step being split: test_usd_behaviour names why
            out[name] = skip
        except Exception as exc:  # noqa: BLE001 - one scene's failure fails its own tests only
            out[name] = exc
    return out


def saved_step(saved_steps: dict, name: str) -> tuple[Scene, Path]:
    entry = saved_steps[name]
    if isinstance(entry, pytest.skip.Exception):
        pytest.skip(f"{name}: {entry}")
    if isinstance(entry, Exception):
        pytest.fail(f"{name}: building or saving the scene failed: {type(entry).__name__}: {entry}")
    return entry


@pytest.mark.parametrize("name", list(SCENES))
def test_other_tools_see_meshes_materials_and_no_validation_problem(saved_steps, name):
    scene, path = saved_step(saved_steps, name)
    assert_other_tools_see(name, scene, path)


def assert_other_tools_see(name: str, scene: Scene, path: Path) -> None:
    """``path`` (saved from ``scene``) opened with plain pxr: no validation problem, a visible Mesh with a non-empty
    bound and a valid topology per drawn entity, a bound material where the entity has one, and a
    UsdPreviewSurface per material."""
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
    scene, path = saved_step(saved_steps, "step03_textures")
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
