"""Tests of the backend-neutral resource data: textures, procedural generators, meshes, primitives, materials and
shader sources (validation messages, conversions, geometry conventions, the include line map)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from gandalf_core.resources import (
    ATTRIBUTE_LOCATIONS,
    CubeTextureData,
    MaterialData,
    MeshData,
    ResourceError,
    ShaderSource,
    TextureData,
    checkerboard,
    cube,
    cube_face_directions,
    format_compile_error,
    gradient,
    plane,
    pyramid,
    quad,
    sky_cube,
    solid,
    torus,
    triangle,
    uv_sphere,
    value_noise,
)

PRIMITIVES = {
    "triangle": triangle,
    "quad": quad,
    "cube": cube,
    "pyramid": pyramid,
    "plane": lambda: plane(2.0, 3),
    "uv_sphere": lambda: uv_sphere(1.0, 12, 6),
    "torus": lambda: torus(1.0, 0.3, 12, 8),
}


def rgba(h: int, w: int, value: int = 0) -> np.ndarray:
    return np.full((h, w, 4), value, dtype=np.uint8)


# --- errors -------------------------------------------------------------------------------------------------------


def test_resource_error_is_value_error_with_parts() -> None:
    err = ResourceError("texture 'a.png'", "wrap", "bad")
    assert isinstance(err, ValueError)
    assert str(err) == "texture 'a.png': wrap: bad"
    assert (err.resource, err.field, err.detail) == ("texture 'a.png'", "wrap", "bad")


# --- TextureData ---------------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("field", "value", "allowed"), [("wrap", "tile", "'clamp'"), ("filter", "cubic", "'nearest'")]
)
def test_texture_settings_validation_names_field_and_allowed_values(field: str, value: str, allowed: str) -> None:
    with pytest.raises(ResourceError, match=rf"texture 'bricks': {field}: '{value}'.*{allowed}"):
        TextureData(rgba(2, 2), name="bricks", **{field: value})


def test_texture_constructor_requires_rgba8() -> None:
    with pytest.raises(ResourceError, match=r"texture 'x': pixels: .*\(H, W, 4\).*float64"):
        TextureData(np.zeros((2, 2, 4)), name="x")
    with pytest.raises(ResourceError, match="pixels: image is empty"):
        TextureData(rgba(0, 3))


def test_texture_pixels_are_private_and_read_only() -> None:
    src = rgba(2, 3, 7)
    tex = TextureData(src)
    src[:] = 99
    assert tex.pixels.max() == 7
    assert not tex.pixels.flags.writeable
    assert tex.pixels.flags.c_contiguous
    assert (tex.width, tex.height) == (3, 2)


def test_from_array_grey_rgb_and_float_rounding() -> None:
    grey = TextureData.from_array(np.array([[0, 255]], dtype=np.uint8))
    assert grey.pixels.tolist() == [[[0, 0, 0, 255], [255, 255, 255, 255]]]
    rgb = TextureData.from_array(np.array([[[0.2, 0.5004, 1.0]]]))
    assert rgb.pixels.tolist() == [[[51, 128, 255, 255]]]  # 0.2*255 = 51, 0.5004*255 = 127.6 -> 128
    ints = TextureData.from_array(np.array([[[1, 2, 3, 4]]], dtype=np.int64))
    assert ints.pixels.tolist() == [[[1, 2, 3, 4]]]


@pytest.mark.parametrize(
    ("arr", "pattern"),
    [
        (np.array([[[0.1, np.nan, 0.2]]]), r"texture 'n': pixels: value at index \(0, 0, 1\) is nan"),
        (np.array([[1.5]]), r"pixels: float values must lie in \[0, 1\], found \[1.5, 1.5\]"),
        (np.array([[300]]), r"pixels: integer values must lie in \[0, 255\], found \[300, 300\]"),
        (np.zeros((2, 2, 2), dtype=np.uint8), r"pixels: shape \(2, 2, 2\) is not one of"),
        (np.zeros((2, 2), dtype=bool), r"pixels: dtype bool"),
    ],
)
def test_from_array_rejects_bad_input(arr: np.ndarray, pattern: str) -> None:
    with pytest.raises(ResourceError, match=pattern):
        TextureData.from_array(arr, name="n")


def test_png_round_trip(tmp_path: Path) -> None:
    rng = np.random.default_rng(1)
    tex = TextureData.from_array(rng.integers(0, 256, (5, 7, 4), dtype=np.uint8), wrap="clamp", name="rt")
    path = tmp_path / "rt.png"
    tex.save_png(path)
    back = TextureData.from_file(path, srgb=False)
    assert np.array_equal(back.pixels, tex.pixels)
    assert back.name == "rt.png"
    assert (back.srgb, back.wrap) == (False, "repeat")


def test_top_row_first_from_file(tmp_path: Path) -> None:
    img = Image.new("RGB", (1, 2))
    img.putpixel((0, 0), (255, 0, 0))  # top
    img.putpixel((0, 1), (0, 0, 255))  # bottom
    img.save(tmp_path / "tb.png")
    tex = TextureData.from_file(tmp_path / "tb.png")
    assert tex.pixels[0, 0].tolist() == [255, 0, 0, 255]
    assert tex.pixels[1, 0].tolist() == [0, 0, 255, 255]


def test_conversion_of_l_rgb_p_and_16_bit_images(tmp_path: Path) -> None:
    Image.new("L", (2, 2), 77).save(tmp_path / "l.png")
    Image.new("RGB", (2, 2), (10, 20, 30)).save(tmp_path / "rgb.png")
    pal = Image.new("P", (2, 1))
    pal.putpalette([0, 0, 0, 200, 100, 50] + [0] * 762)
    pal.putpixel((1, 0), 1)
    pal.save(tmp_path / "p.png", transparency=0)
    Image.fromarray(np.array([[0, 65535, 32896]], dtype=np.uint16)).save(tmp_path / "i16.png")
    Image.new("LA", (1, 1), (90, 30)).save(tmp_path / "la.png")
    Image.new("CMYK", (1, 1), (0, 0, 0, 0)).save(tmp_path / "cmyk.tiff")

    assert TextureData.from_file(tmp_path / "l.png").pixels[0, 0].tolist() == [77, 77, 77, 255]
    assert TextureData.from_file(tmp_path / "rgb.png").pixels[1, 1].tolist() == [10, 20, 30, 255]
    p = TextureData.from_file(tmp_path / "p.png").pixels
    assert p[0, 0].tolist() == [0, 0, 0, 0]  # palette index 0 is transparent
    assert p[0, 1].tolist() == [200, 100, 50, 255]
    i16 = TextureData.from_file(tmp_path / "i16.png").pixels
    assert i16[0, :, 0].tolist() == [0, 255, 128]  # 32896 / 257 = 128
    assert TextureData.from_file(tmp_path / "la.png").pixels.tolist() == [[[90, 90, 90, 30]]]
    assert TextureData.from_file(tmp_path / "cmyk.tiff").pixels.tolist() == [[[255, 255, 255, 255]]]


def test_from_file_errors_name_path_and_mode(tmp_path: Path) -> None:
    missing = tmp_path / "nope.png"
    with pytest.raises(ResourceError, match=r"texture 'nope.png': path: file not found: .*nope\.png"):
        TextureData.from_file(missing)
    corrupt = tmp_path / "corrupt.png"
    corrupt.write_bytes(b"\x89PNG\r\n\x1a\nnot really")
    with pytest.raises(ResourceError, match=r"path: cannot read image .*corrupt\.png"):
        TextureData.from_file(corrupt)
    Image.fromarray(np.full((2, 2), 0.5, dtype=np.float32), mode="F").save(tmp_path / "f.tiff")
    with pytest.raises(ResourceError, match=r"texture 'f.tiff': mode: .*f\.tiff.*'F'"):
        TextureData.from_file(tmp_path / "f.tiff")


def test_mip_levels_and_odd_chain_sizes() -> None:
    assert TextureData(rgba(256, 256)).mip_levels == 9
    assert TextureData(rgba(5, 3)).mip_levels == 3
    assert TextureData(rgba(5, 3), mipmaps=False).mip_levels == 1
    assert [lvl.shape for lvl in TextureData(rgba(5, 3)).mip_chain()] == [(5, 3, 4), (2, 1, 4), (1, 1, 4)]
    assert [lvl.shape[:2] for lvl in TextureData(rgba(1, 7)).mip_chain()] == [(1, 7), (1, 3), (1, 1)]
    assert len(TextureData(rgba(5, 3), mipmaps=False).mip_chain()) == 1


def test_mip_chain_box_filter_keeps_the_mean_for_odd_sizes() -> None:
    rng = np.random.default_rng(2)
    tex = TextureData.from_array(rng.integers(0, 256, (7, 5, 4), dtype=np.uint8), srgb=False)
    chain = tex.mip_chain()
    mean0 = chain[0].astype(float).mean(axis=(0, 1))
    for level in chain[1:]:
        # Exact area weights preserve the mean; only 8-bit rounding of each texel remains (<= 0.5 each).
        assert np.allclose(level.astype(float).mean(axis=(0, 1)), mean0, atol=0.5)


def test_mip_chain_averages_srgb_in_linear_light() -> None:
    black_white = np.zeros((2, 2, 4), dtype=np.uint8)
    black_white[..., 3] = 255
    black_white[0, 0, :3] = black_white[1, 1, :3] = 255
    srgb_level = TextureData(black_white, srgb=True).mip_chain()[1][0, 0]
    data_level = TextureData(black_white, srgb=False).mip_chain()[1][0, 0]
    assert srgb_level.tolist() == [188, 188, 188, 255]  # linear 0.5 encodes to sRGB 0.7354 -> 188
    assert data_level.tolist() == [128, 128, 128, 255]


def test_cube_texture_validation_names_the_face() -> None:
    faces = [rgba(4, 4)] * 6
    assert CubeTextureData(tuple(faces)).size == 4
    with pytest.raises(ResourceError, match=r"cube texture 'sky': faces\[-Y\]: size 2x2 differs from face \+X"):
        CubeTextureData(tuple(faces[:3] + [rgba(2, 2)] + faces[4:]), name="sky")
    with pytest.raises(ResourceError, match=r"faces\[\+X\]: face must be square, got 4x2"):
        CubeTextureData(tuple([rgba(2, 4)] + faces[1:]))
    with pytest.raises(ResourceError, match="faces: expected 6 faces"):
        CubeTextureData(tuple(faces[:5]))
    with pytest.raises(ResourceError, match=r"faces\[\+Z\]: .*nan"):
        CubeTextureData.from_arrays([np.zeros((2, 2))] * 4 + [np.full((2, 2), np.nan), np.zeros((2, 2))])


def test_cube_texture_from_files(tmp_path: Path) -> None:
    paths = []
    for i, face in enumerate(("px", "nx", "py", "ny", "pz", "nz")):
        paths.append(tmp_path / f"{face}.png")
        Image.new("RGB", (4, 4), (i * 40, 0, 0)).save(paths[-1])
    cube_tex = CubeTextureData.from_files(paths, name="env")
    assert [int(f[0, 0, 0]) for f in cube_tex.faces] == [0, 40, 80, 120, 160, 200]
    with pytest.raises(ResourceError, match=r"cube texture 'env': faces: expected 6 files"):
        CubeTextureData.from_files(paths[:5], name="env")
    with pytest.raises(ResourceError, match=r"cube texture 'env': path: file not found: .*gone\.png"):
        CubeTextureData.from_files(paths[:5] + [tmp_path / "gone.png"], name="env")


def test_a_cube_from_files_holds_paths_not_pixels_and_reads_them_again(tmp_path: Path) -> None:
    """The faces are checked when loaded and read again when asked (the upload, a save): the texture keeps none
    of their pixels, unless asked to; a file that changed size since is an error naming it."""
    from gandalf_core.resources.texture_data import FaceFiles

    paths = []
    for i in range(6):
        paths.append(tmp_path / f"f{i}.png")
        Image.new("RGBA", (4, 4), (i * 40, 7, 9, 255)).save(paths[-1])
    lazy = CubeTextureData.from_files(paths, name="env")
    assert isinstance(lazy.faces, FaceFiles) and lazy.size == 4 and lazy.mip_levels == 3
    kept = CubeTextureData.from_files(paths, name="env", keep_pixels=True)
    assert all(isinstance(f, np.ndarray) for f in kept.faces)
    assert np.array_equal(lazy.pixels, kept.pixels) and np.array_equal(lazy.mip_chain()[1], kept.mip_chain()[1])
    assert [int(f[0, 0, 0]) for f in lazy.faces[2:4]] == [80, 120]
    Image.new("RGBA", (8, 8)).save(paths[3])
    with pytest.raises(ResourceError, match=r"cube texture 'env': faces\[-Y\]: .*f3\.png' is now 8x8, was 4x4"):
        _ = lazy.pixels
    with pytest.raises(ResourceError, match=r"cube texture 'env': faces\[-Y\]: size 8x8 differs from face \+X"):
        CubeTextureData.from_files(paths, name="env")
    paths[5].write_bytes(b"not an image")
    with pytest.raises(ResourceError, match=r"cube texture 'env'.*f5\.png"):
        CubeTextureData.from_files(paths[:3] + paths[:2] + paths[5:], name="env")


@pytest.mark.parametrize("backend", ["opengl", "webgpu"])
def test_a_sky_from_files_draws_as_one_from_arrays(tmp_path: Path, backend: str) -> None:
    """Read face by face at the upload, the sky is the same picture as from the arrays held in memory."""
    from gandalf_core import Application, Scene, TransformComponent
    from gandalf_core.components import CameraComponent, SkyboxComponent

    rng = np.random.default_rng(5)
    paths = []
    for i in range(6):
        paths.append(tmp_path / f"f{i}.png")
        Image.fromarray(rng.integers(0, 256, (16, 16, 4), dtype=np.uint8)).save(paths[-1])
    pictures = []
    for keep in (False, True):
        app = Application(backend, 32, 24, headless=True)
        try:
            scene = Scene("sky")
            scene.assets.texture("sky", CubeTextureData.from_files(paths, name="sky", keep_pixels=keep))
            scene.create_entity(TransformComponent((0.0, 0.0, 0.0)), CameraComponent(70.0, 0.1, 10.0))
            scene.create_entity(SkyboxComponent("sky"))
            app.add_scene(scene)
            app.step()
            pictures.append(app.capture())
        finally:
            app.close()
    assert pictures[0].std() > 0 and np.array_equal(pictures[0], pictures[1])


def test_cube_mip_chain_and_stacked_pixels() -> None:
    cube_tex = CubeTextureData(tuple(rgba(8, 8, i * 10) for i in range(6)))
    assert cube_tex.pixels.shape == (6, 8, 8, 4)
    chain = cube_tex.mip_chain()
    assert [lvl.shape for lvl in chain] == [(6, s, s, 4) for s in (8, 4, 2, 1)]
    assert chain[-1][3, 0, 0, 0] == 30  # faces are filtered separately


def test_cube_face_directions_follow_the_gl_webgpu_convention() -> None:
    d = cube_face_directions(4)
    axes = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    centre = d[:, 1:3, 1:3].mean(axis=(1, 2))
    assert np.allclose(centre / np.linalg.norm(centre, axis=1, keepdims=True), axes, atol=1e-12)
    assert np.allclose(np.linalg.norm(d, axis=-1), 1.0)
    for side in (0, 1, 4, 5):  # side faces: top row looks up
        assert (d[side, 0, :, 1] > 0).all() and (d[side, -1, :, 1] < 0).all()
    assert (d[2, 0, :, 2] < 0).all()  # +Y: top row towards -Z
    assert (d[4, :, -1, 0] > 0).all()  # +Z: right column towards +X
    assert (d[0, :, -1, 2] < 0).all()  # +X: right column towards -Z


# --- procedural ----------------------------------------------------------------------------------------------------


def test_checkerboard_layout() -> None:
    tex = checkerboard(size=8, squares=4, color_a=(1, 0, 0), color_b=(0, 0, 1, 0.5))
    assert tex.pixels[0, 0].tolist() == [255, 0, 0, 255]
    assert tex.pixels[0, 2].tolist() == [0, 0, 255, 128]
    assert tex.pixels[2, 2].tolist() == [255, 0, 0, 255]
    assert tex.filter == "nearest"
    with pytest.raises(ResourceError, match=r"texture 'checkerboard': color_b: .*in \[0, 1\]"):
        checkerboard(color_b=(2, 0, 0))
    with pytest.raises(ResourceError, match="squares: must be an integer >= 1"):
        checkerboard(squares=0)


def test_gradient_solid_and_noise() -> None:
    g = gradient(size=4, start=(0, 0, 0), end=(1, 1, 1))
    assert g.pixels[0, 0, 0] < g.pixels[-1, 0, 0] and g.pixels[0, 0, 0] == g.pixels[0, -1, 0]
    h = gradient(size=4, direction="horizontal")
    assert h.pixels[0, 0, 0] < h.pixels[0, -1, 0]
    with pytest.raises(ResourceError, match="direction: 'diagonal'"):
        gradient(direction="diagonal")
    assert solid((0.2, 0.4, 0.6)).pixels.tolist() == [[[51, 102, 153, 255]]]

    a, b, c = value_noise(32, seed=5), value_noise(32, seed=5), value_noise(32, seed=6)
    assert np.array_equal(a.pixels, b.pixels) and not np.array_equal(a.pixels, c.pixels)
    assert a.srgb is False
    grey = a.pixels[..., 0].astype(float)
    # Tileable: the wrap-around step is no larger than the largest step inside the image.
    assert abs(grey[:, 0] - grey[:, -1]).max() <= abs(np.diff(grey, axis=1)).max()
    assert abs(grey[0] - grey[-1]).max() <= abs(np.diff(grey, axis=0)).max()


def test_sky_cube_is_deterministic_and_plausible() -> None:
    sky = sky_cube(16)
    assert np.array_equal(sky.pixels, sky_cube(16).pixels)
    top, bottom = sky.faces[2].astype(float), sky.faces[3].astype(float)
    assert top[..., 2].mean() > top[..., 0].mean() + 50  # blue zenith
    assert bottom[..., :3].mean() < top[..., :3].mean()  # darker ground
    sun_face = sky_cube(32, sun_direction=(0, 0, -1)).faces[5]
    brightness = sun_face[..., :3].astype(float).min(axis=-1)
    row, col = np.unravel_index(np.argmax(brightness), brightness.shape)
    assert brightness[row, col] > 240 and {row, col} <= {15, 16}  # the sun sits in the middle of -Z
    with pytest.raises(ResourceError, match="sun_direction"):
        sky_cube(8, sun_direction=(0, 0, 0))


# --- MeshData ------------------------------------------------------------------------------------------------------


def test_mesh_conversion_and_counts() -> None:
    mesh = MeshData(
        np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.int32), indices=np.array([[0, 1, 2]], np.int64)
    )
    assert mesh.positions.dtype == np.float32 and mesh.indices.dtype == np.uint32
    assert mesh.indices.shape == (3,)
    assert (mesh.vertex_count, mesh.index_count, mesh.triangle_count) == (3, 3, 1)
    lo, hi = mesh.bounds()
    assert lo.tolist() == [0, 0, 0] and hi.tolist() == [1, 1, 0]


@pytest.mark.parametrize(
    ("kwargs", "pattern"),
    [
        ({"positions": np.zeros((3, 2))}, r"mesh 'm': positions: expected shape \(N, 3\), got \(3, 2\)"),
        ({"normals": np.zeros((4, 3))}, r"mesh 'm': normals: has 4 rows but the mesh has N = 3 vertices"),
        ({"uvs": np.zeros((3, 3))}, r"uvs: expected shape \(N, 2\)"),
        ({"tangents": np.zeros((3, 3))}, r"tangents: expected shape \(N, 4\)"),
        ({"colors": [[0, 0, 0, 1]] * 2}, r"colors: has 2 rows but the mesh has N = 3"),
        ({"indices": [0, 1, 2, 0, 5, 1]}, r"indices: indices\[4\] = 5 is out of range for 3 vertices"),
        ({"indices": [0, -1, 2]}, r"indices\[1\] = -1 is out of range"),
        ({"indices": [0, 1, 2, 0]}, r"indices: index count 4 is not a positive multiple of 3"),
        ({"indices": [0.0, 1.0, 2.0]}, r"indices: dtype float64 is not an integer type"),
        ({"positions": [[0, 0, 0], [np.inf, 0, 0], [0, 1, 0]]}, r"positions: positions\[1, 0\] = inf"),
        ({"uvs": [[0, 0], [0, np.nan], [1, 1]]}, r"uvs: uvs\[1, 1\] = nan is not a finite"),
        ({"normals": [[0, 0, 1e39]] * 3}, r"normals: normals\[0, 2\] = 1e\+39 is not a finite float32"),
        ({"positions": np.zeros((4, 3))}, r"positions: 4 vertices without indices do not form whole triangles"),
    ],
)
def test_mesh_validation_names_the_attribute(kwargs: dict, pattern: str) -> None:
    fields = {"positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "name": "m", **kwargs}
    with pytest.raises(ResourceError, match=pattern):
        MeshData(**fields)


def test_mesh_arrays_are_read_only() -> None:
    mesh = quad()
    with pytest.raises(ValueError):
        mesh.positions[0, 0] = 5.0


@pytest.mark.parametrize("make", [cube, lambda: uv_sphere(2.0, 16, 8)])
def test_recomputed_normals_are_unit_and_point_outward(make) -> None:
    mesh = make().with_normals(recompute=True)
    n = mesh.normals.astype(float)
    assert np.allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-6)
    assert (np.sum(n * mesh.positions, axis=1) > 0).all()


def test_sphere_smooth_normals_match_the_radial_direction() -> None:
    sphere = uv_sphere(1.0, 32, 16)
    recomputed = sphere.with_normals(recompute=True).normals
    # Seam and pole vertices are split, so only the others see all their triangles.
    interior = (np.abs(sphere.positions[:, 1]) < 0.9) & (sphere.uvs[:, 0] > 0) & (sphere.uvs[:, 0] < 1)
    dots = np.sum(recomputed[interior] * sphere.normals[interior], axis=1)
    assert dots.min() > 0.995


def test_degenerate_triangles_give_no_nan() -> None:
    positions = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 2, 2], [2, 2, 2], [2, 2, 2], [5, 5, 5]]
    indices = [0, 1, 2, 3, 4, 5, 6, 6, 6]
    mesh = MeshData(positions, uvs=np.zeros((7, 2)), indices=indices).with_tangents()
    assert np.isfinite(mesh.normals).all() and np.isfinite(mesh.tangents).all()
    assert np.allclose(mesh.normals[:3], [0, 0, 1])
    assert np.allclose(mesh.normals[3:], [0, 1, 0])  # no usable triangle -> +Y
    t = mesh.tangents[:, :3]
    assert np.allclose(np.linalg.norm(t, axis=1), 1.0, atol=1e-6)
    assert np.allclose(np.sum(t * mesh.normals, axis=1), 0.0, atol=1e-6)  # fallback is perpendicular


@pytest.mark.parametrize("name", list(PRIMITIVES))
def test_tangents_are_unit_orthogonal_with_handedness(name: str) -> None:
    mesh = PRIMITIVES[name]()
    t, w, n = mesh.tangents[:, :3], mesh.tangents[:, 3], mesh.normals
    assert np.isfinite(mesh.tangents).all()
    assert np.allclose(np.linalg.norm(t, axis=1), 1.0, atol=1e-5)
    assert np.abs(np.sum(t * n, axis=1)).max() < 1e-5
    assert set(np.unique(w)) <= {-1.0, 1.0}


def test_tangent_convention_on_the_quad() -> None:
    mesh = quad()
    assert np.allclose(mesh.tangents, [[1, 0, 0, 1]] * 4)  # T along +u; cross(N, T) * w = +Y = image up (-v)
    flipped = MeshData(mesh.positions, uvs=mesh.uvs * [1, -1] + [0, 1], indices=mesh.indices).with_tangents()
    flipped_uv = MeshData(mesh.positions, uvs=1.0 - mesh.uvs[:, ::-1], indices=mesh.indices).with_tangents()
    assert np.allclose(flipped.tangents[:, 3], -1.0)  # v mirrored -> other handedness
    assert np.isfinite(flipped_uv.tangents).all()
    with pytest.raises(ResourceError, match=r"mesh 'mesh': uvs: tangents need texture coordinates"):
        MeshData(mesh.positions, indices=mesh.indices).with_tangents()


def test_interleaved_layout_offsets_and_data() -> None:
    mesh = cube()
    data, layout = mesh.interleaved(("position", "normal", "uv"))
    assert data.dtype == np.float32 and data.shape == (24, 8) and data.flags.c_contiguous
    assert [(a.name, a.location, a.components, a.offset_bytes) for a in layout.attributes] == [
        ("position", 0, 3, 0),
        ("normal", 1, 3, 12),
        ("uv", 2, 2, 24),
    ]
    assert layout.stride == 32 and layout.floats_per_vertex == 8
    assert np.array_equal(data[:, 3:6], mesh.normals)
    _, full = triangle().interleaved(("uv", "color", "tangent"))
    assert [(a.location, a.offset_bytes, a.wgpu_format, a.gl_format) for a in full.attributes] == [
        (2, 0, "float32x2", "2f"),
        (4, 8, "float32x4", "4f"),
        (3, 24, "float32x4", "4f"),
    ]
    assert full.stride == 40
    assert ATTRIBUTE_LOCATIONS == {"position": 0, "normal": 1, "uv": 2, "tangent": 3, "color": 4}


def test_interleaved_errors_name_the_attribute() -> None:
    with pytest.raises(ResourceError, match=r"mesh 'cube': colors: the shader needs attribute 'color'"):
        cube().interleaved(("position", "color"))
    with pytest.raises(ResourceError, match=r"attributes: unknown attribute 'texcoord'"):
        cube().interleaved(("position", "texcoord"))
    with pytest.raises(ResourceError, match=r"attributes: attribute 'uv' is requested twice"):
        cube().interleaved(("uv", "uv"))


# --- primitives ----------------------------------------------------------------------------------------------------


def _geometric_normals(mesh: MeshData) -> tuple[np.ndarray, np.ndarray]:
    p = mesh.positions.astype(float)
    tri = mesh.triangles().astype(int)
    face = np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]])
    return face, tri


@pytest.mark.parametrize("name", list(PRIMITIVES))
def test_primitives_wind_counter_clockwise_seen_from_outside(name: str) -> None:
    mesh = PRIMITIVES[name]()
    face, tri = _geometric_normals(mesh)
    area = np.linalg.norm(face, axis=1)
    assert area.min() > 1e-6  # no degenerate triangles (sphere poles are skipped)
    stored = mesh.normals[tri].astype(float).sum(axis=1)
    assert (np.sum(face * stored, axis=1) > 0).all()


@pytest.mark.parametrize(
    ("name", "inside"),
    [("cube", (0, 0, 0)), ("pyramid", (0, 0.25, 0)), ("uv_sphere", (0, 0, 0))],
)
def test_convex_primitives_face_away_from_their_inside(name: str, inside: tuple) -> None:
    mesh = PRIMITIVES[name]()
    face, tri = _geometric_normals(mesh)
    centroid = mesh.positions[tri].astype(float).mean(axis=1)
    assert (np.sum(face * (centroid - inside), axis=1) > 0).all()


def test_torus_faces_away_from_its_tube_centre() -> None:
    mesh = torus(1.0, 0.3, 12, 8)
    face, tri = _geometric_normals(mesh)
    centroid = mesh.positions[tri].astype(float).mean(axis=1)
    ring = centroid * [1, 0, 1]
    ring = ring / np.linalg.norm(ring, axis=1, keepdims=True)
    assert (np.sum(face * (centroid - ring), axis=1) > 0).all()


@pytest.mark.parametrize("name", list(PRIMITIVES))
def test_primitives_have_unit_normals_and_uvs_in_range(name: str) -> None:
    mesh = PRIMITIVES[name]()
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-6)
    assert mesh.uvs.min() >= 0.0 and mesh.uvs.max() <= 1.0
    assert np.array_equal(np.unique(mesh.triangles()), np.arange(mesh.vertex_count))  # every vertex is used


def test_uv_origin_is_top_left() -> None:
    q = quad(2.0)
    top_left = np.argmin(q.uvs.sum(axis=1))
    assert q.uvs[top_left].tolist() == [0, 0]
    assert q.positions[top_left].tolist() == [-1, 1, 0]
    c = cube()
    front = np.where(c.normals[:, 2] > 0.5)[0]
    tl = front[np.argmin(c.uvs[front].sum(axis=1))]
    assert c.positions[tl].tolist() == [-0.5, 0.5, 0.5]
    s = uv_sphere()
    assert np.allclose(s.positions[s.uvs[:, 1] == 0], [0, 1, 0], atol=1e-6)  # v = 0 is the north pole


def test_primitive_sizes() -> None:
    c = cube(2.0)
    assert c.vertex_count == 24 and c.index_count == 36
    assert c.bounds()[0].tolist() == [-1, -1, -1] and c.bounds()[1].tolist() == [1, 1, 1]
    p = pyramid(2.0, 3.0)
    assert p.bounds()[0].tolist() == [-1, 0, -1] and p.bounds()[1].tolist() == [1, 3, 1]
    assert plane(4.0, 2).vertex_count == 9 and np.allclose(plane().normals, [0, 1, 0])
    with pytest.raises(ResourceError, match=r"mesh 'cube': size: must be a positive finite number"):
        cube(0)
    with pytest.raises(ResourceError, match=r"mesh 'uv_sphere': segments: must be an integer >= 3"):
        uv_sphere(segments=2)
    with pytest.raises(ResourceError, match=r"mesh 'torus': minor_radius"):
        torus(1.0, 2.0)


# --- MaterialData --------------------------------------------------------------------------------------------------


def test_material_defaults_and_pipeline_key_ignores_colour() -> None:
    m = MaterialData("lit", textures=["bricks"], color=(1, 0, 0), params={"shininess": 32, "tint": [1, 2, 3]})
    assert m.color == (1.0, 0.0, 0.0, 1.0)
    assert m.textures == ("bricks",)
    assert m.uniform_values() == {"color": (1.0, 0.0, 0.0, 1.0), "shininess": 32.0, "tint": (1.0, 2.0, 3.0)}
    blue = m.with_color((0, 0, 1, 0.5))
    assert blue.pipeline_key() == m.pipeline_key()
    assert blue.color == (0.0, 0.0, 1.0, 0.5)
    assert MaterialData("lit", params={"shininess": 2}).pipeline_key() == m.pipeline_key()
    assert MaterialData("lit", cull="none").pipeline_key() != m.pipeline_key()
    assert MaterialData("lit", blend="alpha").pipeline_key() != m.pipeline_key()
    assert MaterialData("lit", depth_write=False).pipeline_key() != m.pipeline_key()
    assert hash(m.pipeline_key()) == hash(blue.pipeline_key())


@pytest.mark.parametrize(
    ("kwargs", "pattern"),
    [
        ({"shader": ""}, r"material '': shader: expected a shader name"),
        ({"cull": "both"}, r"material 'lit': cull: 'both' is not one of 'back', 'front', 'none'"),
        ({"blend": "multiply"}, r"blend: 'multiply' is not one of"),
        ({"color": (1, 0)}, r"color: expected 3 or 4 components, got 2"),
        ({"color": (1, np.nan, 0)}, r"color: values must be finite"),
        ({"textures": "bricks"}, r"textures: expected a sequence of texture names"),
        ({"textures": ["a", 3]}, r"textures\[1\]: expected a texture name"),
        ({"params": {"k": "x"}}, r"params\['k'\]: 'x' is not a number"),
        ({"params": {"k": np.zeros(17)}}, r"params\['k'\]: expected a float or up to 16 floats"),
        ({"params": {"2bad": 1}}, r"params: key '2bad' is not a valid uniform name"),
        ({"params": {"color": 1}}, r"params\['color'\]: 'color' is reserved"),
        ({"depth_test": "yes"}, r"depth_test: expected True or False"),
    ],
)
def test_material_validation_names_the_field(kwargs: dict, pattern: str) -> None:
    with pytest.raises(ResourceError, match=pattern):
        MaterialData(**{"shader": "lit", **kwargs})


def test_material_is_immutable() -> None:
    m = MaterialData("lit", params={"a": 1.0})
    with pytest.raises(TypeError):
        m.params["a"] = 2.0  # type: ignore[index]
    with pytest.raises(AttributeError):
        m.color = (0, 0, 0, 1)  # type: ignore[misc]


# --- ShaderSource --------------------------------------------------------------------------------------------------


def test_shader_from_file_language_stage_and_errors(tmp_path: Path) -> None:
    (tmp_path / "a.frag").write_text("#version 330\nvoid main() {}\n")
    (tmp_path / "b.wgsl").write_text("@fragment fn fs() {}\n")
    frag = ShaderSource.from_file(tmp_path / "a.frag")
    assert (frag.lang, frag.stage, frag.filename) == ("glsl", "fragment", str(tmp_path / "a.frag"))
    assert frag.text == "#version 330\nvoid main() {}\n"
    assert (ShaderSource.from_file(tmp_path / "b.wgsl").lang, ShaderSource.from_file(tmp_path / "b.wgsl").stage) == (
        "wgsl",
        None,
    )
    with pytest.raises(ResourceError, match=r"shader '.*missing\.vert': path: file not found: .*missing\.vert"):
        ShaderSource.from_file(tmp_path / "missing.vert")
    with pytest.raises(ResourceError, match=r"path: unknown shader extension '\.glslx'"):
        ShaderSource.from_file(tmp_path / "x.glslx")
    with pytest.raises(ResourceError, match=r"shader '<text>': stage: a GLSL shader needs a stage"):
        ShaderSource.from_text("void main() {}", "glsl")
    with pytest.raises(ResourceError, match=r"lang: 'hlsl' is not one of"):
        ShaderSource.from_text("", "hlsl")


def test_format_compile_error() -> None:
    src = "line one\n  bad line  \nline three"
    assert format_compile_error("x.frag", src, 2, "syntax error") == "x.frag:2: syntax error\n      bad line"
    assert format_compile_error("x.frag", src, 9, "eof") == "x.frag:9: eof"


def test_include_line_map_names_the_right_file_and_line(tmp_path: Path) -> None:
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "common.glsl").write_text("// common\nfloat sq(float x) { return x * x; }\n")
    (tmp_path / "lib" / "light.glsl").write_text('#include "common.glsl"\nvec3 lambert() { oops; }\n')
    (tmp_path / "main.frag").write_text(
        '#version 330\n#include "lib/light.glsl"\n#include "lib/common.glsl"\nvoid main() { bad; }\n'
    )
    src = ShaderSource.from_file(tmp_path / "main.frag")
    lines = src.text.splitlines()
    main, light, common = (
        str(tmp_path / "main.frag"),
        str(tmp_path / "lib/light.glsl"),
        str(tmp_path / "lib/common.glsl"),
    )
    oops = lines.index("vec3 lambert() { oops; }") + 1
    assert src.source_map(oops) == (light, 2)
    assert src.source_map(lines.index("float sq(float x) { return x * x; }") + 1) == (common, 2)
    bad = lines.index("void main() { bad; }") + 1
    assert src.source_map(bad) == (main, 4)
    assert src.source_map(1) == (main, 1)
    assert sum("float sq" in line for line in lines) == 1  # common.glsl is included once
    assert src.format_error(oops, "error: 'oops' undeclared") == (
        f"{light}:2: error: 'oops' undeclared\n    vec3 lambert() {{ oops; }}"
    )
    assert src.format_error(0, "something").startswith(f"{main}:0: something")
    with pytest.raises(ResourceError, match=r"line: 999 is outside the expanded text"):
        src.source_map(999)


def test_include_cycle_and_missing_include(tmp_path: Path) -> None:
    (tmp_path / "a.glsl").write_text('#include "b.glsl"\n')
    (tmp_path / "b.glsl").write_text('// b\n#include "a.glsl"\n')
    (tmp_path / "s.wgsl").write_text('#include "a.glsl"\n')
    with pytest.raises(
        ResourceError, match=r"include: include cycle: .*s\.wgsl -> .*a\.glsl -> .*b\.glsl -> .*a\.glsl"
    ):
        ShaderSource.from_file(tmp_path / "s.wgsl")
    (tmp_path / "m.vert").write_text('#version 330\n\n#include "nothere.glsl"\n')
    with pytest.raises(ResourceError, match=r'include: .*m\.vert:3: "nothere.glsl" not found'):
        ShaderSource.from_file(tmp_path / "m.vert")


def test_include_from_text_uses_base_dir_and_include_dirs(tmp_path: Path) -> None:
    (tmp_path / "snip.wgsl").write_text("const k = 1.0;\n")
    src = ShaderSource.from_text('#include "snip.wgsl"\nfn f() {}\n', "wgsl", include_dirs=[tmp_path], filename="t")
    assert src.source_map(2) == (str(tmp_path / "snip.wgsl"), 1)
    assert src.source_map(3) == ("t", 2)
    with pytest.raises(ResourceError, match=r"shader 't': include: t:1: \"snip.wgsl\" not found"):
        ShaderSource.from_text('#include "snip.wgsl"\n', "wgsl", filename="t")


def test_texture_data_takes_a_path_as_in_the_paper(tmp_path):
    from PIL import Image

    path = tmp_path / "bricks.png"
    Image.fromarray(np.full((4, 6, 3), (200, 100, 50), np.uint8), "RGB").save(path)
    texture = TextureData(path, wrap="clamp")
    assert texture.name == "bricks.png"
    assert texture.pixels.shape == (4, 6, 4)
    assert np.array_equal(texture.pixels, TextureData.from_file(path, wrap="clamp").pixels)
    with pytest.raises(ResourceError, match="missing.png"):
        TextureData(tmp_path / "missing.png")


# --- anisotropic filtering -------------------------------------------------------------------------------------
@pytest.mark.parametrize(("settings", "needle"), [
    ({"anisotropy": 0}, "from 1 .off. to 16"), ({"anisotropy": 17}, "from 1 .off. to 16"),
    ({"anisotropy": 4.0}, "from 1 .off. to 16"), ({"anisotropy": True}, "from 1 .off. to 16"),
    ({"anisotropy": 8, "filter": "nearest"}, "needs filter='linear' and mipmaps=True"),
    ({"anisotropy": 8, "mipmaps": False}, "needs filter='linear' and mipmaps=True"),
])
def test_anisotropy_is_checked(settings, needle):
    from gandalf_core.resources import TextureData

    with pytest.raises(ResourceError, match=rf"texture 'floor': anisotropy: .*{needle}"):
        TextureData(np.zeros((4, 4, 4), np.uint8), name="floor", **settings)


def test_anisotropy_round_trips_through_usd(tmp_path):
    from gandalf_core import Scene
    from gandalf_core.resources import TextureData
    from step07_advanced.usd import load_scene, save_scene

    scene = Scene("aniso")
    scene.assets.texture("floor", TextureData(np.full((8, 8, 4), 200, np.uint8), anisotropy=8))
    scene.assets.texture("plain", TextureData(np.full((8, 8, 4), 200, np.uint8)))
    loaded = load_scene(save_scene(scene, tmp_path / "aniso.usda"))
    assert loaded.assets.textures["floor"].anisotropy == 8 and loaded.assets.textures["plain"].anisotropy == 1
