"""Backend-neutral texture data: RGBA8 pixels plus how they are sampled.

Pixels are stored **top row first** (row 0 is the top of the image, as in every image file). Both render
backends upload the rows in this order, so texture coordinate (0, 0) samples the top-left texel in OpenGL and
in WebGPU alike (see :mod:`gandalf_core.resources.primitives` for the matching UV convention).

Colour textures hold sRGB-encoded values (``srgb=True``, the default): the GPU decodes them to linear light when
sampling. Data textures (normal maps, roughness, noise used as data) set ``srgb=False`` and are read as stored.

Pillow is imported only when a file is read or written.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from gandalf_core.resources.errors import ResourceError
from gandalf_core.resources.memory import give_back_freed_memory

WRAP_MODES = ("repeat", "clamp")
FILTER_MODES = ("linear", "nearest")
CUBE_FACE_NAMES = ("+X", "-X", "+Y", "-Y", "+Z", "-Z")

_ARRAY_SHAPES = "(H, W), (H, W, 3) or (H, W, 4)"
# Float input may overshoot [0, 1] by rounding error of the caller's maths; more than this is a real mistake.
_FLOAT_SLACK = 1e-6


def srgb_to_linear(values: np.ndarray) -> np.ndarray:
    """Decode sRGB-encoded values in [0, 1] to linear light (float64), per IEC 61966-2-1."""
    v = np.asarray(values, dtype=np.float64)
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(values: np.ndarray) -> np.ndarray:
    """Encode linear-light values in [0, 1] to sRGB (float64); inputs are clipped to [0, 1] first."""
    v = np.clip(np.asarray(values, dtype=np.float64), 0.0, 1.0)
    return np.where(v <= 0.0031308, v * 12.92, 1.055 * v ** (1.0 / 2.4) - 0.055)


def _label(kind: str, name: str) -> str:
    return f"{kind} '{name}'"


def _check_settings(label: str, wrap: str, filter: str) -> None:
    if wrap not in WRAP_MODES:
        allowed = ", ".join(repr(m) for m in WRAP_MODES)
        raise ResourceError(label, "wrap", f"{wrap!r} is not one of {allowed}")
    if filter not in FILTER_MODES:
        allowed = ", ".join(repr(m) for m in FILTER_MODES)
        raise ResourceError(label, "filter", f"{filter!r} is not one of {allowed}")


def _check_rgba8(label: str, field: str, pixels: Any) -> np.ndarray:
    """Validate an (H, W, 4) uint8 array and return a private, read-only, C-contiguous copy."""
    if not isinstance(pixels, np.ndarray):
        raise ResourceError(label, field, f"expected a numpy array, got {type(pixels).__name__}")
    if pixels.dtype != np.uint8 or pixels.ndim != 3 or pixels.shape[2] != 4:
        raise ResourceError(
            label,
            field,
            f"expected a uint8 array of shape (H, W, 4), got {pixels.dtype} {pixels.shape} "
            "(use from_array to convert other shapes and dtypes)",
        )
    if pixels.shape[0] < 1 or pixels.shape[1] < 1:
        raise ResourceError(label, field, f"image is empty: shape {pixels.shape}")
    if _FRESH.get(id(pixels)) is pixels and pixels.flags.c_contiguous:
        # Just decoded from a file by this module: nobody else holds it, so it becomes the texture's own array
        # (a 2048² face is 16 MB; copying six of them doubled a sky's memory while loading).
        del _FRESH[id(pixels)]
        pixels.flags.writeable = False
        return pixels
    # A copy keeps later edits of the caller's array out of a texture that may already be cached on the GPU.
    owned = np.array(pixels, dtype=np.uint8, order="C", copy=True)
    owned.flags.writeable = False
    return owned


# Arrays decoded from image files by _read_image_rgba8 and not yet adopted by a TextureData/CubeTextureData.
_FRESH: weakref.WeakValueDictionary[int, np.ndarray] = weakref.WeakValueDictionary()


def _to_rgba8(label: str, arr: Any) -> np.ndarray:
    """Convert (H, W), (H, W, 3) or (H, W, 4) uint8/integer/float arrays to (H, W, 4) uint8."""
    a = np.asarray(arr)
    if a.ndim not in (2, 3) or (a.ndim == 3 and a.shape[2] not in (3, 4)):
        raise ResourceError(label, "pixels", f"shape {a.shape} is not one of {_ARRAY_SHAPES}")
    if a.shape[0] < 1 or a.shape[1] < 1:
        raise ResourceError(label, "pixels", f"image is empty: shape {a.shape}")
    if a.dtype == np.uint8:
        a8 = a
    elif a.dtype.kind == "f":
        finite = np.isfinite(a)
        if not finite.all():
            bad = tuple(int(i) for i in np.argwhere(~finite)[0])
            raise ResourceError(label, "pixels", f"value at index {bad} is {a[bad]} (NaN/Inf is not a colour)")
        lo, hi = float(a.min()), float(a.max())
        if lo < -_FLOAT_SLACK or hi > 1.0 + _FLOAT_SLACK:
            raise ResourceError(label, "pixels", f"float values must lie in [0, 1], found [{lo:g}, {hi:g}]")
        a8 = np.rint(np.clip(a.astype(np.float64), 0.0, 1.0) * 255.0).astype(np.uint8)
    elif a.dtype.kind in "iu":
        lo, hi = int(a.min()), int(a.max())
        if lo < 0 or hi > 255:
            raise ResourceError(label, "pixels", f"integer values must lie in [0, 255], found [{lo}, {hi}]")
        a8 = a.astype(np.uint8)
    else:
        raise ResourceError(label, "pixels", f"dtype {a.dtype} is not uint8, integer or float")
    if a8.ndim == 2:
        a8 = np.repeat(a8[:, :, None], 3, axis=2)
    if a8.shape[2] == 3:
        alpha = np.full(a8.shape[:2] + (1,), 255, dtype=np.uint8)
        a8 = np.concatenate([a8, alpha], axis=2)
    return np.ascontiguousarray(a8)


def _box_weights(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Taps for reducing ``n`` texels to ``max(1, n // 2)`` with an exact box (area) filter.

    Output texel ``i`` covers the source interval ``[i*r, (i+1)*r)`` with ``r = n / m``; each source texel
    contributes the length of its overlap. For even ``n`` this is the plain 2-texel average; for odd ``n`` a
    footprint of 2.5 or 3 texels, so no source texel is dropped (a plain 2x2 average would skip the last one).
    Returns ``(indices (m, 4), weights (m, 4))``.
    """
    m = max(1, n // 2)
    r = n / m
    start = np.floor(np.arange(m) * r).astype(np.int64)
    idx = start[:, None] + np.arange(4)[None, :]
    lo = np.arange(m)[:, None] * r
    hi = lo + r
    overlap = np.clip(np.minimum(idx + 1, hi) - np.maximum(idx, lo), 0.0, None)
    overlap[idx >= n] = 0.0
    return np.minimum(idx, n - 1), overlap / r


def _reduce_axis(img: np.ndarray, axis: int) -> np.ndarray:
    n = img.shape[axis]
    if n % 2 == 0:  # the plain 2-texel average, on strided views (no gathers), in img's float type
        even = [slice(None)] * img.ndim
        odd = list(even)
        even[axis], odd[axis] = slice(0, None, 2), slice(1, None, 2)
        out = img[tuple(even)] + img[tuple(odd)]
        out *= 0.5
        return out
    idx, w = _box_weights(n)
    w = w.astype(img.dtype) if img.dtype.kind == "f" else w
    shape = [1] * img.ndim
    shape[axis] = w.shape[0]
    out = None
    for k in range(idx.shape[1]):
        if not w[:, k].any():
            continue
        term = np.take(img, idx[:, k], axis=axis) * w[:, k].reshape(shape)
        out = term if out is None else out + term
    return out


def _check_flags(label: str, srgb: Any, mipmaps: Any) -> None:
    """``srgb`` and ``mipmaps`` are True or False: a string such as "no" would otherwise count as True."""
    for field, value in (("srgb", srgb), ("mipmaps", mipmaps)):
        if not isinstance(value, (bool, np.bool_)):
            raise ResourceError(label, field, f"expected True or False, got {value!r}")


def _mip_chain(pixels: np.ndarray, srgb: bool) -> list[np.ndarray]:
    """Box-filtered mip levels of (..., H, W, 4) uint8 pixels, averaged in linear light when ``srgb``."""
    levels = [pixels]
    h, w = pixels.shape[-3], pixels.shape[-2]
    count = max(h, w).bit_length()
    if count == 1:
        return levels
    # Work on a float chain so rounding to 8 bits happens once per level, not accumulated over levels. float32
    # is ample for 8-bit results (relative error ~1e-7 against a rounding step of 1/510) and halves the memory
    # of float64: a 6 x 2048² cube map's level 0 is 400 MB in float32 (800 MB in float64). The sRGB decode is a
    # 256-entry table lookup.
    current = (_SRGB_DECODE if srgb else _UNORM_DECODE)[pixels]
    if srgb:
        current[..., 3] = _UNORM_DECODE[pixels[..., 3]]
    for _ in range(count - 1):
        current = _reduce_axis(_reduce_axis(current, current.ndim - 3), current.ndim - 2).astype(np.float32, copy=False)
        encoded = np.clip(current, 0.0, 1.0)
        if srgb:  # alpha is never sRGB-encoded
            rgb = encoded[..., :3]
            encoded[..., :3] = np.where(rgb <= 0.0031308, rgb * np.float32(12.92),
                                        np.float32(1.055) * rgb ** np.float32(1.0 / 2.4) - np.float32(0.055))
        encoded *= np.float32(255.0)
        levels.append(np.ascontiguousarray(np.rint(encoded).astype(np.uint8)))
    return levels


# uint8 -> float32 in [0, 1], plain and sRGB-decoded (computed in float64, stored in float32).
_UNORM_DECODE = (np.arange(256, dtype=np.float64) / 255.0).astype(np.float32)
_SRGB_DECODE = srgb_to_linear(np.arange(256, dtype=np.float64) / 255.0).astype(np.float32)


def _read_image_rgba8(path: str | Path, label: str) -> np.ndarray:
    """Read an image file with Pillow and convert it to (H, W, 4) uint8, top row first (a fresh array that the
    texture adopts without a copy)."""
    pixels = _decode_image_rgba8(path, label)
    _FRESH[id(pixels)] = pixels
    return pixels


def _decode_image_rgba8(path: str | Path, label: str) -> np.ndarray:
    from PIL import Image, ImageOps

    p = Path(path)
    if not p.is_file():
        raise ResourceError(label, "path", f"{'is a folder, not an image file' if p.is_dir() else 'file not found'}: "
                            f"{str(p)!r}")
    try:
        with Image.open(p) as img:
            img.load()
            # Photos store their rotation in EXIF; textures want pixels. In place: no copy of an image that needs
            # no turn (a 2048² face is 16 MiB; each copy while decoding adds to a sky's peak memory).
            ImageOps.exif_transpose(img, in_place=True)
            mode = img.mode
            if mode == "F":
                # 32-bit float images have no agreed range (0..1? 0..255? HDR?): converting silently would
                # guess. Read them with Pillow/numpy and call TextureData.from_array with explicit scaling.
                raise ResourceError(
                    label, "mode", f"{str(p)!r} has mode 'F' (32-bit float); scale it yourself and use from_array"
                )
            if mode.startswith("I"):
                # 16-bit greyscale ('I;16*'), or 'I' (32-bit int) which Pillow also uses for 16-bit PNGs.
                grey = np.asarray(img).astype(np.int64)
                if grey.size and (grey.min() < 0 or grey.max() > 65535):
                    raise ResourceError(
                        label, "mode", f"{str(p)!r} has mode {mode!r} with values outside the 16-bit range"
                    )
                grey8 = ((grey * 255 + 32767) // 65535).astype(np.uint8)
                return _to_rgba8(label, grey8)
            try:
                rgba = img if mode == "RGBA" else img.convert("RGBA")
            except ValueError as exc:
                raise ResourceError(label, "mode", f"{str(p)!r}: cannot convert mode {mode!r} to RGBA: {exc}") from exc
            return _image_array(rgba)
    except ResourceError:
        raise
    except (OSError, ValueError, SyntaxError, Image.DecompressionBombError) as exc:
        raise ResourceError(label, "path", f"cannot read image {str(p)!r}: {exc}") from exc


def _image_array(image: Any) -> np.ndarray:
    """An RGBA Pillow image's pixels as a fresh (H, W, 4) uint8 array, copied in strips of about 1 MiB. Pillow's
    ``tobytes()`` (and so ``np.array(image)``) holds its encoded chunks and their join at once: twice the image on
    top of it while decoding, 32 MiB more for one 2048² face of a sky."""
    width, height = image.size
    pixels = np.empty((height, width, 4), dtype=np.uint8)
    rows = max(1, (1 << 20) // max(1, 4 * width))
    for top in range(0, height, rows):
        bottom = min(height, top + rows)
        pixels[top:bottom] = np.asarray(image.crop((0, top, width, bottom)))
    return pixels


def _write_png(pixels: np.ndarray, path: str | Path, label: str) -> None:
    from PIL import Image

    try:
        Image.fromarray(np.ascontiguousarray(pixels), mode="RGBA").save(Path(path), format="PNG")
    except OSError as exc:
        raise ResourceError(label, "path", f"cannot write PNG {str(path)!r}: {exc}") from exc


#: The largest anisotropy a texture may ask for (what WebGPU allows; OpenGL drivers offer at least this).
MAX_ANISOTROPY = 16


@dataclass(frozen=True, eq=False)
class TextureData:
    """An RGBA8 image (top row first) plus its sampling settings.

    ``pixels`` is a read-only, C-contiguous ``uint8`` array of shape (H, W, 4). The constructor takes exactly
    that, or an image file's path as in the paper (``TextureData(TEXTURES / "bricks.png")``, the same as
    :meth:`from_file`); :meth:`from_array` converts other arrays. Instances are immutable: derive a new one
    with :func:`dataclasses.replace` to change a setting.
    """

    pixels: np.ndarray  # or, when constructing, an image file's path
    srgb: bool = True
    wrap: str = "repeat"
    filter: str = "linear"
    mipmaps: bool = True
    name: str = "texture"
    #: Anisotropic filtering: up to this many samples along the direction a surface recedes in (1 = off,
    #: at most :data:`MAX_ANISOTROPY`); it needs ``filter="linear"`` and mipmaps (both APIs' rule).
    anisotropy: int = 1

    def __post_init__(self) -> None:
        if isinstance(self.pixels, (str, Path)):
            path = Path(self.pixels)
            if self.name == "texture":
                object.__setattr__(self, "name", path.name)
            object.__setattr__(self, "pixels", _read_image_rgba8(path, _label("texture", self.name)))
        label = _label("texture", self.name)
        _check_settings(label, self.wrap, self.filter)
        object.__setattr__(self, "pixels", _check_rgba8(label, "pixels", self.pixels))
        _check_flags(label, self.srgb, self.mipmaps)
        object.__setattr__(self, "srgb", bool(self.srgb))
        object.__setattr__(self, "mipmaps", bool(self.mipmaps))
        a = self.anisotropy
        if isinstance(a, bool) or not isinstance(a, (int, np.integer)) or not 1 <= a <= MAX_ANISOTROPY:
            raise ResourceError(label, "anisotropy", f"expected an integer from 1 (off) to {MAX_ANISOTROPY}, got {a!r}")
        if a > 1 and not (self.filter == "linear" and self.mipmaps):
            raise ResourceError(label, "anisotropy", f"{a} needs filter='linear' and mipmaps=True "
                                f"(got filter={self.filter!r}, mipmaps={self.mipmaps})")
        object.__setattr__(self, "anisotropy", int(a))

    @classmethod
    def from_array(cls, arr: Any, **settings: Any) -> TextureData:
        """Build a texture from (H, W) grey, (H, W, 3) RGB or (H, W, 4) RGBA data, top row first.

        ``uint8`` (and other integer arrays with values in 0..255) are taken as is; float arrays must hold values
        in [0, 1] and are scaled by 255 with rounding. NaN/Inf or out-of-range values raise :class:`ResourceError`.
        ``settings`` are the sampling fields (srgb, wrap, filter, mipmaps, anisotropy, name).
        """
        name = settings.get("name", "texture")
        return cls(_to_rgba8(_label("texture", name), arr), **settings)

    @classmethod
    def from_file(cls, path: str | Path, **settings: Any) -> TextureData:
        """Load an image file with Pillow; the texture's name defaults to the file name.

        Every 8-bit mode Pillow can convert (L, LA, P with transparency, RGB, RGBA, CMYK, YCbCr, 1, ...) becomes
        RGBA8. 16-bit greyscale ('I;16', and 'I' with values in 0..65535) is scaled to 8 bits with rounding.
        Float images (mode 'F') are **rejected**: their value range is unknown, so the caller scales them and uses
        :meth:`from_array`. Animated files give their first frame; EXIF rotation is applied.
        """
        settings.setdefault("name", Path(path).name)
        return cls(_read_image_rgba8(path, _label("texture", settings["name"])), **settings)

    @property
    def width(self) -> int:
        """Width in texels."""
        return int(self.pixels.shape[1])

    @property
    def height(self) -> int:
        """Height in texels."""
        return int(self.pixels.shape[0])

    @property
    def mip_levels(self) -> int:
        """Number of mip levels: ``floor(log2(max(w, h))) + 1`` with mipmaps, else 1."""
        return max(self.width, self.height).bit_length() if self.mipmaps else 1

    def mip_chain(self) -> list[np.ndarray]:
        """All mip levels as (h, w, 4) uint8 arrays, level 0 first.

        Each level halves both sizes (rounding down, never below 1), the WebGPU/OpenGL rule. Texels are box
        filtered over their exact footprint (odd sizes included); sRGB textures are averaged in linear light so
        distant textures do not darken. Without mipmaps the chain is just level 0.
        """
        if not self.mipmaps:
            return [self.pixels]
        return _mip_chain(self.pixels, self.srgb)

    def save_png(self, path: str | Path) -> None:
        """Write level 0 as an RGBA PNG (for debugging and reference images)."""
        _write_png(self.pixels, path, _label("texture", self.name))


def cube_face_directions(size: int) -> np.ndarray:
    """Unit view directions through the texel centres of the six cube faces, shape (6, size, size, 3).

    This is the cube-map convention shared by OpenGL, Vulkan and WebGPU. For a direction ``(x, y, z)`` the
    face is chosen by the largest component ``ma``, then ``s = (sc/|ma| + 1) / 2`` and
    ``t = (tc/|ma| + 1) / 2`` address the face image, with ``t = 0`` its first (top) row:

    ====  =====  =====
    face  sc     tc
    ====  =====  =====
    +X    -z     -y
    -X    +z     -y
    +Y    +x     +z
    -Y    +x     -z
    +Z    +x     -y
    -Z    -x     -y
    ====  =====  =====

    So the side faces have +Y at their top row, +Y's top row faces -Z and -Y's top row faces +Z.
    """
    c = (np.arange(size, dtype=np.float64) + 0.5) / size * 2.0 - 1.0
    tc, sc = np.meshgrid(c, c, indexing="ij")  # rows walk t, columns walk s
    one = np.ones_like(sc)
    faces = [
        (one, -tc, -sc),  # +X
        (-one, -tc, sc),  # -X
        (sc, one, tc),  # +Y
        (sc, -one, -tc),  # -Y
        (sc, -tc, one),  # +Z
        (-sc, -tc, -one),  # -Z
    ]
    dirs = np.stack([np.stack(f, axis=-1) for f in faces])
    return dirs / np.linalg.norm(dirs, axis=-1, keepdims=True)


def _check_face_shape(label: str, face: str, pixels: np.ndarray, first: int) -> None:
    """Raise unless a cube face is square and as large as face +X (``first`` texels a side)."""
    height, width = pixels.shape[:2]
    if height != width:
        raise ResourceError(label, f"faces[{face}]", f"face must be square, got {width}x{height}")
    if height != first:
        raise ResourceError(label, f"faces[{face}]", f"size {width}x{height} differs from face +X ({first}x{first})")


class FaceFiles(Sequence[np.ndarray]):
    """The six faces of a cube texture loaded from image files, read from the files at each access and not held:
    a sky of six 2048² faces keeps no 96 MiB of pixels in memory once the renderer has uploaded it (each face is
    read, uploaded and let go in turn). :meth:`CubeTextureData.from_files` checks every file once when it loads
    them (each error names its file). A later read gets the file as it is then: one that was removed or no longer
    has the size it had is an error naming it."""

    def __init__(self, paths: Sequence[Path], label: str, size: int) -> None:
        self.paths = tuple(paths)
        self.label = label
        self.size = size

    def __len__(self) -> int:
        return len(self.paths)

    def __getitem__(self, index: Any) -> Any:
        if isinstance(index, slice):
            return tuple(self[i] for i in range(*index.indices(len(self))))
        path, face = self.paths[index], CUBE_FACE_NAMES[index]
        pixels = _check_rgba8(self.label, f"faces[{face}]", _read_image_rgba8(path, self.label))
        if pixels.shape[:2] != (self.size, self.size):
            now, was = f"{pixels.shape[1]}x{pixels.shape[0]}", f"{self.size}x{self.size}"
            detail = f"{str(path)!r} is now {now}, was {was} when loaded"
            raise ResourceError(self.label, f"faces[{face}]", detail)
        return pixels

    def __repr__(self) -> str:
        return f"FaceFiles({[str(p) for p in self.paths]!r})"


@dataclass(frozen=True, eq=False)
class CubeTextureData:
    """Six square RGBA8 faces of equal size, in the order +X, -X, +Y, -Y, +Z, -Z (see :data:`CUBE_FACE_NAMES`).

    The orientation of each face follows the OpenGL/WebGPU cube-map convention documented in
    :func:`cube_face_directions`; with faces stored top row first, both backends sample them identically.
    Cube maps always clamp at their edges, so there is no ``wrap`` setting.

    ``levels`` optionally gives the mip levels below level 0 explicitly, each a (6, s, s, 4) uint8 array with
    ``s = max(1, size >> k)`` for level ``k = 1, 2, ...``: a prefiltered environment stores one roughness per
    level, which no box filter would produce. Fewer levels than the full chain are allowed (the texture then
    has ``1 + len(levels)`` levels); they need ``mipmaps=True``.
    """

    faces: Sequence[np.ndarray]  # a tuple of arrays, or FaceFiles (read from files when asked)
    srgb: bool = True
    filter: str = "linear"
    mipmaps: bool = True
    name: str = "cubemap"
    levels: tuple[np.ndarray, ...] | None = None

    def __post_init__(self) -> None:
        label = _label("cube texture", self.name)
        _check_settings(label, "clamp", self.filter)
        if isinstance(self.faces, FaceFiles):  # checked face by face when loaded (from_files)
            self._check_rest(label)
            return
        faces = tuple(self.faces)
        if len(faces) != 6:
            raise ResourceError(label, "faces", f"expected 6 faces ({', '.join(CUBE_FACE_NAMES)}), got {len(faces)}")
        checked = tuple(_check_rgba8(label, f"faces[{face}]", f) for face, f in zip(CUBE_FACE_NAMES, faces))
        for face, f in zip(CUBE_FACE_NAMES, checked):
            _check_face_shape(label, face, f, checked[0].shape[0])
        object.__setattr__(self, "faces", checked)
        self._check_rest(label)

    def _check_rest(self, label: str) -> None:
        _check_flags(label, self.srgb, self.mipmaps)
        object.__setattr__(self, "srgb", bool(self.srgb))
        object.__setattr__(self, "mipmaps", bool(self.mipmaps))
        if self.levels is not None:
            object.__setattr__(self, "levels", self._check_levels(label))

    def _check_levels(self, label: str) -> tuple[np.ndarray, ...]:
        if not self.mipmaps:
            raise ResourceError(label, "levels", "explicit mip levels need mipmaps=True")
        if isinstance(self.levels, np.ndarray) or not isinstance(self.levels, Sequence):
            detail = f"expected a sequence of (6, s, s, 4) arrays, got {type(self.levels).__name__}"
            raise ResourceError(label, "levels", detail)
        size = self.size
        if len(self.levels) > size.bit_length() - 1:
            raise ResourceError(label, "levels", f"{len(self.levels)} levels below level 0, but a {size}x{size} cube "
                                                 f"has at most {size.bit_length() - 1}")
        checked = []
        for k, level in enumerate(self.levels, start=1):
            s = max(1, size >> k)
            a = level if isinstance(level, np.ndarray) else None
            if a is None or a.dtype != np.uint8 or a.shape != (6, s, s, 4):
                got = f"{a.dtype} {a.shape}" if a is not None else type(level).__name__
                detail = f"mip level {k} must be uint8 of shape (6, {s}, {s}, 4), got {got}"
                raise ResourceError(label, f"levels[{k - 1}]", detail)
            owned = np.array(a, dtype=np.uint8, order="C", copy=True)
            owned.flags.writeable = False
            checked.append(owned)
        return tuple(checked)

    @classmethod
    def from_arrays(cls, faces: Sequence[Any], **settings: Any) -> CubeTextureData:
        """Build from six arrays accepted by :meth:`TextureData.from_array`, in +X, -X, +Y, -Y, +Z, -Z order."""
        label = _label("cube texture", settings.get("name", "cubemap"))
        if len(faces) != 6:
            raise ResourceError(label, "faces", f"expected 6 faces ({', '.join(CUBE_FACE_NAMES)}), got {len(faces)}")
        converted = []
        for face, arr in zip(CUBE_FACE_NAMES, faces):
            try:
                converted.append(_to_rgba8(label, arr))
            except ResourceError as exc:
                raise ResourceError(label, f"faces[{face}]", exc.detail) from exc
        return cls(tuple(converted), **settings)

    @classmethod
    def from_files(cls, paths: Sequence[str | Path], keep_pixels: bool = False, **settings: Any) -> CubeTextureData:
        """Load six image files, in +X, -X, +Y, -Y, +Z, -Z order (same conversions as ``TextureData.from_file``).

        Every file is read and checked now. Unless ``keep_pixels``, the texture then holds the paths, not the pixels
        (:class:`FaceFiles`): ``faces`` reads them again when asked (the upload, a save, the editor)."""
        settings.setdefault("name", Path(paths[0]).stem if len(paths) else "cubemap")
        label = _label("cube texture", settings["name"])
        if len(paths) != 6:
            raise ResourceError(label, "faces", f"expected 6 files ({', '.join(CUBE_FACE_NAMES)}), got {len(paths)}")
        if not keep_pixels:
            # Each file decoded and checked now, one at a time, then let go: the faces are read again when the
            # renderer uploads them (and when a save or the editor needs them), so the loaded texture holds none.
            size = 0
            for face, path in zip(CUBE_FACE_NAMES, paths):
                pixels = _check_rgba8(label, f"faces[{face}]", _read_image_rgba8(path, label))
                size = size or pixels.shape[0]
                _check_face_shape(label, face, pixels, size)
                del pixels
            # Absolute: a later read must not depend on the working folder of that moment.
            return cls(FaceFiles([Path(p).absolute() for p in paths], label, size), **settings)
        return cls(tuple(_read_image_rgba8(p, label) for p in paths), **settings)

    def write_faces(self, write: Callable[[int, np.ndarray], None]) -> None:
        """Hand each face in turn to ``write(index, pixels)`` (0-5: +X, -X, +Y, -Y, +Z, -Z), holding one at a time:
        a face read from a file is decoded just before its write and let go, its memory given back to the system,
        before the next is read. A face still held would sit on top of the C heap and keep the freed faces below it
        with the process (benchmarks page, "Again on 7 December: the sky's peak memory")."""
        for index in range(len(self.faces)):
            pixels = self.faces[index]
            write(index, pixels)
            del pixels
            give_back_freed_memory()

    @property
    def size(self) -> int:
        """Edge length of each face in texels."""
        if isinstance(self.faces, FaceFiles):
            return self.faces.size
        return int(self.faces[0].shape[0])

    @property
    def pixels(self) -> np.ndarray:
        """All faces stacked as one (6, size, size, 4) uint8 array, ready for a layered upload."""
        return np.stack(self.faces)

    @property
    def mip_levels(self) -> int:
        """Number of mip levels: ``1 + len(levels)`` when given, ``floor(log2(size)) + 1`` with mipmaps, else 1."""
        if self.levels is not None:
            return 1 + len(self.levels)
        return self.size.bit_length() if self.mipmaps else 1

    def mip_chain(self) -> list[np.ndarray]:
        """All mip levels as (6, s, s, 4) uint8 arrays, level 0 first: the explicit ``levels`` when given,
        else box filtered as in TextureData."""
        if not self.mipmaps:
            return [self.pixels]
        if self.levels is not None:
            return [self.pixels, *self.levels]
        return _mip_chain(self.pixels, self.srgb)

    def save_png(self, path: str | Path) -> None:
        """Write the faces as a horizontal cross (4x3 faces, transparent gaps) PNG, for debugging."""
        s = self.size
        cross = np.zeros((3 * s, 4 * s, 4), dtype=np.uint8)
        # (row, column) of each face in the usual unfolded cross: -X | +Z | +X | -Z across the middle.
        cells = {"+X": (1, 2), "-X": (1, 0), "+Y": (0, 1), "-Y": (2, 1), "+Z": (1, 1), "-Z": (1, 3)}
        for face, img in zip(CUBE_FACE_NAMES, self.faces):
            r, c = cells[face]
            cross[r * s : (r + 1) * s, c * s : (c + 1) * s] = img
        _write_png(cross, path, _label("cube texture", self.name))
