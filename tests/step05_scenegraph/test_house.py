"""Grades the house capstone, milestone by milestone, by rendering it headless in both APIs.

Each milestone is graded on its own: the test takes that one part from the implementation under test and
the other four from the reference, so a student earns each milestone's points independently.
"""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from PIL import Image

import step05_scenegraph
from gandalf_core import Application
from gandalf_core.app.cli import load_impl
from gandalf_core.math import quat_from_axis_angle
from gandalf_core.resources import MaterialData, MeshData, TextureData
from gandalf_tools.testing import compare_images, compare_to_reference, psnr, save_failure, shown_failure
from step05_scenegraph import SHADERS
from step05_scenegraph.house.components import HouseRotationComponent
from step05_scenegraph.house.scene import build_house_scene

# The other milestones (the reference solutions; in a student's release, which has none, the student's own).
reference = load_impl("step05_scenegraph")
REFERENCES = Path(__file__).parent / "references"
SHADER_DIR = Path(step05_scenegraph.__file__).resolve().parent / "shaders"
W, H = 96, 72
# The house image vs. its committed reference: software rasterisers agree to the byte here; 35 dB leaves
# room for a different driver's rounding without letting a misplaced roof or a flat texture through.
REFERENCE_PSNR = 35.0
#: The brick texture's colours (sRGB) and how far a texel may stray from them, per channel, as the stub states.
BRICK_COLOUR, BRICK_RANGE = (0.62, 0.24, 0.17), 0.1
MORTAR_COLOUR, MORTAR_RANGE = (0.82, 0.80, 0.75), 0.05
PARTS = ("house_meshes", "brick_texture_data", "house_material_data", "house_camera", "HouseRotationSystem")


def mixed(impl, part: str) -> SimpleNamespace:
    """The reference house with ``part`` taken from ``impl``."""
    parts = {name: getattr(reference, name) for name in PARTS}
    parts[part] = getattr(impl, part)
    return SimpleNamespace(**parts)


def house_app(parts, backend: str, width: int = W, height: int = H) -> tuple[Application, object]:
    app = Application(backend, width, height, headless=True, fixed_dt=1 / 60)
    for name in SHADERS:
        if backend == "opengl":
            app.renderer.shaders.build(name, SHADER_DIR / f"{name}.vert", SHADER_DIR / f"{name}.frag")
        else:
            app.renderer.shaders.build(name, SHADER_DIR / f"{name}.wgsl")
    scene = app.add_scene(build_house_scene(parts))
    return app, scene


def render(parts, backend: str, frames: int = 1, **size) -> np.ndarray:
    app, _ = house_app(parts, backend, **size)
    with app:
        app.run(frames=frames)
        return app.capture()


def masks(image: np.ndarray) -> dict[str, np.ndarray]:
    """Pixel classes: orange roof, red-brown brick (with mortar blended in), light-blue sky."""
    r, g, b = (image[..., i].astype(float) for i in range(3))
    return {
        "orange": (r > 90) & (b < 0.15 * r) & (g > 0.3 * r) & (g < 0.7 * r),
        "brick": (r > 40) & (r > 1.1 * g) & (b >= 0.15 * r),  # mortar blended in (minified texture) lowers r / g
        "sky": (b > r) & (b > 150),
    }


def centroid_row(mask: np.ndarray) -> float:
    return float(np.nonzero(mask)[0].mean())


def _in_picture(image: np.ndarray, text: str) -> str:
    """A failed check of the house picture in words: the picture drawn (the input), then ``text`` (got against
    expected), and where the picture and the reference were saved side by side."""
    saved = shown_failure(save_failure(image, np.asarray(Image.open(REFERENCES / "house.png").convert("RGBA"))))
    return f"for the house drawn {image.shape[1]}x{image.shape[0]}: {text}; pictures: {saved}"


def check_house_picture(image: np.ndarray) -> None:
    """Roof orange region above the brick region, both of a plausible size, sky around."""
    m = masks(image)
    total = image.shape[0] * image.shape[1]
    for part, low, high in (("orange", 0.03, 0.3), ("brick", 0.05, 0.4)):
        count = int(m[part].sum())
        assert low * total < count < high * total, _in_picture(
            image, f"got {count} {part} pixels, expected {low:.0%} to {high:.0%} of {total} ({part} = "
                   f"{'roof' if part == 'orange' else 'walls'})")
    roof, walls = centroid_row(m["orange"]), centroid_row(m["brick"])
    assert roof < walls - 5, _in_picture(
        image, f"got the roof's centre at row {roof:.0f} and the walls' at row {walls:.0f}, expected the roof above "
               f"the walls (more than 5 rows)")
    assert m["sky"][0].all() and m["sky"][-1].all(), _in_picture(
        image, f"got {int((~m['sky'][0]).sum())} house pixels in the top row and {int((~m['sky'][-1]).sum())} in the "
               f"bottom row, expected none (the house must not touch the top or bottom edge)")


