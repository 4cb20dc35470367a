"""GPU-driven motion: the same spinning cubes turned per entity on the CPU, batched with numpy, and by the
technique's compute pass must give the same picture at the same time t, in both APIs.

Tolerance (argued from float32): the CPU packs float64 matrices rounded once to float32; the kernel turns the
float32 rows of the starting pose by a float32 rotation, a few ulp (≤ 1e-6 relative) away. A vertex then moves
≤ 1e-6 · 10 units = 1e-5 units, 1e-5 · (120 px / (2 tan 25° · 8 units)) ≈ 2e-4 px on screen: a pixel changes
coverage only when its centre lies that close to an edge, about perimeter · 2e-4 ≈ 0.5 pixels of a 160×120 frame,
and shading (normals of the same relative error) moves a colour by far less than 1/255. So: no channel more than
1/255 apart except on at most 0.2 % of the pixels (38), where an edge may pass either side of a pixel centre.
Measured: identical on llvmpipe and lavapipe.
"""

from __future__ import annotations

import numpy as np
import pytest

from gandalf_core import Application, TransformComponent
from gandalf_core.components import MaterialComponent, MeshComponent
from gandalf_core.ecs import LinkComponent
from gandalf_core.math import quat_from_axis_angle, quat_mul, trs
from gandalf_core.render.frame import pack_instances
from gandalf_core.systems.spin import SpinComponent, SpinSystem
from step07_advanced.gpu_motion.motion import MOTION_EPOCH, GpuMotion, motion_rows, spin_rows_np
from step07_advanced.gpu_motion.scene import build_scene
from step07_advanced.gpu_motion.system import GpuSpinSystem

W, H = 160, 120
FRAMES = 40
COUNT = 64
MAX_FLIPPED = int(0.002 * W * H)


def render(backend: str, path: str, frames: int = FRAMES, start: float = 0.0, count: int = COUNT,
           local: bool = False, late: int = 0):
    """The scene after ``frames`` frames; ``late`` more cubes join (in front) after the first frames."""
    app = Application(backend, W, H, headless=True, fixed_dt=1 / 60)
    try:
        app.clock.time = start
        scene = build_scene(path=path, count=count, local=local)
        app.add_scene(scene)
        app.step()
        first = app.capture()
        for frame in range(frames - 1):
            if late and frame == frames // 2:
                for k in range(late):
                    scene.create_entity(TransformComponent((1.2 * k - 1.0, 0.8, 4.0), (10.0 * k, 0, 0), 0.4),
                                        MeshComponent("cube"), MaterialComponent("cube"),
                                        SpinComponent((1.0, 0.5 * k, 0.2), 90.0 + 20 * k, local=local))
            app.step()
        return first, app.capture(), dict(app.renderer.stats)
    finally:
        app.close()


def assert_same(got: np.ndarray, expected: np.ndarray, what: str) -> None:
    diff = np.abs(got.astype(int) - expected.astype(int)).max(axis=-1)
    flipped = int(np.count_nonzero(diff > 1))
    assert flipped <= MAX_FLIPPED, f"{what}: {flipped} pixels differ by more than 1/255 (allowed {MAX_FLIPPED})"


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_gpu_animated_cubes_match_the_cpu_animated_ones(backend: str) -> None:
    first, cpu, cpu_stats = render(backend, "entity")
    _first, batch, _ = render(backend, "batch")
    gpu_first, gpu, gpu_stats = render(backend, "gpu")
    assert np.count_nonzero(np.any(cpu != first, axis=-1)) > 200, "the cubes did not turn: nothing is compared"
    assert_same(gpu_first, first, "first frame, gpu against entity")
    assert_same(batch, cpu, f"frame {FRAMES}, batch against entity")
    assert_same(gpu, cpu, f"frame {FRAMES}, gpu against entity")
    # The structure: the GPU path turns the cubes in a compute pass and uploads no instance row after the first.
    assert gpu_stats["motion_passes"] == FRAMES and gpu_stats["instances_uploaded"] == 0
    assert cpu_stats.get("motion_passes", 0) == 0 and cpu_stats["instances_uploaded"] == COUNT


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_the_motion_epoch_rolls_over_without_a_jump(backend: str) -> None:
    start = MOTION_EPOCH - 0.25  # 15 frames before the epoch ends, 25 after
    _first, cpu, _ = render(backend, "entity", start=start)
    _first, gpu, _ = render(backend, "gpu", start=start)
    assert_same(gpu, cpu, f"across the epoch at {MOTION_EPOCH} s")


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_local_spins_and_cubes_that_join_later_match_the_cpu(backend: str) -> None:
    """A local axis becomes the world axis R0·a once; cubes created mid-run start turning from their own pose."""
    _first, cpu, _ = render(backend, "entity", count=27, local=True, late=2)
    _first, gpu, stats = render(backend, "gpu", count=27, local=True, late=2)
    assert_same(gpu, cpu, "local spins, two cubes joining at frame 20")
    assert stats["instances_uploaded"] == 0  # after the joining frame, nothing is uploaded again


