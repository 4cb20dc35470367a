"""The names the USD mapping uses, shared by the writer and the reader (no USD import here).

Layout of a saved scene::

    /Scene                  Xform, the default prim: gandalf:sceneName, gandalf:version, clear colour, skybox
        /<entity>           one prim per entity (Xform, Camera or a UsdLux light), nested like the Links
            /mesh           a visible Mesh referencing /Assets/Meshes/<mesh>, with the material binding
    /Assets                 Scope (invisible)
        /Meshes/<mesh>      UsdGeom.Mesh
        /Materials/<mat>    UsdShade.Material with inputs:gandalf:* values and a UsdPreviewSurface network
        /Textures/<tex>     Scope with gandalf:files (the PNGs next to the USD file)
    /Systems                Scope: one prim per saved system, in update order (gandalf:system = its import path,
        /<System>           gandalf:enabled, gandalf:settings:<name> values, gandalf:functions:<name> functions)

A registered component's fields are ``gandalf:<ClassName>:<field>`` attributes on its entity's prim (an entity
field is a relationship of that name to the entity's prim); the prim's ``gandalf:components`` lists the classes
by import path.
"""

from __future__ import annotations

from pathlib import Path

from gandalf_core import components as core

FORMAT_VERSION = 1
EXTENSIONS = {".usda": "usda", ".usdc": "usdc"}

ROOT = "/Scene"
ASSETS = "/Assets"
MESHES = "/Assets/Meshes"
MATERIALS = "/Assets/Materials"
TEXTURES = "/Assets/Textures"
SYSTEMS = "/Systems"

# --8<-- [start:builtin]
BUILTIN_TYPES = (
    core.InfoComponent,
    core.LinkComponent,
    core.TransformComponent,
    core.CameraComponent,
    core.LightComponent,
    core.MeshComponent,
    core.MaterialComponent,
    core.ClearColorComponent,
    core.SkyboxComponent,
)

# LightComponent.kind <-> UsdLux prim type.
LIGHT_TYPES = {"point": "SphereLight", "directional": "DistantLight", "ambient": "DomeLight"}
LIGHT_KINDS = {v: k for k, v in LIGHT_TYPES.items()}
# --8<-- [end:builtin]

# Camera film back used to express the field of view as focal length / aperture (mm, USD's units for them).
VERTICAL_APERTURE_MM = 24.0
DEFAULT_ASPECT = 4.0 / 3.0  # only for the horizontal aperture of cameras whose aspect follows the target

# The UsdPreviewSurface network inside each material prim (for other USD tools; gandalf reads inputs:gandalf:*).
PREVIEW_SURFACE = "PreviewSurface"
PREVIEW_TEXTURE = "Texture"
PREVIEW_ST_READER = "PrimvarSt"

# The visible Mesh prim inside an entity prim that references its asset mesh (stored once under /Assets).
ENTITY_MESH = "mesh"
ENTITY_MESH_MARK = "gandalf:entityMesh"

CUBE_FACE_SUFFIXES = ("px", "nx", "py", "ny", "pz", "nz")  # +X, -X, +Y, -Y, +Z, -Z


def texture_folder_name(path: Path) -> str:
    """The folder next to the file that holds its textures: ``level.usda`` -> ``level_usda_textures``.

    The extension is part of the name, so ``level.usda`` and ``level.usdc`` never share (and overwrite)
    one folder.
    """
    return f"{path.stem}_{path.suffix.lstrip('.').lower()}_textures"