def check_milestone_render(impl, part: str, backend: str) -> None:
    """The house with the student's ``part`` renders as a house, and as the reference picture."""
    image = render(mixed(impl, part), backend)
    check_house_picture(image)
    compare_to_reference(image, REFERENCES / "house.png", min_psnr=REFERENCE_PSNR)


# --- milestone 1: attributes ------------------------------------------------------------------------------
@pytest.mark.exercise("house_meshes")
def test_house_meshes_are_placed_and_scaled(impl):
    walls, roof = impl.house_meshes()
    assert isinstance(walls, MeshData) and isinstance(roof, MeshData)
    lo, hi = walls.bounds()
    assert np.allclose(lo, (-0.5, 0.0, -0.5), atol=1e-6) and np.allclose(hi, (0.5, 1.0, 0.5), atol=1e-6)
    lo, hi = roof.bounds()
    assert np.allclose(lo, (-0.65, 1.0, -0.65), atol=1e-6) and np.allclose(hi, (0.65, 1.7, 0.65), atol=1e-6)
    for mesh in (walls, roof):
        assert mesh.normals is not None and mesh.uvs is not None, "keep the normals and uvs"
    assert walls.triangle_count == 12 and roof.triangle_count == 6


@pytest.mark.exercise("house_meshes")
def test_house_meshes_render(impl, backend):
    check_milestone_render(impl, "house_meshes", backend)


# --- milestone 2: textures --------------------------------------------------------------------------------
def _runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """(start, length) of each run of True in ``flags``, read cyclically (a texture wraps: a run may cross the
    edge); the whole array True is one run starting at 0."""
    n = len(flags)
    if flags.all():
        return [(0, n)]
    first_false = int(np.argmin(flags))
    rolled = np.roll(flags, -first_false)
    runs, start = [], None
    for i, flag in enumerate(np.append(rolled, False)):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            runs.append(((start + first_false) % n, i - start))
            start = None
    return runs


def _cyclic_distance(a: float, b: float, period: float) -> float:
    d = (a - b) % period
    return min(d, period - d)


def check_brick_texture(texture, size: int) -> None:
    """The stub's properties, not one picture: brick and mortar colours within the stated ranges, four courses
    separated by 2-texel bed joints, 2-texel head joints evenly spaced along each course, and every other course
    shifted by half a brick. Where the joints sit (top or bottom of a course, left or right of a brick) and how
    many bricks a course holds are the student's choice."""
    assert isinstance(texture, TextureData), f"expected a TextureData, got {type(texture).__name__}"
    assert texture.pixels.shape == (size, size, 4), f"brick_texture_data({size}): {texture.pixels.shape}"
    assert texture.name == "house.brick", f"name {texture.name!r}, expected 'house.brick'"
    rgb = texture.pixels[..., :3].astype(int)
    brick = np.all(np.abs(rgb - np.round(255 * np.array(BRICK_COLOUR))) <= 255 * BRICK_RANGE + 1, axis=-1)
    mortar = np.all(np.abs(rgb - np.round(255 * np.array(MORTAR_COLOUR))) <= 255 * MORTAR_RANGE + 1, axis=-1)
    odd = ~(brick | mortar)
    assert not odd.any(), (
        f"got {int(odd.sum())} texels that are neither brick nor mortar, e.g. {rgb[odd][0].tolist()} at "
        f"{np.argwhere(odd)[0].tolist()}; expected each texel brick (sRGB {BRICK_COLOUR} within {BRICK_RANGE}) or "
        f"mortar ({MORTAR_COLOUR} within {MORTAR_RANGE})")
    beds = _runs(mortar.all(axis=1))
    assert len(beds) == 4 and all(length == 2 for _, length in beds), (
        f"bed joints (rows of mortar, start and height): {beds}; expected four joints 2 texels high (four courses)")
    heads, period = [], None
    for (start, length), (following, _) in zip(beds, beds[1:] + beds[:1]):
        rows = [(start + length + i) % size for i in range((following - start - length) % size)]
        column_joint = mortar[rows].all(axis=0)
        assert np.array_equal(mortar[rows], np.broadcast_to(column_joint, (len(rows), size))), (
            f"course at rows {rows[0]}..{rows[-1]}: mortar texels that are not part of a whole head joint")
        joints = _runs(column_joint)
        assert joints and all(length == 2 for _, length in joints), (
            f"course at rows {rows[0]}..{rows[-1]}: head joints (start, width) {joints}; expected 2 texels wide")
        starts = [s for s, _ in joints]
        spacing = [(b - a) % size or size for a, b in zip(starts, starts[1:] + starts[:1])]
        assert max(spacing) - min(spacing) <= 1, f"course at rows {rows[0]}..{rows[-1]}: uneven bricks {spacing}"
        period = period or size / len(starts)
        assert abs(size / len(starts) - period) < 1e-9, "every course holds the same number of bricks"
        heads.append(starts[0])
    for k in range(4):
        offset = _cyclic_distance(heads[(k + 1) % 4], heads[k], period)
        assert abs(offset - period / 2) <= 1, (
            f"head joints of neighbouring courses are {offset:g} texels apart, expected half a brick ({period / 2:g})")


