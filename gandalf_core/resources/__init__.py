"""Backend-neutral resource data: textures, meshes, materials and shader sources.

Nothing here touches a GPU: these are validated numpy/text descriptions that the OpenGL and WebGPU resource
libraries turn into GPU objects. Pillow is imported only when an image file is read or written.
"""

from gandalf_core.resources.errors import ResourceError
from gandalf_core.resources.gltf import GLTFModel, load_gltf
from gandalf_core.resources.material_data import BLEND_MODES, CULL_MODES, MaterialData
from gandalf_core.resources.mesh_data import (
    ATTRIBUTE_LOCATIONS,
    INSTANCE_LOCATIONS,
    MeshData,
    VertexAttribute,
    VertexLayout,
)
from gandalf_core.resources.mesh_loader import MESH_EXTENSIONS, load_mesh, load_meshes
from gandalf_core.resources.primitives import cube, plane, pyramid, quad, torus, triangle, uv_sphere
from gandalf_core.resources.procedural import checkerboard, gradient, sky_cube, solid, value_noise
from gandalf_core.resources.shader_source import (
    LANGUAGES,
    SHADER_EXTENSIONS,
    STAGES,
    ShaderSource,
    format_compile_error,
)
from gandalf_core.resources.texture_data import (
    CUBE_FACE_NAMES,
    FILTER_MODES,
    WRAP_MODES,
    CubeTextureData,
    TextureData,
    cube_face_directions,
    linear_to_srgb,
    srgb_to_linear,
)

__all__ = [
    "GLTFModel",
    "MESH_EXTENSIONS",
    "load_gltf",
    "load_mesh",
    "load_meshes",
    "ATTRIBUTE_LOCATIONS",
    "BLEND_MODES",
    "CUBE_FACE_NAMES",
    "CULL_MODES",
    "FILTER_MODES",
    "INSTANCE_LOCATIONS",
    "LANGUAGES",
    "SHADER_EXTENSIONS",
    "STAGES",
    "WRAP_MODES",
    "CubeTextureData",
    "MaterialData",
    "MeshData",
    "ResourceError",
    "ShaderSource",
    "TextureData",
    "VertexAttribute",
    "VertexLayout",
    "checkerboard",
    "cube",
    "cube_face_directions",
    "format_compile_error",
    "gradient",
    "linear_to_srgb",
    "plane",
    "pyramid",
    "quad",
    "sky_cube",
    "solid",
    "srgb_to_linear",
    "torus",
    "triangle",
    "uv_sphere",
    "value_noise",
]
