"""Step 06's meshes (not graded: no exercise of its own): the bunny file, its parts placed by their node
transforms, the script that writes it, and the concept's picture in both APIs.

Pictures (160 × 120, 30 frames): the two APIs agree to PSNR ≥ 40 dB (measured on llvmpipe/lavapipe: 94.0 dB,
largest channel difference 1) and OpenGL matches ``references/step06_lighting-meshes-opengl.png`` to ≥ 40 dB.
"""

from __future__ import annotations

import numpy as np
import pytest
from step06_helpers import check_concept_apis_agree, check_concept_reference

from gandalf_core import InfoComponent, TransformComponent, TransformSystem
from gandalf_core.components import LinkComponent, MeshComponent
from gandalf_core.resources.mesh_loader import load_mesh, load_meshes
from step06_lighting.meshes import make_bunny
from step06_lighting.meshes.scene import BUNNY_PATH, PART_COLORS, build_scene

PART = "step06_lighting.meshes"


def test_bunny_model_is_small_and_has_five_parts():
    assert BUNNY_PATH.stat().st_size < 200_000
    parts = load_meshes(BUNNY_PATH)
    assert sorted(parts) == ["body", "ear_left", "ear_right", "head", "tail"]
    # The node transforms place the parts: the ears are the highest, the bunny stands on y = 0.
    tops = {name: mesh.bounds()[1][1] for name, mesh in parts.items()}
    assert max(tops, key=tops.get).startswith("ear")
    assert min(mesh.bounds()[0][1] for mesh in parts.values()) == pytest.approx(0.0, abs=0.02)


def test_the_parts_hang_from_one_parent_and_make_the_whole_bunny():
    scene = build_scene()
    scene.add_system(TransformSystem())
    scene.update(0.0)
    names = {entity: info.name for entity, (info,) in scene.view(InfoComponent)}
    parent = next(entity for entity, name in names.items() if name == "bunny")
    parts = [(names[e], link) for e, (link,) in scene.view(LinkComponent) if link.parent is not None]
    assert sorted(name for name, _ in parts) == sorted(PART_COLORS)
    assert all(link.parent == parent for _, link in parts), "every part hangs from the bunny entity"
    # The parts' vertices already carry their node transforms: together they span the merged bunny.
    low = np.min([load_meshes(BUNNY_PATH)[name].bounds()[0] for name in PART_COLORS], axis=0)
    high = np.max([load_meshes(BUNNY_PATH)[name].bounds()[1] for name in PART_COLORS], axis=0)
    merged = load_mesh(BUNNY_PATH).bounds()
    assert np.allclose(low, merged[0], atol=1e-6) and np.allclose(high, merged[1], atol=1e-6)
    meshes = {mesh.mesh for (mesh,) in scene.query(MeshComponent).components}
    assert {"sphere 8x4", "sphere 64x32"} <= meshes
    world = scene.get_component(parent, TransformComponent).world
    assert np.allclose(world[:3, 3], (-1.3, 0.0, 0.0))


def test_make_bunny_writes_the_committed_model_and_help_only_helps(tmp_path, capsys):
    out = tmp_path / "bunny.glb"
    before = BUNNY_PATH.stat().st_mtime_ns
    assert make_bunny.main(["--out", str(out)]) == 0
    fresh, committed = load_meshes(out), load_meshes(BUNNY_PATH)
    assert sorted(fresh) == sorted(committed)
    for name in committed:
        assert np.allclose(fresh[name].positions, committed[name].positions, atol=1e-6), name
    with pytest.raises(SystemExit) as stop:
        make_bunny.main(["--help"])
    assert stop.value.code == 0 and "--out" in capsys.readouterr().out
    assert BUNNY_PATH.stat().st_mtime_ns == before, "the committed model was rewritten"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bunny.glb"]


def test_both_apis_draw_the_same_meshes():
    check_concept_apis_agree(PART, "meshes")


def test_the_meshes_match_their_reference():
    check_concept_reference(PART, "meshes")