@pytest.mark.exercise("brick_texture_data")
@pytest.mark.parametrize("size", [64, 128])
def test_brick_texture_has_the_stated_properties(impl, size):
    check_brick_texture(impl.brick_texture_data(size) if size != 64 else impl.brick_texture_data(), size)


@pytest.mark.exercise("brick_texture_data")
def test_brick_texture_renders(impl, backend):
    image = render(mixed(impl, "brick_texture_data"), backend)
    check_house_picture(image)
    brick = masks(image)["brick"]
    # A texture, not a flat colour: the walls vary in brightness (mortar lines).
    assert image[..., 1][brick].std() > 6.0


# --- milestone 3: shaders and colours -----------------------------------------------------------------------
@pytest.mark.exercise("house_material_data")
def test_house_materials(impl):
    materials = impl.house_material_data()
    walls, roof = materials["house.walls"], materials["house.roof"]
    assert isinstance(walls, MaterialData) and isinstance(roof, MaterialData)
    assert walls.shader == "shaded_textured" and walls.textures == ("house.brick",)
    assert roof.shader == "shaded" and np.allclose(roof.color, (1.0, 0.5, 0.0, 1.0))


@pytest.mark.exercise("house_material_data")
def test_house_materials_render(impl, backend):
    check_milestone_render(impl, "house_material_data", backend)


# --- milestone 4: camera ------------------------------------------------------------------------------------
@pytest.mark.exercise("house_camera")
def test_house_camera_is_perspective(impl):
    camera, transform = impl.house_camera(2.0)
    assert camera.projection == "perspective" and camera.aspect == 2.0
    assert impl.house_camera(None)[0].aspect is None


@pytest.mark.exercise("house_camera")
def test_house_camera_frames_the_house(impl, backend):
    image = render(mixed(impl, "house_camera"), backend)
    check_house_picture(image)
    house = ~masks(image)["sky"]
    rows, cols = np.nonzero(house)
    assert rows.min() >= 3 and rows.max() <= H - 4 and cols.min() >= 3 and cols.max() <= W - 4, _in_picture(
        image, f"got the house in rows {rows.min()}-{rows.max()}, columns {cols.min()}-{cols.max()}, expected a "
               f"margin of 3 pixels (rows 3-{H - 4}, columns 3-{W - 4})")
    assert 0.1 < house.mean() < 0.6, _in_picture(
        image, f"got the house over {house.mean():.0%} of the frame, expected 10% to 60%")
    assert abs(cols.mean() - W / 2) < 0.1 * W and abs(rows.mean() - H / 2) < 0.2 * H, _in_picture(
        image, f"got the house's centre at (x {cols.mean():.1f}, y {rows.mean():.1f}), expected within "
               f"({0.1 * W:.1f}, {0.2 * H:.1f}) pixels of the frame's centre ({W / 2:g}, {H / 2:g})")


# --- milestone 5: uniforms / interactivity -------------------------------------------------------------------
def _angle_about_y(q: np.ndarray, degrees: float) -> bool:
    expected = quat_from_axis_angle((0.0, 1.0, 0.0), math.radians(degrees))
    return abs(abs(float(np.dot(q, expected))) - 1.0) < 1e-9


