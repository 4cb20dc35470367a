"""Backend-neutral resource data: textures, meshes, materials and shader sources.

Nothing here touches a GPU: these are validated numpy/text descriptions that the OpenGL and WebGPU resource
libraries turn into GPU objects. Pillow is imported only when an image file is read or written.

Its names load on first use (module ``__getattr__``): importing the package costs nothing until a loader, a
primitive or a data class is needed.
"""

from __future__ import annotations

from ..lazy import lazy_attributes

# name -> submodule that defines it
_LAZY = {
    "ResourceError": "errors",
    "MeshFileWarning": "errors",
    "GLTFModel": "gltf",
    "GLTFWarning": "gltf_file",
    "load_gltf": "gltf",
    "BLEND_MODES": "material_data",
    "CULL_MODES": "material_data",
    "MaterialData": "material_data",
    "ATTRIBUTE_LOCATIONS": "mesh_data",
    "MeshData": "mesh_data",
    "VertexAttribute": "mesh_data",
    "VertexLayout": "mesh_data",
    "MESH_EXTENSIONS": "mesh_loader",
    "load_mesh": "mesh_loader",
    "load_meshes": "mesh_loader",
    "cube": "primitives",
    "plane": "primitives",
    "pyramid": "primitives",
    "quad": "primitives",
    "torus": "primitives",
    "triangle": "primitives",
    "uv_sphere": "primitives",
    "checkerboard": "procedural",
    "gradient": "procedural",
    "sky_cube": "procedural",
    "solid": "procedural",
    "value_noise": "procedural",
    "LANGUAGES": "shader_source",
    "SHADER_EXTENSIONS": "shader_source",
    "STAGES": "shader_source",
    "ShaderSource": "shader_source",
    "format_compile_error": "shader_source",
    "CUBE_FACE_NAMES": "texture_data",
    "FILTER_MODES": "texture_data",
    "WRAP_MODES": "texture_data",
    "CubeTextureData": "texture_data",
    "TextureData": "texture_data",
    "cube_face_directions": "texture_data",
    "linear_to_srgb": "texture_data",
    "srgb_to_linear": "texture_data",
}

_SUBMODULES = (
    'assets',
    'blocks',
    'color',
    'errors',
    'gltf',
    'material_data',
    'mesh_data',
    'mesh_loader',
    'primitives',
    'procedural',
    'shader_source',
    'texture_data',
)


__getattr__, __dir__ = lazy_attributes(__name__, _LAZY, _SUBMODULES)


__all__ = [
    "GLTFModel",
    "GLTFWarning",
    "MESH_EXTENSIONS",
    "load_gltf",
    "load_mesh",
    "load_meshes",
    "ATTRIBUTE_LOCATIONS",
    "BLEND_MODES",
    "CUBE_FACE_NAMES",
    "CULL_MODES",
    "FILTER_MODES",
    "LANGUAGES",
    "SHADER_EXTENSIONS",
    "STAGES",
    "WRAP_MODES",
    "CubeTextureData",
    "MaterialData",
    "MeshData",
    "MeshFileWarning",
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