def test_the_kernel_reference_matches_the_quaternion_spin() -> None:
    """The kernel's arithmetic (``spin_rows_np``, Rodrigues on the rows) is the quaternion product the CPU path
    applies, for world and local axes, with phases taken at an epoch in float64."""
    rng = np.random.default_rng(5)
    n = 20
    q0 = rng.normal(size=(n, 4))
    q0 /= np.linalg.norm(q0, axis=1, keepdims=True)
    t = rng.normal(size=(n, 3)) * 10
    s = rng.uniform(0.5, 2.0, (n, 3))
    axes = rng.normal(size=(n, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    speeds = rng.uniform(-3.0, 3.0, n)
    joined = rng.uniform(0.0, 500.0, n)
    time = 3000.0 + 0.123
    epoch = 2 * MOTION_EPOCH
    rows = motion_rows(n, np.arange(n), [GpuMotion(np.arange(n), axes, speeds, joined)], epoch)
    angles = rows[:, 3].astype(np.float64) * (time - epoch) + rows[:, 4]
    world = np.stack([trs(t[i], q0[i], s[i]) for i in range(n)])
    got = spin_rows_np(pack_instances(world, np.arange(n)).astype(np.float64), rows[:, :3], angles)
    expected = np.stack([trs(t[i], quat_mul(quat_from_axis_angle(axes[i], speeds[i] * (time - joined[i])), q0[i]),
                             s[i]) for i in range(n)])
    np.testing.assert_allclose(got, pack_instances(expected, np.arange(n)), atol=2e-4)


def test_the_gpu_path_refuses_an_entity_in_a_hierarchy() -> None:
    scene = build_scene(path="gpu", count=8)
    spinning = scene.query(SpinComponent, TransformComponent).entities
    parent = scene.create_entity(TransformComponent())
    scene.add_component(spinning[3], LinkComponent(parent))
    system = next(s for s in scene.systems if isinstance(s, GpuSpinSystem))
    with pytest.raises(ValueError, match=r"GpuSpinSystem turns root entities"):
        system.gpu_motion()


def test_a_spin_system_names_a_path_it_does_not_have() -> None:
    with pytest.raises(ValueError, match="path must be one of entity, batch, got 'cuda'"):
        SpinSystem(path="cuda")


def test_a_saved_scene_keeps_the_path_its_spin_system_takes(tmp_path) -> None:
    from step07_advanced.usd import load_scene, save_scene

    for path in ("gpu", "batch"):
        saved = save_scene(build_scene(path=path, count=8), tmp_path / f"{path}.usda")
        loaded = load_scene(saved)
        (system,) = [s for s in loaded.systems if isinstance(s, SpinSystem)]
        assert system.path == path


def test_more_instances_than_one_dispatch_or_binding_holds_is_an_error_naming_the_limit() -> None:
    from types import SimpleNamespace

    from step07_advanced.gpu_motion.motion_wgpu import WGPUMotionPass

    motion = object.__new__(WGPUMotionPass)
    motion.device = SimpleNamespace(limits={"max-compute-workgroups-per-dimension": 65535,
                                            "max-storage-buffer-binding-size": 2**31})
    motion._check_limits(None, 65535 * 64)  # the largest count one dispatch covers
    with pytest.raises(ValueError, match=r"65537 workgroups of 64, more than this device dispatches at once \(65535\)"):
        motion._check_limits(None, 65536 * 64 + 1)
    motion.device.limits["max-storage-buffer-binding-size"] = 134217728  # WebGPU's default: 2,796,202 instances
    motion._check_limits(None, 134217728 // 48)
    with pytest.raises(ValueError, match=r"instance rows \(134217744 bytes\) are more than this device binds"):
        motion._check_limits(None, 134217728 // 48 + 1)


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_the_motion_pass_reports_its_buffers_in_the_renderers_gpu_memory(backend: str) -> None:
    """The pass's buffers: its motion rows (2 vec4 an instance), the moved rows (as large as the instance buffer they
    are read instead of) and its small parameter block, under the kernel's name."""
    with Application(backend, W, H, headless=True, fixed_dt=1 / 60) as app:
        app.add_scene(build_scene(path="gpu", count=COUNT))
        app.step()
        held = app.renderer.gpu_memory()
        rows_and_moved = COUNT * 32 + held["instances"]
        assert rows_and_moved < held["motion_spin"] <= rows_and_moved + 64
        assert held["total"] == sum(v for k, v in held.items() if k != "total")
