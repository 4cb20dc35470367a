"""Tessellation's contract between a program and a mesh, checked the same way for both backends.

A program with a tessellation control stage declares its patch size (``layout(vertices = N) out;``) and can
only draw a patch mesh (``MeshData(..., patch_size=N)``) of the same N; a patch mesh can only be drawn by such a
program. WebGPU has no tessellation stage at all: there a patch mesh is an error that points to the compute route.
"""

from __future__ import annotations

import re

from ..resources import MeshData, ResourceError

_VERTICES_OUT = re.compile(r"layout\s*\(\s*vertices\s*=\s*(\d+)\s*\)\s*out\s*;")


def declared_patch_size(tess_control_glsl: str, filename: str) -> int:
    """The N of a tessellation control shader's ``layout(vertices = N) out;`` (comments ignored)."""
    text = re.sub(r"/\*.*?\*/", " ", tess_control_glsl, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    found = _VERTICES_OUT.findall(text)
    if len(found) != 1:
        raise ResourceError(f"shader file '{filename}'", "layout(vertices = N) out",
                            "a tessellation control shader must declare its patch size exactly once")
    return int(found[0])


def check_patch_draw(material: str, shader: str, shader_patch: int | None, mesh_name: str, mesh: MeshData,
                     backend: str) -> None:
    """Raise a ResourceError naming the material, shader and mesh when they disagree about patches."""
    if shader_patch is None and mesh.patch_size is None:
        return  # the common case, checked first: a triangle program and a triangle mesh
    label = f"material '{material}' (shader '{shader}') with mesh '{mesh_name}'"
    if backend == "webgpu" and mesh.patch_size is not None:
        raise ResourceError(label, "patch_size",
                            f"the mesh is made of patches of {mesh.patch_size}, but WebGPU has no tessellation stage: "
                            "generate the vertices in a compute pass and draw them instead (step07 terrain)")
    if shader_patch is None and mesh.patch_size is not None:
        raise ResourceError(label, "patch_size",
                            f"the mesh is made of patches of {mesh.patch_size}, but the program has no tessellation "
                            "control stage to draw them (build it with tess_control= and tess_evaluation=)")
    if shader_patch is not None and mesh.patch_size is None:
        raise ResourceError(label, "patch_size",
                            f"the program tessellates patches of {shader_patch} (layout(vertices = {shader_patch}) "
                            f"out), but the mesh is a triangle mesh: give it MeshData(..., patch_size={shader_patch})")
    if shader_patch is not None and mesh.patch_size != shader_patch:
        raise ResourceError(label, "patch_size",
                            f"the mesh has patches of {mesh.patch_size}, the program expects {shader_patch}")
