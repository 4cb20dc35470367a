"""Scene assets in USD: meshes (UsdGeom.Mesh), materials (UsdShade.Material) and textures (PNG files).

Mesh attribute data is float32 in both gandalf and USD, so it round-trips exactly. gandalf's UVs have v = 0 at
the top of the image; USD's ``st`` has t = 0 at the bottom, so ``t = 1 - v`` both ways (computed in float64;
stored as texCoord2f when that is exact for every vertex, else as texCoord2d).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from pxr import Gf, Sdf, Usd, UsdGeom, UsdShade, Vt

from gandalf_core.resources import CubeTextureData, MaterialData, MeshData, ResourceError, TextureData, srgb_to_linear

from .attributes import FileContext, authored, mesh_attribute, numeric_array, read, read_floats, write
from .mapping import CUBE_FACE_SUFFIXES, PREVIEW_ST_READER, PREVIEW_SURFACE, PREVIEW_TEXTURE

T = Sdf.ValueTypeNames
_MAX_INDEX = 2**31 - 1  # faceVertexIndices is int[]


# --- meshes -------------------------------------------------------------------------------------------
def write_mesh(stage: Usd.Stage, path: str, name: str, mesh: MeshData) -> None:
    usd = UsdGeom.Mesh.Define(stage, path)
    prim = usd.GetPrim()
    write(prim, "gandalf:name", T.String, name)
    write(prim, "gandalf:meshName", T.String, mesh.name)
    write(prim, "gandalf:indexed", T.Bool, mesh.indices is not None)
    usd.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    points = Vt.Vec3fArray.FromNumpy(mesh.positions)
    usd.CreatePointsAttr(points)
    usd.CreateExtentAttr(UsdGeom.PointBased.ComputeExtent(points))  # bounds for other tools (no draw needed)
    size = 3
    if mesh.patch_size is not None:  # a patch mesh: each face is one patch of control points
        size = mesh.patch_size
        write(prim, "gandalf:patchSize", T.Int, size)
        flat = mesh.indices if mesh.indices is not None else np.arange(mesh.vertex_count, dtype=np.uint32)
        tri = flat.reshape(-1, size)
    else:
        tri = mesh.triangles()
    if tri.size and int(tri.max()) > _MAX_INDEX:
        raise ValueError(f"mesh '{name}' has indices beyond USD's int range")
    usd.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(tri), size, dtype=np.int32)))
    usd.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(tri.reshape(-1).astype(np.int32)))
    primvars = UsdGeom.PrimvarsAPI(usd)
    if mesh.normals is not None:
        usd.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(mesh.normals))
        usd.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
    if mesh.uvs is not None:
        st = mesh.uvs.astype(np.float64)
        st[:, 1] = 1.0 - st[:, 1]
        st32 = st.astype(np.float32)
        back = st32.astype(np.float64)
        back[:, 1] = 1.0 - back[:, 1]
        if np.array_equal(back.astype(np.float32), mesh.uvs):
            primvars.CreatePrimvar("st", T.TexCoord2fArray, UsdGeom.Tokens.vertex).Set(Vt.Vec2fArray.FromNumpy(st32))
        else:
            primvars.CreatePrimvar("st", T.TexCoord2dArray, UsdGeom.Tokens.vertex).Set(Vt.Vec2dArray.FromNumpy(st))
    if mesh.tangents is not None:
        primvars.CreatePrimvar("tangents", T.Float4Array, UsdGeom.Tokens.vertex).Set(
            Vt.Vec4fArray.FromNumpy(mesh.tangents)
        )
    if mesh.colors is not None:
        rgb = np.ascontiguousarray(mesh.colors[:, :3])
        alpha = np.ascontiguousarray(mesh.colors[:, 3])
        usd.CreateDisplayColorPrimvar(UsdGeom.Tokens.vertex).Set(Vt.Vec3fArray.FromNumpy(rgb))
        usd.CreateDisplayOpacityPrimvar(UsdGeom.Tokens.vertex).Set(Vt.FloatArray.FromNumpy(alpha))


def read_mesh(ctx: FileContext, prim: Usd.Prim) -> tuple[str, MeshData]:
    name = read(ctx, prim, "gandalf:name", "string", prim.GetName())
    positions = numeric_array(ctx, prim, "points", ("point3f[]", "float3[]"), np.float32, 3)
    counts = numeric_array(ctx, prim, "faceVertexCounts", "int[]", np.int64, None)
    indices = numeric_array(ctx, prim, "faceVertexIndices", "int[]", np.int64, None)
    patch_size = read(ctx, prim, "gandalf:patchSize", "int", None)
    size = 3 if patch_size is None else patch_size
    if (counts != size).any():
        what = "triangle meshes are" if patch_size is None else f"patches of {size} are"
        raise ctx.fail(prim, "faceVertexCounts", f"only {what} supported (every count must be {size})")
    if indices.size != counts.size * size:
        raise ctx.fail(prim, "faceVertexIndices", f"has {indices.size} indices for {counts.size} faces of {size}")
    fields: dict[str, object] = {"positions": positions, "patch_size": patch_size}
    fields["normals"] = numeric_array(ctx, prim, "normals", ("normal3f[]", "float3[]"), np.float32, 3, None)
    st = numeric_array(ctx, prim, "primvars:st", ("texCoord2f[]", "texCoord2d[]", "float2[]"), np.float64, 2, None)
    if st is not None:
        st[:, 1] = 1.0 - st[:, 1]
        fields["uvs"] = st.astype(np.float32)
    fields["tangents"] = numeric_array(ctx, prim, "primvars:tangents", "float4[]", np.float32, 4, None)
    rgb = numeric_array(ctx, prim, "primvars:displayColor", ("color3f[]", "float3[]"), np.float32, 3, None)
    if rgb is not None:
        alpha = numeric_array(ctx, prim, "primvars:displayOpacity", "float[]", np.float32, None, None)
        alpha = np.ones(len(rgb), np.float32) if alpha is None else alpha
        if alpha.shape != (len(rgb),):
            raise ctx.fail(prim, "primvars:displayOpacity", f"has {alpha.size} values for {len(rgb)} colours")
        fields["colors"] = np.concatenate([rgb, alpha[:, None]], axis=1)
    if read(ctx, prim, "gandalf:indexed", "bool", True):
        fields["indices"] = indices.astype(np.int64)
    elif not np.array_equal(indices, np.arange(len(positions))):
        raise ctx.fail(prim, "faceVertexIndices", "a mesh saved without indices must list 0, 1, 2, ... in order")
    try:
        return name, MeshData(**fields, name=read(ctx, prim, "gandalf:meshName", "string", name))
    except ResourceError as exc:
        raise ctx.fail(prim, mesh_attribute(exc.field), exc.detail) from None


# --- materials ----------------------------------------------------------------------------------------
_PARAMS = "inputs:gandalf:params:"


def write_material(stage: Usd.Stage, path: str, name: str, material: MaterialData,
                   texture: tuple[str, bool] | None = None) -> None:
    """A UsdShade.Material: the exact gandalf values as ``inputs:gandalf:*``, and a UsdPreviewSurface network.

    ``texture`` is the first texture's relative file and whether it is sRGB (None: no texture node).
    """
    usd = UsdShade.Material.Define(stage, path)
    prim = usd.GetPrim()
    write(prim, "gandalf:name", T.String, name)
    inputs = {
        "shader": (T.String, material.shader),
        "materialName": (T.String, material.name),
        "textures": (T.StringArray, list(material.textures)),
        "buffers": (T.StringArray, list(material.buffers)),
        "color": (T.Double4, material.color),
        "cull": (T.String, material.cull),
        "depthTest": (T.Bool, material.depth_test),
        "depthWrite": (T.Bool, material.depth_write),
        "blend": (T.String, material.blend),
    }
    for key, (type_name, value) in inputs.items():
        usd.CreateInput(f"gandalf:{key}", type_name).Set(value)
    for key, value in material.params.items():
        # A float stays a double, a sequence a double[] (even of length 1), so the type round-trips too.
        if isinstance(value, float):
            usd.CreateInput(f"gandalf:params:{key}", T.Double).Set(value)
        else:
            usd.CreateInput(f"gandalf:params:{key}", T.DoubleArray).Set(Vt.DoubleArray(list(value)))
    write_preview_surface(stage, usd, material, texture)


def _param_float(material: MaterialData, key: str) -> float | None:
    value = material.params.get(key)
    if isinstance(value, float):
        return value
    if isinstance(value, tuple) and len(value) == 1:
        return value[0]
    return None


def write_preview_surface(stage: Usd.Stage, usd: UsdShade.Material, material: MaterialData,
                          texture: tuple[str, bool] | None) -> None:
    """The standard network other USD tools draw: ``PreviewSurface`` (+ ``Texture`` and ``PrimvarSt`` readers).

    diffuseColor (or the texture's scale) is the material colour in linear light, opacity its alpha; params
    named ``roughness``, ``metallic``, ``emissive``/``emission`` (3 floats) map to the inputs of those names;
    a Blinn-Phong ``shininess`` becomes roughness = (2 / (shininess + 2))^(1/4).
    """
    path = usd.GetPath()
    surface = UsdShade.Shader.Define(stage, path.AppendChild(PREVIEW_SURFACE))
    surface.CreateIdAttr("UsdPreviewSurface")
    linear = srgb_to_linear(np.clip(np.asarray(material.color[:3], dtype=np.float64), 0.0, None))
    color = Gf.Vec3f(*map(float, linear))
    if texture is not None:
        file, srgb = texture
        reader = UsdShade.Shader.Define(stage, path.AppendChild(PREVIEW_ST_READER))
        reader.CreateIdAttr("UsdPrimvarReader_float2")
        reader.CreateInput("varname", T.String).Set("st")
        tex = UsdShade.Shader.Define(stage, path.AppendChild(PREVIEW_TEXTURE))
        tex.CreateIdAttr("UsdUVTexture")
        tex.CreateInput("file", T.Asset).Set(Sdf.AssetPath(file))
        tex.CreateInput("sourceColorSpace", T.Token).Set("sRGB" if srgb else "raw")
        tex.CreateInput("scale", T.Float4).Set(Gf.Vec4f(*color, 1.0))
        tex.CreateInput("st", T.Float2).ConnectToSource(reader.ConnectableAPI(), "result")
        tex.CreateOutput("rgb", T.Float3)
        surface.CreateInput("diffuseColor", T.Color3f).ConnectToSource(tex.ConnectableAPI(), "rgb")
    else:
        surface.CreateInput("diffuseColor", T.Color3f).Set(color)
    surface.CreateInput("opacity", T.Float).Set(float(np.clip(material.color[3], 0.0, 1.0)))
    roughness = _param_float(material, "roughness")
    shininess = _param_float(material, "shininess")
    if roughness is None and shininess is not None and shininess >= 0.0:
        roughness = (2.0 / (shininess + 2.0)) ** 0.25
    if roughness is not None:
        surface.CreateInput("roughness", T.Float).Set(float(np.clip(roughness, 0.0, 1.0)))
    metallic = _param_float(material, "metallic")
    if metallic is not None:
        surface.CreateInput("metallic", T.Float).Set(float(np.clip(metallic, 0.0, 1.0)))
    for key in ("emissive", "emission"):
        value = material.params.get(key)
        if isinstance(value, tuple) and len(value) == 3:
            surface.CreateInput("emissiveColor", T.Color3f).Set(Gf.Vec3f(*map(float, value)))
            break
    usd.CreateSurfaceOutput().ConnectToSource(surface.ConnectableAPI(), "surface")


def read_material(ctx: FileContext, prim: Usd.Prim) -> tuple[str, MaterialData]:
    name = read(ctx, prim, "gandalf:name", "string", prim.GetName())
    params: dict[str, object] = {}
    for attr in prim.GetAuthoredAttributes():
        attr_name = attr.GetName()
        if attr_name.startswith(_PARAMS):
            if str(attr.GetTypeName()) == "double[]":
                params[attr_name[len(_PARAMS):]] = tuple(read_floats(ctx, prim, attr_name, ("double[]",), None))
            else:
                params[attr_name[len(_PARAMS):]] = float(read(ctx, prim, attr_name, "double"))
    g = "inputs:gandalf:"
    try:
        return name, MaterialData(
            shader=read(ctx, prim, g + "shader", "string"),
            textures=list(read(ctx, prim, g + "textures", "string[]", [])),
            buffers=list(read(ctx, prim, g + "buffers", "string[]", [])),
            color=tuple(read_floats(ctx, prim, g + "color", ("double4",), 4)),
            params=params,
            cull=read(ctx, prim, g + "cull", "string", "back"),
            depth_test=read(ctx, prim, g + "depthTest", "bool", True),
            depth_write=read(ctx, prim, g + "depthWrite", "bool", True),
            blend=read(ctx, prim, g + "blend", "string", "opaque"),
            name=read(ctx, prim, g + "materialName", "string", ""),
        )
    except ResourceError as exc:
        raise ctx.fail(prim, g + exc.field, exc.detail) from None


# --- textures -----------------------------------------------------------------------------------------
def texture_files(file_stem: str, texture: TextureData | CubeTextureData) -> list[str]:
    """The PNG file names (inside the textures folder) that hold ``texture``."""
    if isinstance(texture, CubeTextureData):
        files = [f"{file_stem}_{suffix}.png" for suffix in CUBE_FACE_SUFFIXES]
        for k in range(1, len(texture.levels or ()) + 1):  # explicit mip levels: 6 files per level
            files += [f"{file_stem}_mip{k}_{suffix}.png" for suffix in CUBE_FACE_SUFFIXES]
        return files
    return [f"{file_stem}.png"]


def texture_images(texture: TextureData | CubeTextureData) -> list[np.ndarray]:
    """The images to write, in the order of :func:`texture_files`."""
    if isinstance(texture, CubeTextureData):
        return [*texture.faces, *(face for level in (texture.levels or ()) for face in level)]
    return [texture.pixels]


def write_texture(stage: Usd.Stage, path: str, name: str, texture: TextureData | CubeTextureData,
                  relative_files: list[str]) -> None:
    prim = stage.DefinePrim(path, "Scope")
    cube = isinstance(texture, CubeTextureData)
    write(prim, "gandalf:name", T.String, name)
    write(prim, "gandalf:textureName", T.String, texture.name)
    write(prim, "gandalf:kind", T.String, "cube" if cube else "2d")
    write(prim, "gandalf:files", T.AssetArray, Sdf.AssetPathArray([Sdf.AssetPath(f) for f in relative_files[:6]
                                                                   if cube] or [Sdf.AssetPath(relative_files[0])]))
    if cube and len(relative_files) > 6:  # explicit mip levels below level 0, six faces each
        write(prim, "gandalf:levelFiles", T.AssetArray,
              Sdf.AssetPathArray([Sdf.AssetPath(f) for f in relative_files[6:]]))
    write(prim, "gandalf:srgb", T.Bool, texture.srgb)
    write(prim, "gandalf:filter", T.String, texture.filter)
    write(prim, "gandalf:mipmaps", T.Bool, texture.mipmaps)
    if getattr(texture, "anisotropy", 1) != 1:
        write(prim, "gandalf:anisotropy", T.Int, texture.anisotropy)
    if not cube:
        write(prim, "gandalf:wrap", T.String, texture.wrap)


def _texture_paths(ctx: FileContext, prim: Usd.Prim, attribute: str, folder: Path, allow_outside: bool) -> list[Path]:
    """The PNG files of ``attribute`` (an asset[]), relative ones resolved against ``folder``; each must exist and,
    after symlinks are followed, lie inside ``folder`` unless ``allow_outside``."""
    root = folder.resolve()
    out = []
    for asset in read(ctx, prim, attribute, "asset[]"):
        given = Path(asset.path)
        file = (given if given.is_absolute() else folder / given).resolve()
        if not allow_outside and not file.is_relative_to(root):
            raise ctx.fail(prim, attribute, f"the texture file @{asset.path}@ ({file}) lies outside the scene's "
                                            f"folder {root}: refused (load_scene(..., allow_outside=True) allows it)")
        if file.suffix.lower() != ".png" or not file.is_file():
            raise ctx.fail(prim, attribute, f"texture file {str(file)!r} is missing or not a .png")
        out.append(file)
    return out


def read_texture(ctx: FileContext, prim: Usd.Prim, folder: Path,
                 allow_outside: bool = False) -> tuple[str, TextureData | CubeTextureData]:
    """A texture prim's data; its files must lie in ``folder`` (the scene file's) unless ``allow_outside``."""
    name = read(ctx, prim, "gandalf:name", "string", prim.GetName())
    kind = read(ctx, prim, "gandalf:kind", "string")
    files = read(ctx, prim, "gandalf:files", "asset[]")
    expected = 6 if kind == "cube" else 1
    if kind not in ("cube", "2d") or len(files) != expected:
        raise ctx.fail(prim, "gandalf:files", f"a '{kind}' texture needs {expected} file(s), got {len(files)}")
    paths = _texture_paths(ctx, prim, "gandalf:files", folder, allow_outside)
    settings = {
        "srgb": read(ctx, prim, "gandalf:srgb", "bool", True),
        "filter": read(ctx, prim, "gandalf:filter", "string", "linear"),
        "mipmaps": read(ctx, prim, "gandalf:mipmaps", "bool", True),
        **({"anisotropy": read(ctx, prim, "gandalf:anisotropy", "int")} if authored(prim, "gandalf:anisotropy")
           else {}),
        "name": read(ctx, prim, "gandalf:textureName", "string", name),
    }
    if kind == "cube" and authored(prim, "gandalf:levelFiles"):
        level_files = _texture_paths(ctx, prim, "gandalf:levelFiles", folder, allow_outside)
        if len(level_files) % 6:
            raise ctx.fail(prim, "gandalf:levelFiles", f"needs 6 files per mip level, got {len(level_files)}")
        images = []
        for f in level_files:
            try:
                images.append(TextureData.from_file(f, mipmaps=False).pixels)
            except ResourceError as exc:
                raise ctx.fail(prim, "gandalf:levelFiles", exc.detail) from None
        try:
            settings["levels"] = tuple(np.stack(images[i:i + 6]) for i in range(0, len(images), 6))
        except ValueError:
            raise ctx.fail(prim, "gandalf:levelFiles", "the six faces of a mip level differ in size") from None
    try:
        if kind == "cube":
            return name, CubeTextureData.from_files(paths, **settings)
        return name, TextureData.from_file(paths[0], wrap=read(ctx, prim, "gandalf:wrap", "string", "repeat"),
                                           **settings)
    except ResourceError as exc:
        # The image's own problems (its path, pixels, mode) are the problems of the file named in gandalf:files.
        attribute = "gandalf:files" if exc.field in ("path", "pixels", "mode") else "gandalf:" + exc.field
        raise ctx.fail(prim, attribute, exc.detail) from None

