"""WebGPU resource libraries: textures, shaders, meshes and materials, built once and cached by name.

As in the paper: ``renderer.textures.build('bricks', TextureData(...))``,
``renderer.shaders.build('unlit', 'unlit.wgsl')``,
``renderer.materials.build('M_Bricks', MaterialData('unlit', ['bricks']))``.

Bindings come from the shader itself (:mod:`gandalf_core.render.wgsl_reflect`): group 0 is the engine's
(binding 0: the frame uniforms), group 1 the material's (binding 0: its uniform struct, then a texture
and a sampler for each of the material's textures, in order).
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import wgpu

from ...resources import CubeTextureData, MaterialData, MeshData, ResourceError, ShaderSource, TextureData
from ...resources.blocks import WGSL_BINDINGS, MaterialDeclaration
from ...resources.layout import BlockLayout, LayoutError
from ..builtin_materials import prepare as prepare_builtin
from ..errors import ShaderCompileError
from ..library import ResourceLib
from ..material_block import block_values, check_wgsl_varyings, declared_block, used_block
from ..material_checks import check_parameters
from ..material_values import MaterialValues
from ..shader_files import load_shader
from ..storage import buffer_bytes
from ..texture_checks import check_texture_kinds, check_texture_size
from ..wgsl_reflect import Binding, ShaderReflection, WGSLReflectError, reflect

_ADDRESS = {"repeat": "repeat", "clamp": "clamp-to-edge"}
_NAGA_LINE = re.compile(r"(?:wgsl|<[^>]*>|\S+\.wgsl):(\d+):(\d+)")
MATERIAL_GROUP = WGSL_BINDINGS["Material"][0]  # the one convention: resources/blocks.py


# --- textures -------------------------------------------------------------------------------------
@dataclass
class WGPUTexture:
    texture: Any
    view: Any
    sampler: Any


class TextureLib(ResourceLib[WGPUTexture]):
    kind = "texture"

    def __init__(self, device: Any, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.device = device

    def _create(self, name: str, data: TextureData | CubeTextureData) -> WGPUTexture:
        check_texture_size(name, data, int(self.device.limits["max-texture-dimension-2d"]),
                           "max-texture-dimension-2d")
        cube = isinstance(data, CubeTextureData)
        fmt = "rgba8unorm-srgb" if data.srgb else "rgba8unorm"
        usage = wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST
        if cube and data.levels is None and data.mipmaps and _is_power_of_two(data.size):
            # A cube map's faces go up one by one from their own arrays (no stacked copy) and its mip levels are
            # made on the GPU, each the exact 2x2 box average of the level above (one bilinear tap at the texel
            # corner), in linear light for sRGB: no CPU mip chain (6 x 2048² faces: ~0.5 GB of floats).
            usage |= wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC
            texture = self.device.create_texture(size=(data.size, data.size, 6), mip_level_count=data.mip_levels,
                                                 format=fmt, usage=usage, label=name)
            for face, pixels in enumerate(data.faces):
                self._write(texture, 0, face, pixels)
            self._downsample(texture, fmt, data.size, data.mip_levels)
        else:
            chain = data.mip_chain() if data.mipmaps else [data.pixels]
            height, width = chain[0].shape[-3:-1]
            layers = 6 if cube else 1
            texture = self.device.create_texture(size=(width, height, layers), mip_level_count=len(chain),
                                                 format=fmt, usage=usage, label=name)
            for level, pixels in enumerate(chain):
                for layer in range(layers):
                    self._write(texture, level, layer, pixels[layer] if cube else pixels)
            del chain
        view = texture.create_view(dimension="cube" if cube else "2d")
        linear = data.filter == "linear"
        address = "clamp-to-edge" if cube else _ADDRESS[data.wrap]
        sampler = self.device.create_sampler(
            address_mode_u=address, address_mode_v=address, address_mode_w=address,
            mag_filter="linear" if linear else "nearest",
            min_filter="linear" if linear else "nearest",
            mipmap_filter="linear" if linear else "nearest",
            max_anisotropy=getattr(data, "anisotropy", 1),
        )
        self.stats["textures_created"] += 1
        return WGPUTexture(texture, view, sampler)

    def _write(self, texture: Any, level: int, layer: int, pixels: np.ndarray) -> None:
        h, w = pixels.shape[:2]
        self.device.queue.write_texture({"texture": texture, "mip_level": level, "origin": (0, 0, layer)},
                                        np.ascontiguousarray(pixels), {"offset": 0, "bytes_per_row": w * 4,
                                                                       "rows_per_image": h}, (w, h, 1))

    def _downsample(self, texture: Any, fmt: str, size: int, levels: int) -> None:
        """Fill mip levels 1.. of every layer of ``texture`` from level 0, one render pass per layer and level."""
        pipeline, sampler = self._mip_pipeline(fmt)
        encoder = self.device.create_command_encoder(label="mip levels")
        layout = pipeline.get_bind_group_layout(0)
        for layer in range(texture.size[2]):
            for level in range(1, levels):
                src = texture.create_view(dimension="2d", base_mip_level=level - 1, mip_level_count=1,
                                          base_array_layer=layer, array_layer_count=1)
                dst = texture.create_view(dimension="2d", base_mip_level=level, mip_level_count=1,
                                          base_array_layer=layer, array_layer_count=1)
                group = self.device.create_bind_group(layout=layout, entries=[
                    {"binding": 0, "resource": src}, {"binding": 1, "resource": sampler}])
                rp = encoder.begin_render_pass(color_attachments=[{
                    "view": dst, "load_op": "clear", "store_op": "store", "clear_value": (0, 0, 0, 0)}])
                rp.set_pipeline(pipeline)
                rp.set_bind_group(0, group)
                rp.draw(3)
                rp.end()
        self.device.queue.submit([encoder.finish()])

    def _mip_pipeline(self, fmt: str) -> tuple[Any, Any]:
        cache = self.__dict__.setdefault("_mip_pipelines", {})
        if fmt not in cache:
            module = self.device.create_shader_module(code=_MIP_WGSL, label="mip downsample")
            pipeline = self.device.create_render_pipeline(
                layout="auto",
                vertex={"module": module, "entry_point": "vs"},
                fragment={"module": module, "entry_point": "fs", "targets": [{"format": fmt}]},
                primitive={"topology": "triangle-list"},
                label=f"mip downsample {fmt}",
            )
            sampler = self.device.create_sampler(mag_filter="linear", min_filter="linear",
                                                 address_mode_u="clamp-to-edge", address_mode_v="clamp-to-edge")
            cache[fmt] = (pipeline, sampler)
        return cache[fmt]

    def _release(self, item: WGPUTexture) -> None:
        item.texture.destroy()


def _is_power_of_two(n: int) -> bool:
    return n > 0 and n & (n - 1) == 0


# One full-screen triangle; each target texel's centre maps to the shared corner of its 2x2 source texels, where
# one bilinear tap is their exact average (sampled as linear light from an -srgb view, encoded again on store).
_MIP_WGSL = """
@group(0) @binding(0) var src: texture_2d<f32>;
@group(0) @binding(1) var smp: sampler;
struct VOut { @builtin(position) pos: vec4<f32>, @location(0) uv: vec2<f32> };
@vertex fn vs(@builtin(vertex_index) i: u32) -> VOut {
    let p = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    var out: VOut;
    out.pos = vec4<f32>(p * 2.0 - 1.0, 0.0, 1.0);
    out.uv = vec2<f32>(p.x, 1.0 - p.y);
    return out;
}
@fragment fn fs(v: VOut) -> @location(0) vec4<f32> {
    return textureSampleLevel(src, smp, v.uv, 0.0);
}
"""


# --- shaders --------------------------------------------------------------------------------------
@dataclass
class WGPUShader:
    """A compiled module and its reflection."""

    name: str
    module: Any
    source: ShaderSource
    reflection: ShaderReflection
    vertex_entry: str
    fragment_entry: str
    attributes: dict[int, str]  # location -> vertex input name
    material_layout: Any  # the bind group layout of group 1, or None
    material_bindings: list[Binding] = field(default_factory=list)
    #: The WGSL uniform layout of its ``@group(1) @binding(0)`` Material struct, or None.
    material_block: BlockLayout | None = None


class ShaderLib(ResourceLib[WGPUShader]):
    kind = "shader"

    def __init__(self, device: Any, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.device = device

    def build(self, name: str, source: str | Path | ShaderSource, *, vertex_entry: str | None = None,
              fragment_entry: str | None = None, include_dirs: Sequence[str | Path] = (),
              material: MaterialDeclaration | None = None) -> WGPUShader:
        """Compile a WGSL module (a ``.wgsl`` path or ShaderSource) and reflect it; cached by ``name``.

        ``include_dirs`` are searched for ``#include`` files after the shader's own folder. ``material`` declares
        the module's Material block (fields, or a BlockLayout; by default the colour alone), which it declares with
        ``#include "material.wgsl"``.
        """
        if name in self._items:
            return self._items[name]
        declared, generated = declared_block(name, material)
        src = load_shader(source, None, "wgsl", include_dirs, generated)
        block = used_block(name, declared, [src], material is not None)
        try:
            reflection = reflect(src.text, src.filename)
        except WGSLReflectError as exc:
            line = int(m.group(1)) if (m := re.search(r":(\d+):", str(exc))) else 0
            raise ShaderCompileError(src.format_error(line, str(exc).split(": ", 1)[-1])) from None
        try:
            module = self.device.create_shader_module(code=src.text, label=src.filename)
        except wgpu.GPUError as exc:
            raise ShaderCompileError(_explain_naga_error(src, str(exc))) from None
        self.stats["shaders_created"] += 1
        vs = _entry(reflection, "vertex", vertex_entry, src.filename)
        fs = _entry(reflection, "fragment", fragment_entry, src.filename)
        attributes = {vi.location: vi.name for vi in reflection.entry_points[vs].vertex_inputs}
        if (varying := check_wgsl_varyings(name, src.filename, reflection, vs, fs)) is not None:
            raise ShaderCompileError(varying)
        material_bindings = reflection.group(MATERIAL_GROUP)
        layout = None
        if material_bindings:
            layout = self.device.create_bind_group_layout(
                entries=[_layout_entry(b) for b in material_bindings], label=f"{name} material"
            )
        shader = WGPUShader(name, module, src, reflection, vs, fs, attributes, layout, material_bindings, block)
        self._items[name] = shader
        self._data[name] = src
        return shader


def _entry(reflection: ShaderReflection, stage: str, wanted: str | None, filename: str) -> str:
    names = [e.name for e in reflection.entry_points.values() if e.stage == stage]
    if wanted is not None:
        if wanted not in names:
            raise ShaderCompileError(f"{filename}: no @{stage} entry point named '{wanted}' (have: {names})")
        return wanted
    if len(names) != 1:
        raise ShaderCompileError(
            f"{filename}: expected exactly one @{stage} entry point, found {len(names)} ({names}); name one"
        )
    return names[0]


def _explain_naga_error(src: ShaderSource, message: str) -> str:
    match = _NAGA_LINE.search(message)
    if match is None:
        return f"{src.filename}: {message.strip()}"
    first = next((ln.strip() for ln in message.splitlines() if ln.strip().startswith("error")), message.strip())
    return src.format_error(int(match.group(1)), first)


def _layout_entry(b: Binding) -> dict[str, Any]:
    stage = wgpu.ShaderStage
    visibility = 0
    for name, flag in (("vertex", stage.VERTEX), ("fragment", stage.FRAGMENT), ("compute", stage.COMPUTE)):
        if name in b.stages:
            visibility |= flag
    entry: dict[str, Any] = {"binding": b.binding, "visibility": visibility or stage.FRAGMENT}
    if b.kind == "uniform":
        entry["buffer"] = {"type": "uniform"}
    elif b.kind in ("storage", "read-only-storage"):
        entry["buffer"] = {"type": b.kind}
    elif b.kind == "texture":
        entry["texture"] = {"sample_type": b.sample_type, "view_dimension": b.view_dimension,
                            "multisampled": b.multisampled}
    elif b.kind in ("sampler", "comparison-sampler"):
        entry["sampler"] = {"type": "comparison" if b.kind == "comparison-sampler" else "filtering"}
    else:
        raise ShaderCompileError(f"binding '{b.name}' ({b.kind}) is not supported in a material's group")
    return entry


# --- meshes ---------------------------------------------------------------------------------------
@dataclass
class WGPUMesh:
    name: str
    data: MeshData
    index_buffer: Any
    vertex_buffers: dict[tuple[str, ...], tuple[Any, Any]] = field(default_factory=dict)

    @property
    def count(self) -> int:
        return self.data.index_count if self.index_buffer is not None else self.data.vertex_count


class MeshLib(ResourceLib[WGPUMesh]):
    kind = "mesh"

    def __init__(self, device: Any, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.device = device

    def _create(self, name: str, data: MeshData) -> WGPUMesh:
        ibo = None
        if data.indices is not None:
            ibo = self.device.create_buffer_with_data(
                data=np.ascontiguousarray(data.indices, dtype=np.uint32), usage=wgpu.BufferUsage.INDEX
            )
            self.stats["buffers_created"] += 1
        return WGPUMesh(name, data, ibo)

    def vertex_buffer(self, mesh: WGPUMesh, attributes: tuple[str, ...]) -> tuple[Any, Any]:
        """The interleaved buffer with exactly ``attributes`` and its layout (built once per attribute set)."""
        if attributes not in mesh.vertex_buffers:
            data, layout = mesh.data.interleaved(attributes)
            buf = self.device.create_buffer_with_data(data=data, usage=wgpu.BufferUsage.VERTEX)
            mesh.vertex_buffers[attributes] = (buf, layout)
            self.stats["buffers_created"] += 1
        return mesh.vertex_buffers[attributes]

    def _release(self, item: WGPUMesh) -> None:
        for buf, _ in item.vertex_buffers.values():
            buf.destroy()
        if item.index_buffer is not None:
            item.index_buffer.destroy()


# --- storage buffers -------------------------------------------------------------------------------
#: What a named buffer may be used for: read by materials (storage, vertex, index), written by compute
#: passes and copies, and drawn indirectly.
BUFFER_USAGE = (wgpu.BufferUsage.STORAGE | wgpu.BufferUsage.VERTEX | wgpu.BufferUsage.INDEX
                | wgpu.BufferUsage.INDIRECT | wgpu.BufferUsage.COPY_SRC | wgpu.BufferUsage.COPY_DST)


class BufferLib(ResourceLib[Any]):
    """Storage buffers by name, for materials that read them (vertex pulling) and the compute code that fills them.

    ``build(name, data)``: ``data`` is a numpy array (its bytes) or a size in bytes (zeros).
    """

    kind = "buffer"

    def __init__(self, device: Any, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.device = device

    def _create(self, name: str, data: Any) -> Any:
        content, size = buffer_bytes(name, data)
        limit = int(self.device.limits["max-storage-buffer-binding-size"])
        if size > limit:
            raise ResourceError(f"buffer '{name}'", "size",
                                f"{size} bytes is more than the device's max-storage-buffer-binding-size ({limit})")
        if content is None:
            buf = self.device.create_buffer(size=size, usage=BUFFER_USAGE, label=name)
        else:
            buf = self.device.create_buffer_with_data(data=content, usage=BUFFER_USAGE, label=name)
        self.stats["buffers_created"] += 1
        return buf

    def _release(self, item: Any) -> None:
        item.destroy()


# --- materials ------------------------------------------------------------------------------------
class WGPUMaterial(MaterialValues):
    """A material instance: uniform buffer + bind group; values change without touching any pipeline.

    The uniform struct's members are filled by name from the material's colour and params with the one layout rule
    (:mod:`gandalf_core.resources.layout`: the same bytes as OpenGL's std140 Material block); a matrix may be given
    as 9 or 16 row-major floats.
    """

    def __init__(self, name: str, data: MaterialData, shader: WGPUShader, textures: list[WGPUTexture],
                 device: Any, buffers: list[Any] | None = None) -> None:
        buffers = buffers or []
        self.name, self.data, self.shader, self.device = name, data, shader, device
        self.uniform_buffer = None
        self._struct = None
        entries = []
        texture_slots = [b for b in shader.material_bindings if b.kind == "texture"]
        if len(texture_slots) != len(textures):
            raise ResourceError(
                f"material '{name}'", "textures",
                f"{len(textures)} texture(s) given but shader '{shader.name}' ({shader.source.filename}) declares "
                f"{len(texture_slots)} in @group(1) ({', '.join(b.name for b in texture_slots) or 'none'})",
            )
        storage_slots = [b for b in shader.material_bindings if b.kind in ("storage", "read-only-storage")]
        if len(storage_slots) != len(buffers):
            raise ResourceError(
                f"material '{name}'", "buffers",
                f"{len(buffers)} buffer(s) given but shader '{shader.name}' ({shader.source.filename}) declares "
                f"{len(storage_slots)} storage buffer(s) in @group(1) "
                f"({', '.join(b.name for b in storage_slots) or 'none'})",
            )
        next_buffer = iter(buffers)
        next_texture = iter(textures)
        current: WGPUTexture | None = None
        for b in shader.material_bindings:
            if b.kind == "uniform":
                self._struct = shader.material_block
                if self._struct is None:
                    raise ResourceError(f"material '{name}'", "shader", f"shader '{shader.name}' "
                                        f"({shader.source.filename}): @group(1) uniform '{b.name}' has no struct "
                                        "type the material can fill")
                self.uniform_buffer = device.create_buffer(
                    size=max(16, self._struct.size),
                    usage=wgpu.BufferUsage.UNIFORM | wgpu.BufferUsage.COPY_DST,
                )
                entries.append({"binding": b.binding, "resource": {"buffer": self.uniform_buffer}})
            elif b.kind in ("storage", "read-only-storage"):
                entries.append({"binding": b.binding, "resource": {"buffer": next(next_buffer)}})
            elif b.kind == "texture":
                current = next(next_texture)
                entries.append({"binding": b.binding, "resource": current.view})
            elif b.kind in ("sampler", "comparison-sampler"):
                if current is None:
                    raise ShaderCompileError(
                        f"shader '{shader.name}': sampler '{b.name}' must follow the texture it samples in @group(1)"
                    )
                entries.append({"binding": b.binding, "resource": current.sampler})
        self.bind_group = (
            device.create_bind_group(layout=shader.material_layout, entries=entries)
            if shader.material_layout is not None else None
        )
        self.set_values(data.uniform_values())

    def _upload(self) -> None:
        struct = self._struct
        if struct is None:
            return
        try:
            self.block_bytes = struct.pack(block_values(struct, self.values))
        except LayoutError as exc:
            raise ResourceError(f"material '{self.name}'", "params",
                                f"shader '{self.shader.name}' ({self.shader.source.filename}): {exc}") from None
        self.device.queue.write_buffer(self.uniform_buffer, 0, self.block_bytes)


class MaterialLib(ResourceLib[WGPUMaterial]):
    kind = "material"

    def __init__(self, device: Any, shaders: ShaderLib, textures: TextureLib, stats: Counter[str],
                 buffers: BufferLib | None = None) -> None:
        super().__init__(stats)
        self.device, self.shaders, self.textures, self.buffers = device, shaders, textures, buffers

    def _create(self, name: str, data: MaterialData) -> WGPUMaterial:
        referrer = f"material '{name}'"
        data = prepare_builtin(self.shaders, name, data, "wgsl")  # gandalf.unlit, gandalf.blinn_phong
        shader = self.shaders.get(data.shader, referrer)
        textures = [self.textures.get(tex, referrer) for tex in data.textures]
        if data.buffers and self.buffers is None:
            raise ResourceError(referrer, "buffers", "this material library has no buffer library")
        buffers = [self.buffers.get(buf, referrer) for buf in data.buffers]
        slots = [(b.name, b.view_dimension == "cube") for b in shader.material_bindings if b.kind == "texture"]
        check_texture_kinds(name, shader.name, slots, [(t, self.textures.data_of(t)) for t in data.textures])
        block = shader.material_block
        fields = {f.name: f.has_default for f in block.fields} if block is not None else {}
        check_parameters(name, shader.name, shader.source.filename, data.params, fields)
        return WGPUMaterial(name, data, shader, textures, self.device, buffers)

    def _release(self, item: WGPUMaterial) -> None:
        if item.uniform_buffer is not None:
            item.uniform_buffer.destroy()