@pytest.mark.exercise("HouseRotationSystem")
def test_house_turns_at_its_speed(impl):
    from gandalf_core import Scene, TransformComponent

    scene = Scene("turn")
    fast = scene.create_entity(HouseRotationComponent(speed=90.0), TransformComponent())
    slow = scene.create_entity(HouseRotationComponent(speed=-30.0, angle=10.0), TransformComponent())
    scene.add_system(impl.HouseRotationSystem())
    for _ in range(10):
        scene.update(0.1)  # no app: the system must still turn (no input to read)
    for entity, speed, degrees in ((fast, 90.0, 90.0), (slow, -30.0, -20.0)):
        q = scene.get_component(entity, TransformComponent).quaternion
        want = quat_from_axis_angle((0.0, 1.0, 0.0), math.radians(degrees))
        assert _angle_about_y(q, degrees), (
            f"HouseRotationSystem, speed {speed:g}°/s, after 10 updates of 0.1 s: got the quaternion "
            f"{np.round(q, 4).tolist()}, expected {np.round(want, 4).tolist()} ({degrees:g}° about +y, or -q)")
    angle = scene.get_component(fast, HouseRotationComponent).angle
    assert 0.0 <= angle < 360.0 and angle == pytest.approx(90.0, abs=1e-9)


@pytest.mark.exercise("HouseRotationSystem")
def test_rotation_changes_the_picture_at_known_times(impl, backend):
    parts = mixed(impl, "HouseRotationSystem")
    app, scene = house_app(parts, backend)
    with app:
        app.run(frames=1)
        start = app.capture()  # 0.75 degrees
        app.run(frames=30)
        turned = app.capture()  # 23.25 degrees: a different picture
        app.run(frames=90)
        quarter = app.capture()  # 90.75 degrees: the house is four-fold symmetric, same picture as at 0.75
        house = scene.query(HouseRotationComponent).entities[0]
    assert psnr(start, turned) < 25.0
    compare_images(quarter, start, f"house-quarter-turn-{backend}", min_psnr=40.0)
    assert scene.get_component(house, HouseRotationComponent).angle == pytest.approx(121 * 0.75, abs=1e-9)


@pytest.mark.exercise("HouseRotationSystem")
def test_pause_key_toggles_the_rotation(impl, backend):
    app, scene = house_app(mixed(impl, "HouseRotationSystem"), backend)
    house = scene.query(HouseRotationComponent).entities[0]
    rotation = scene.get_component(house, HouseRotationComponent)
    with app:
        app.run(frames=10)
        app.input.key("P")
        app.step()
        paused_angle = rotation.angle
        paused_image = app.capture()
        app.input.key("P", "release")
        app.run(frames=20)
        assert rotation.paused and rotation.angle == paused_angle
        compare_images(app.capture(), paused_image, f"house-paused-{backend}", min_psnr=60.0)
        app.input.key("P")
        app.run(frames=20)
        assert not rotation.paused and rotation.angle == pytest.approx(paused_angle + 20 * 0.75, abs=1e-9)


@pytest.mark.exercise("HouseRotationSystem")
@pytest.mark.parametrize(("speed", "start", "seconds", "expected"), [
    (90.0, 300.0, 1.0, 30.0),     # forwards past 360
    (-30.0, 10.0, 1.0, 340.0),    # backwards past 0
    (-720.0, 45.0, 1.0, 45.0),    # two whole turns backwards in one step
])
def test_the_angle_stays_in_0_360(impl, speed, start, seconds, expected):
    """The docstring's rule: advance the angle and "keep it in [0, 360)", whichever way the house turns."""
    from gandalf_core import Scene, TransformComponent

    scene = Scene("wrap")
    house = scene.create_entity(HouseRotationComponent(speed=speed, angle=start), TransformComponent())
    scene.add_system(impl.HouseRotationSystem())
    scene.update(seconds)
    angle = scene.get_component(house, HouseRotationComponent).angle
    assert 0.0 <= angle < 360.0 and angle == pytest.approx(expected, abs=1e-9), (
        f"speed {speed} from {start} for {seconds} s: expected {expected}, got {angle} (math.fmod keeps the sign: "
        "use Python's %, or add 360 to a negative result)")
    assert _angle_about_y(scene.get_component(house, TransformComponent).quaternion, expected)
