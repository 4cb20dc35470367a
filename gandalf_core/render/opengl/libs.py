"""OpenGL resource libraries: textures, shaders, meshes and materials, built once and cached by name.

As in the paper: ``renderer.textures.build('bricks', TextureData(...))``,
``renderer.shaders.build('unlit', 'unlit.vert', 'unlit.frag')``,
``renderer.materials.build('M_Bricks', MaterialData('unlit', ['bricks']))``. The libraries belong to
one renderer (one GL context), so a fresh renderer starts empty.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import moderngl
import numpy as np

from ...resources import CubeTextureData, MaterialData, MeshData, ResourceError, ShaderSource, TextureData
from ...resources.blocks import BLOCK_BINDINGS, MaterialDeclaration
from ...resources.layout import BlockLayout, LayoutError
from ..builtin_materials import prepare as prepare_builtin
from ..entry_points import check_glsl_main
from ..errors import ShaderCompileError
from ..gpu_memory import buffer_size, chain_bytes
from ..library import ResourceLib
from ..material_block import MATERIAL_BLOCK, block_values, check_glsl_varyings, declared_block, used_block
from ..material_checks import check_parameters
from ..material_values import MaterialValues
from ..patches import declared_patch_size
from ..rebuild import RebuildableShaders
from ..shader_files import load_shader
from ..storage import StorageBufferLib, StorageLayout, buffer_bytes, check_material_buffer, glsl_storage_layouts
from ..texture_checks import check_texture_kinds, check_texture_size
from . import raw_gl

GL_SRGB8_ALPHA8 = 0x8C43
# GL_FLOAT_MAT2, _MAT3, _MAT4 -> size
# The engine's uniform blocks and their binding points (resources/blocks.py states the convention for both APIs).
UNIFORM_BLOCKS = BLOCK_BINDINGS
# The engine's samplers and their reserved texture units (materials use the units from 0 up): the shadow map, and the
# buffer texture of the frame's instance rows (instance.glsl).
ENGINE_SAMPLERS = {"u_shadow_map": 15, "u_instance_rows": 14}
# The engine's loose uniforms, set by the renderer per draw (a material's own values go in its Material block).
ENGINE_UNIFORMS = frozenset({"u_first_instance"})
GL_RGBA8 = 0x8058
# Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ..."; others: "ERROR: 0:12: ..."
_GL_LINE = re.compile(r"^\s*(?:ERROR:\s*)?\d+[:(](\d+)\)?")


def make_current(ctx: moderngl.Context) -> None:
    """Make ``ctx`` current on this thread (EGL or the window's GLX context), with no restore: the caller's context
    stays current until another renderer makes its own current. (moderngl's ``with ctx:`` restores the previous
    context on exit, which goes wrong when two contexts nest; glcontext's plain enter does just the switch.)"""
    ctx.mglo._context.__enter__()


class _InContext:
    """GL objects are made in their renderer's context, whichever another Application made current."""

    ctx: moderngl.Context

    def build(self, name: str, data: Any) -> Any:
        if name not in self._items:  # type: ignore[attr-defined]
            make_current(self.ctx)
        return super().build(name, data)  # type: ignore[misc]


# --- textures -------------------------------------------------------------------------------------
class TextureLib(_InContext, ResourceLib[Any]):
    kind = "texture"

    def __init__(self, ctx: moderngl.Context, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.ctx = ctx

    def _create(self, name: str, data: TextureData | CubeTextureData) -> Any:
        cube = isinstance(data, CubeTextureData)
        key = "GL_MAX_CUBE_MAP_TEXTURE_SIZE" if cube else "GL_MAX_TEXTURE_SIZE"
        check_texture_size(name, data, int(self.ctx.info[key]), key)
        fmt = GL_SRGB8_ALPHA8 if data.srgb else GL_RGBA8
        if isinstance(data, CubeTextureData) and data.levels is None:
            # Each face goes straight from its own array (no stacked copy, no bytes copy) and the mip levels are
            # made on the GPU (glGenerateMipmap; sRGB levels are averaged in linear light by the driver): a sky of
            # six 2048² faces costs no CPU memory beyond the faces themselves.
            if data.mipmaps and raw_gl.has_texture_storage(self.ctx.version_code, self.ctx.extensions):
                tex = raw_gl.CubeTexture(data.size, data.mip_levels, fmt)  # every level allocated once
            else:
                tex = self.ctx.texture_cube((data.size, data.size), 4, None, internal_format=fmt)
            data.write_faces(tex.write)  # one face held at a time (a sky from files is decoded face by face)
            if data.mipmaps:
                tex.build_mipmaps(0, data.mip_levels - 1)
            return self._finish(tex, data, data.mipmaps)
        chain = data.mip_chain() if data.mipmaps else None
        if isinstance(data, CubeTextureData):
            levels = chain or [data.pixels]
            tex = self.ctx.texture_cube((data.size, data.size), 4, levels[0], internal_format=fmt)
        else:
            levels = chain or [data.pixels]
            tex = self.ctx.texture((data.width, data.height), 4, levels[0], internal_format=fmt)
        if chain:
            tex.build_mipmaps(0, len(chain) - 1)
            if not isinstance(data, CubeTextureData):
                # Replace the driver's levels with ours (averaged in linear light), as the WebGPU backend
                # uploads; moderngl cannot write the levels of a cube map, which keep the driver's ...
                for level, pixels in enumerate(chain[1:], start=1):
                    tex.write(pixels, level=level)
            elif data.levels is not None:
                # ... unless they are given explicitly (a prefiltered environment): then glTexSubImage2D writes them.
                self._write_cube_levels(tex, chain)
        return self._finish(tex, data, bool(chain))

    def _finish(self, tex: Any, data: TextureData | CubeTextureData, mipmapped: bool) -> Any:
        linear = moderngl.LINEAR_MIPMAP_LINEAR if mipmapped else moderngl.LINEAR
        nearest = moderngl.NEAREST_MIPMAP_NEAREST if mipmapped else moderngl.NEAREST
        tex.filter = (linear, moderngl.LINEAR) if data.filter == "linear" else (nearest, moderngl.NEAREST)
        if getattr(data, "anisotropy", 1) > 1:
            tex.anisotropy = float(data.anisotropy)
        if isinstance(data, TextureData):
            tex.repeat_x = tex.repeat_y = data.wrap == "repeat"
        self.stats["textures_created"] += 1
        return tex

    # glTexSubImage2D(target, level, x, y, width, height, format, type, pixels), loaded through the context's own
    # loader (moderngl 5.13's TextureCube.write has no level): glcontext's ``load`` for a standalone context (EGL,
    # GLX, WGL, CGL), moderngl's DefaultLoader ``load_opengl_function`` for a window's context (glfw).
    _GL_TEXTURE_CUBE_MAP_POSITIVE_X, _GL_RGBA, _GL_UNSIGNED_BYTE = 0x8515, 0x1908, 0x1401

    def _write_cube_levels(self, tex: Any, chain: list[np.ndarray]) -> None:
        import ctypes

        loader = getattr(self.ctx.mglo, "_context", None)
        load = getattr(loader, "load", None) or getattr(loader, "load_opengl_function", None)
        address = load("glTexSubImage2D") if load is not None else 0
        if not address:
            raise RuntimeError(f"cannot load glTexSubImage2D through this context's loader "
                               f"({type(loader).__name__}) to write cube-map levels")
        sub_image = ctypes.CFUNCTYPE(None, *[ctypes.c_uint] + [ctypes.c_int] * 5 + [ctypes.c_uint] * 2
                                     + [ctypes.c_void_p])(address)
        tex.use(0)  # binds it to GL_TEXTURE_CUBE_MAP on unit 0; materials bind their own units before drawing
        for level, pixels in enumerate(chain[1:], start=1):
            size = pixels.shape[1]
            for face in range(6):
                face_pixels = np.ascontiguousarray(pixels[face])
                sub_image(self._GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, level, 0, 0, size, size, self._GL_RGBA,
                          self._GL_UNSIGNED_BYTE, face_pixels.ctypes.data)

    def _gpu_bytes(self, item: Any, data: TextureData | CubeTextureData) -> int:
        # Every level the texture has: the data's chain, or all of them where the GL makes them (glGenerateMipmap).
        cube = isinstance(data, CubeTextureData)
        width, height = (data.size, data.size) if cube else (data.width, data.height)
        return chain_bytes(width, height, 4, data.mip_levels, 6 if cube else 1)

    def _release(self, item: Any) -> None:
        item.release()


# --- shaders --------------------------------------------------------------------------------------
@dataclass
class GLShader:
    """A linked program with what the renderer needs from its introspection."""

    name: str
    program: moderngl.Program
    attributes: dict[int, str]  # location -> attribute name in the shader
    samplers: list[str]  # sampler uniforms in declaration order (texture unit = index)
    uniforms: set[str] = field(default_factory=set)
    patch_vertices: int | None = None  # with a tessellation control stage: its layout(vertices = N)
    storage_blocks: list[str] = field(default_factory=list)  # shader storage blocks in declaration order
    active_storage: dict[str, int] = field(default_factory=dict)  # block -> binding, of the blocks still in use
    cube_samplers: dict[str, bool] = field(default_factory=dict)  # sampler -> samples a cube map
    source: str = ""  # the stage files, for messages
    #: The std140 layout of the program's ``uniform Material { ... } material;`` block, or None.
    material_block: BlockLayout | None = None
    #: The bytes each storage block needs (std430), by block name, where its declaration can be laid out.
    storage_layouts: dict[str, StorageLayout] = field(default_factory=dict)


class ShaderLib(RebuildableShaders, ResourceLib[GLShader]):
    kind = "shader"

    def __init__(self, ctx: moderngl.Context, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.ctx = ctx
        self._recipes: dict[str, tuple[tuple[Any, ...], dict[str, Any]]] = {}

    def build(
        self,
        name: str,
        vertex: str | Path | ShaderSource,
        fragment: str | Path | ShaderSource,
        geometry: str | Path | ShaderSource | None = None,
        tess_control: str | Path | ShaderSource | None = None,
        tess_evaluation: str | Path | ShaderSource | None = None,
        *,
        include_dirs: Sequence[str | Path] = (),
        material: MaterialDeclaration | None = None,
    ) -> GLShader:
        """Compile and link a program from files (or ShaderSource); cached by ``name``.

        ``include_dirs`` are searched for ``#include`` files after the shader's own folder. ``material`` declares
        the program's Material block (fields, or a BlockLayout; by default the colour alone), which the stages
        declare with ``#include "material.glsl"``.
        """
        if name in self._items:
            return self._items[name]
        args = (vertex, fragment, geometry, tess_control, tess_evaluation)
        kwargs = {"include_dirs": include_dirs, "material": material}
        shader, stages = self._compile(name, *args, **kwargs)
        self._items[name] = shader
        self._data[name] = stages
        self._remember(name, args, kwargs)
        return shader

    def _compile(self, name: str, vertex: Any, fragment: Any, geometry: Any, tess_control: Any, tess_evaluation: Any,
                 include_dirs: Sequence[str | Path], material: MaterialDeclaration | None,
                 texts: Mapping[Path, str] | None = None) -> tuple[GLShader, dict[str, ShaderSource]]:
        """The linked program and its stages (``texts``: file text to use instead of the disk's, by path)."""
        make_current(self.ctx)  # this renderer's context, whichever another Application made current
        layout, generated = declared_block(name, material)
        stages = {
            "vertex_shader": load_shader(vertex, "vertex", "glsl", include_dirs, generated, texts),
            "fragment_shader": load_shader(fragment, "fragment", "glsl", include_dirs, generated, texts),
        }
        for key, src, stage in (
            ("geometry_shader", geometry, "geometry"),
            ("tess_control_shader", tess_control, "tess_control"),
            ("tess_evaluation_shader", tess_evaluation, "tess_evaluation"),
        ):
            if src is not None:
                stages[key] = load_shader(src, stage, "glsl", include_dirs, generated, texts)
        for src in stages.values():
            check_glsl_main(src)
        material_block = used_block(name, layout, list(stages.values()), material is not None)
        if (varying := check_glsl_varyings(name, stages)) is not None:
            raise ShaderCompileError(varying)
        patch_vertices = None
        if "tess_evaluation_shader" in stages:
            if "tess_control_shader" not in stages:
                raise ShaderCompileError(
                    f"shader '{name}' ({stages['tess_evaluation_shader'].filename}): a tessellation evaluation stage "
                    "needs a tessellation control stage here (its layout(vertices = N) gives the patch size)"
                )
            control = stages["tess_control_shader"]
            patch_vertices = declared_patch_size(control.text, control.filename)
        elif "tess_control_shader" in stages:
            raise ShaderCompileError(f"shader '{name}' ({stages['tess_control_shader'].filename}): a tessellation "
                                     "control stage needs a tessellation evaluation stage (tess_evaluation=)")
        try:
            program = self.ctx.program(**{k: v.text for k, v in stages.items()})
        except moderngl.Error as exc:
            raise ShaderCompileError(_explain_gl_error(name, str(exc), stages)) from None
        self.stats["shaders_created"] += 1
        attributes, uniforms, active_storage = {}, set(), {}
        for member in program:
            obj = program[member]
            if isinstance(obj, moderngl.Attribute):
                if not member.startswith("gl_"):  # gl_VertexID and friends are built-ins, not mesh attributes
                    attributes[obj.location] = member
            elif isinstance(obj, moderngl.Uniform):
                uniforms.add(member)
            elif isinstance(obj, moderngl.UniformBlock) and member in UNIFORM_BLOCKS:
                obj.binding = UNIFORM_BLOCKS[member]
            elif isinstance(obj, moderngl.StorageBlock):
                active_storage[member] = obj.binding
        # Texture unit i belongs to the i-th sampler declared (also one the compiler dropped as unused, so
        # a material's textures line up with the source the student reads, as with WGSL bindings).
        # The engine's own samplers (the shadow map) keep their reserved units and are no material texture.
        declared = (name for src in stages.values() for name in _declared_samplers(src.text))
        samplers = list(dict.fromkeys(name for name in declared if name not in ENGINE_SAMPLERS))
        units = {**{sampler: unit for unit, sampler in enumerate(samplers)}, **ENGINE_SAMPLERS}
        for sampler, unit in units.items():
            if sampler not in uniforms:
                continue
            if program[sampler].gl_type in raw_gl.GL_BUFFER_SAMPLER_TYPES:  # moderngl ignores their value
                raw_gl.set_sampler_unit(program.glo, program[sampler].location, unit)
            else:
                program[sampler].value = unit
        storage_blocks = list(dict.fromkeys(b for src in stages.values() for b in _declared_storage_blocks(src.text)))
        kinds = dict(kind for src in stages.values() for kind in _declared_sampler_kinds(src.text))
        values = {k: v for src in stages.values() for k, v in _declared_material_uniforms(src.text).items()
                  if f"u_{k}" not in ENGINE_UNIFORMS}
        files = ", ".join(src.filename for src in stages.values())
        try:
            if material_block is not None:
                _check_block_against_driver(name, files, program, material_block)
            if values:
                raise ShaderCompileError(f"shader '{name}' ({files}): declares loose material uniforms "
                                         f"({', '.join('u_' + v for v in values)}); a material's values go in one "
                                         "'layout(std140) uniform Material { ... } material;' block, the same fields "
                                         "as WGSL's Material struct")
        except ShaderCompileError:
            program.release()  # a program refused here is never drawn with (a rebuild keeps the last good one)
            raise
        shader = GLShader(name, program, attributes, samplers, uniforms, patch_vertices, storage_blocks, active_storage,
                          {s: "Cube" in kinds.get(s, "") for s in samplers}, files, material_block,
                          glsl_storage_layouts([src.text for src in stages.values()]))
        return shader, stages

    def _release(self, item: GLShader) -> None:
        item.program.release()


def _check_block_against_driver(name: str, files: str, program: moderngl.Program, block: BlockLayout) -> None:
    """The driver's offsets of the Material block's members must be the ones the engine packs (a member the
    engine's reading of the GLSL got wrong would otherwise read the wrong bytes silently)."""
    from .raw_gl import block_members

    try:
        driver = block_members(program.glo).get(MATERIAL_BLOCK)
    except (RuntimeError, OSError):  # no GL library to ask: the std140 rule stands on its own
        return
    if not driver:
        return  # the block is never read: nothing to compare
    declared = {path: offset for path, offset, _type in block.leaves()}
    for member, (offset, _stride) in driver.items():
        field = member.split(".", 1)[1] if member.startswith(MATERIAL_BLOCK + ".") else member
        if declared.get(field, offset) != offset:
            raise ShaderCompileError(f"shader '{name}' ({files}): the driver puts Material field '{field}' at offset "
                                     f"{offset}, the engine's std140 layout at {declared[field]}: declare the block "
                                     "with layout(std140) and plain members")


def _declared_samplers(glsl: str) -> list[str]:
    """Sampler uniform names in declaration order (comments stripped; formatting does not matter)."""
    return [name for name, _kind in _declared_sampler_kinds(glsl)]


def _declared_sampler_kinds(glsl: str) -> list[tuple[str, str]]:
    """(name, GLSL type) of every sampler uniform, in declaration order."""
    text = re.sub(r"/\*.*?\*/", " ", glsl, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    tokens = re.findall(r"[A-Za-z_]\w*|[;{}]", text)
    found = []
    for i, tok in enumerate(tokens[:-2]):
        if tok == "uniform" and tokens[i + 1].startswith(("sampler", "isampler", "usampler")):
            found.append((tokens[i + 2], tokens[i + 1]))
    return found


_MATERIAL_UNIFORM = re.compile(r"\buniform\s+(?!sampler|isampler|usampler)[A-Za-z_]\w*\s+u_([A-Za-z_]\w*)\s*"
                               r"(?:\[[^\]]*\]\s*)?(=)?")


def _declared_material_uniforms(glsl: str) -> dict[str, bool]:
    """Loose ``uniform <type> u_<name>`` declarations of a GLSL stage (not samplers, not blocks) -> whether it
    states a default (``= value``), comments stripped: refused in a material's program (values go in its block)."""
    text = re.sub(r"/\*.*?\*/", " ", glsl, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    return {m.group(1): m.group(2) is not None for m in _MATERIAL_UNIFORM.finditer(text)}


def _declared_storage_blocks(glsl: str) -> list[str]:
    """Shader storage block names (``... buffer Name { ... }``) in declaration order, comments stripped."""
    text = re.sub(r"/\*.*?\*/", " ", glsl, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    return re.findall(r"\bbuffer\s+([A-Za-z_]\w*)\s*\{", text)


def _explain_gl_error(name: str, message: str, stages: dict[str, ShaderSource]) -> str:
    """Turn moderngl's compiler log into ``file:line: message`` lines for the stage that failed."""
    lines = message.splitlines()
    current: ShaderSource | None = None
    out = []
    for line in lines:
        key = line.strip()
        if key in stages:
            current = stages[key]
            continue
        match = _GL_LINE.match(line)
        if match and current is not None:
            out.append(current.format_error(int(match.group(1)), line.strip()))
    if not out:
        files = ", ".join(s.filename for s in stages.values())
        out.append(f"shader '{name}' ({files}): {message.strip()}")
    return "\n".join(out)


# --- meshes ---------------------------------------------------------------------------------------
@dataclass
class GLMesh:
    name: str
    data: MeshData
    index_buffer: moderngl.Buffer | None
    vertex_buffers: dict[tuple[str, ...], moderngl.Buffer] = field(default_factory=dict)

    @property
    def count(self) -> int:
        return self.data.index_count if self.index_buffer is not None else self.data.vertex_count


class MeshLib(_InContext, ResourceLib[GLMesh]):
    kind = "mesh"

    def __init__(self, ctx: moderngl.Context, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.ctx = ctx

    def _create(self, name: str, data: MeshData) -> GLMesh:
        ibo = None
        if data.indices is not None:
            ibo = self.ctx.buffer(np.ascontiguousarray(data.indices, dtype=np.uint32).tobytes())
            self.stats["buffers_created"] += 1
        return GLMesh(name, data, ibo)

    def vertex_buffer(self, mesh: GLMesh, attributes: tuple[str, ...]) -> tuple[moderngl.Buffer, Any]:
        """The interleaved buffer with exactly ``attributes`` (built once per attribute set)."""
        data, layout = mesh.data.interleaved(attributes)
        if attributes not in mesh.vertex_buffers:
            mesh.vertex_buffers[attributes] = self.ctx.buffer(data.tobytes())
            self.stats["buffers_created"] += 1
        return mesh.vertex_buffers[attributes], layout

    def _gpu_bytes(self, item: GLMesh, data: MeshData) -> int:
        return buffer_size(item.index_buffer) + sum(buffer_size(b) for b in item.vertex_buffers.values())

    def _release(self, item: GLMesh) -> None:
        for buf in item.vertex_buffers.values():
            buf.release()
        if item.index_buffer is not None:
            item.index_buffer.release()


# --- storage buffers -------------------------------------------------------------------------------
class BufferLib(StorageBufferLib, _InContext, ResourceLib[moderngl.Buffer]):
    """Storage buffers by name, for materials that read them (vertex pulling) and the compute code that fills them.

    ``build(name, data)``: ``data`` is a numpy array (its bytes) or a size in bytes (zeros); building a name again
    writes the new data into its buffer (same size) or is an error (:class:`~gandalf_core.render.storage.
    StorageBufferLib`).
    """

    kind = "buffer"

    def __init__(self, ctx: moderngl.Context, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.ctx = ctx

    def _create(self, name: str, data: Any) -> moderngl.Buffer:
        content, size = buffer_bytes(name, data)
        buf = self.ctx.buffer(content) if content is not None else self.ctx.buffer(reserve=size)
        if content is None:
            buf.clear()
        self.stats["buffers_created"] += 1
        return buf

    def _write(self, buffer: moderngl.Buffer, content: bytes) -> None:
        make_current(self.ctx)
        buffer.write(content)

    def _gpu_bytes(self, item: moderngl.Buffer, data: Any) -> int:
        return buffer_size(item)

    def _release(self, item: moderngl.Buffer) -> None:
        item.release()


# --- materials ------------------------------------------------------------------------------------
class GLMaterial(MaterialValues):
    """A material instance: its shader, textures and uniform values (changeable without rebuilding).

    The values fill the program's std140 ``Material`` block by field name (its own uniform buffer, bound to
    binding point ``BLOCK_BINDINGS["Material"]`` when drawn): the same bytes as WebGPU's ``Material`` struct. A
    matrix given as 9 or 16 row-major floats is written column by column.
    """

    def __init__(self, name: str, data: MaterialData, shader: GLShader, textures: list[Any],
                 buffers: list[moderngl.Buffer] | None = None) -> None:
        buffers = buffers or []
        if len(textures) != len(shader.samplers):
            raise ResourceError(
                f"material '{name}'", "textures",
                f"{len(textures)} texture(s) given but shader '{shader.name}' samples {len(shader.samplers)} "
                f"({', '.join(shader.samplers) or 'none'})",
            )
        if len(buffers) != len(shader.storage_blocks):
            raise ResourceError(
                f"material '{name}'", "buffers",
                f"{len(buffers)} buffer(s) given but shader '{shader.name}' declares {len(shader.storage_blocks)} "
                f"storage block(s) ({', '.join(shader.storage_blocks) or 'none'})",
            )
        for block, binding in shader.active_storage.items():
            if binding >= len(buffers):
                raise ResourceError(f"material '{name}'", "buffers",
                                    f"shader '{shader.name}' reads storage block '{block}' at binding {binding}, but "
                                    f"the material binds buffers 0..{len(buffers) - 1} (declare binding = its index)")
            check_material_buffer(name, shader.name, data.buffers[binding], buffers[binding].size,
                                  shader.storage_layouts.get(block))
        self.name, self.data, self.shader, self.textures = name, data, shader, textures
        self.buffers = buffers
        self.block_buffer: moderngl.Buffer | None = None
        self.block_bytes = b""
        self.set_values(data.uniform_values())

    def _upload(self) -> None:
        block = self.shader.material_block
        if block is not None:
            try:
                self.block_bytes = block.pack(block_values(block, self.values))
            except LayoutError as exc:
                raise ResourceError(f"material '{self.name}'", "params",
                                    f"shader '{self.shader.name}' ({self.shader.source}): {exc}") from None
            make_current(self.shader.program.ctx)  # whichever Application's context was current
            if self.block_buffer is None:
                self.block_buffer = self.shader.program.ctx.buffer(self.block_bytes)
            else:
                self.block_buffer.write(self.block_bytes)

    def apply(self) -> None:
        if self.block_buffer is not None:
            self.block_buffer.bind_to_uniform_block(BLOCK_BINDINGS[MATERIAL_BLOCK])
        for unit, texture in enumerate(self.textures):
            texture.use(location=unit)
        for binding, buffer in enumerate(self.buffers):
            buffer.bind_to_storage_buffer(binding)


class MaterialLib(ResourceLib[GLMaterial]):
    kind = "material"

    def __init__(self, shaders: ShaderLib, textures: TextureLib, stats: Counter[str],
                 buffers: BufferLib | None = None) -> None:
        super().__init__(stats)
        self.shaders, self.textures, self.buffers = shaders, textures, buffers
        # A shader rebuilt from new text (or released) takes the materials built with it along.
        shaders.on_forget.append(lambda shader: self.renew_where(lambda material: material.shader.name == shader))

    def _create(self, name: str, data: MaterialData) -> GLMaterial:
        referrer = f"material '{name}'"
        data = prepare_builtin(self.shaders, name, data, "glsl")  # gandalf.unlit, gandalf.blinn_phong
        shader = self.shaders.get(data.shader, referrer)
        textures = [self.textures.get(tex, referrer) for tex in data.textures]
        if data.buffers and self.buffers is None:
            raise ResourceError(referrer, "buffers", "this material library has no buffer library")
        buffers = [self.buffers.get_for(buf, "storage", referrer) for buf in data.buffers]
        check_texture_kinds(name, shader.name, [(s, shader.cube_samplers.get(s, False)) for s in shader.samplers],
                            [(t, self.textures.data_of(t)) for t in data.textures])
        block = shader.material_block
        fields = {f.name: f.has_default for f in block.fields} if block is not None else {}
        check_parameters(name, shader.name, shader.source, data.params, fields)
        return GLMaterial(name, data, shader, textures, buffers)

    def _gpu_bytes(self, item: GLMaterial, data: MaterialData) -> int:
        return buffer_size(item.block_buffer)  # made on the material's first draw

    def _release(self, item: GLMaterial) -> None:
        if item.block_buffer is not None:
            item.block_buffer.release()
