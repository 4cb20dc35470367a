"""WebGPU resource libraries: textures, shaders, meshes and materials, built once and cached by name.

As in the paper: ``renderer.textures.build('bricks', TextureData(...))``,
``renderer.shaders.build('unlit', 'unlit.wgsl')``,
``renderer.materials.build('M_Bricks', MaterialData('unlit', ['bricks']))``.

Bindings follow the engine's convention, not a reading of the shader: group 0 is the engine's (the frame uniforms,
lights, shadow map), group 1 the material's (binding 0: its Material block when the shader includes it, then a
texture and a sampler for each of the material's textures, then its storage buffers, in order). naga checks that
the shader's use fits (:mod:`.validation` reports what it finds).
"""

from __future__ import annotations

import itertools
import re
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import wgpu

from ...resources.blocks import WGSL_BINDINGS, MaterialDeclaration
from ...resources.errors import ResourceError
from ...resources.layout import BlockLayout, LayoutError
from ...resources.material_data import MaterialData
from ...resources.mesh_data import ATTRIBUTE_LOCATIONS, MeshData
from ...resources.shader_source import ShaderSource
from ...resources.texture_data import CubeTextureData, TextureData
from ..builtin_materials import prepare as prepare_builtin
from ..entry_points import wgsl_entry
from ..errors import ShaderCompileError
from ..gpu_memory import buffer_size, wgpu_texture_bytes
from ..library import ResourceLib
from ..material_block import block_values, declared_block, used_block
from ..material_checks import check_parameters
from ..material_values import MaterialValues
from ..rebuild import RebuildableShaders
from ..shader_files import load_shader
from ..storage import StorageBufferLib, StorageLayout, buffer_bytes, check_material_buffer, wgsl_storage_layouts
from ..texture_checks import check_texture_size
from .validation import compile_error, first_cause, stage_error

_ADDRESS = {"repeat": "repeat", "clamp": "clamp-to-edge"}
MATERIAL_GROUP = WGSL_BINDINGS["Material"][0]  # the one convention: resources/blocks.py


# --- textures -------------------------------------------------------------------------------------
@dataclass
class WGPUTexture:
    texture: Any
    view: Any
    sampler: Any
    cube: bool = False


class TextureLib(ResourceLib[WGPUTexture]):
    kind = "texture"

    def __init__(self, device: Any, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.device = device
        # wgpu's OpenGL backend cannot bind one layer of a six-layer texture as a 2-D texture (it takes such a
        # texture for a cube map): there, cube mips are made on the CPU as for every other texture.
        self._cube_mips_on_gpu = device.adapter.info.get("backend_type") != "OpenGL"

    def _create(self, name: str, data: TextureData | CubeTextureData) -> WGPUTexture:
        check_texture_size(name, data, int(self.device.limits["max-texture-dimension-2d"]),
                           "max-texture-dimension-2d")
        cube = isinstance(data, CubeTextureData)
        fmt = "rgba8unorm-srgb" if data.srgb else "rgba8unorm"
        # COPY_SRC: a texture viewer (the editor's frame inspector) can read any level back.
        usage = wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST | wgpu.TextureUsage.COPY_SRC
        if cube and data.levels is None and data.mipmaps and _is_power_of_two(data.size) and self._cube_mips_on_gpu:
            # A cube map's faces go up one by one from their own arrays (no stacked copy) and its mip levels are
            # made on the GPU, each the exact 2x2 box average of the level above (one bilinear tap at the texel
            # corner), in linear light for sRGB: no CPU mip chain (6 x 2048² faces: ~0.5 GB of floats).
            usage |= wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC
            texture = self.device.create_texture(size=(data.size, data.size, 6), mip_level_count=data.mip_levels,
                                                 format=fmt, usage=usage, label=name)
            def write_face(face: int, pixels: np.ndarray) -> None:
                self._write(texture, 0, face, pixels)
                # The write's staging copy goes to the GPU now, not with the six others at the next submission:
                # one face's staging held at a time (bench_skybox.py on lavapipe: 370 -> 308 MiB at the peak).
                self.device.queue.submit([])

            data.write_faces(write_face)  # one face held at a time (a sky from files is decoded face by face)
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
        return WGPUTexture(texture, view, sampler, cube)

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

    def _gpu_bytes(self, item: WGPUTexture, data: Any) -> int:
        return wgpu_texture_bytes(item.texture)

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
# Every engine vertex input a shader may read, for the pipeline that checks a module when it is built: the mesh's
# attributes at their fixed locations (attributes.py). The instance rows are no vertex input (group 0 binds them).
_ALL_INPUTS = [
    {"array_stride": 64, "step_mode": "vertex", "attributes": [
        {"format": f"float32x{n}", "offset": offset, "shader_location": ATTRIBUTE_LOCATIONS[name]}
        for name, n, offset in (("position", 3, 0), ("normal", 3, 12), ("uv", 2, 24), ("tangent", 4, 32),
                                ("color", 4, 48))]},
]


@dataclass
class WGPUShader:
    """A compiled module, the entry points it is drawn with and what its ``@group(1)`` holds."""

    name: str
    module: Any
    source: ShaderSource
    vertex_entry: str
    fragment_entry: str
    #: The layout naga derives for ``@group(1)`` from what the stages use: a material's bind group is checked
    #: against it when the material is built (the draws use the layout declared by the material, which must fit).
    material_check: Any
    #: The WGSL uniform layout of its ``@group(1) @binding(0)`` Material struct, or None.
    material_block: BlockLayout | None = None
    #: The bytes each ``@group(1)`` storage variable needs, by binding, where its type can be laid out.
    storage_layouts: dict[int, StorageLayout] = field(default_factory=dict)


class ShaderLib(RebuildableShaders, ResourceLib[WGPUShader]):
    kind = "shader"

    def __init__(self, device: Any, stats: Counter[str]) -> None:
        super().__init__(stats)
        self.device = device
        self._group_layouts: dict[tuple[str, ...], Any] = {}
        self._recipes: dict[str, tuple[tuple[Any, ...], dict[str, Any]]] = {}

    def build(self, name: str, source: str | Path | ShaderSource, *, vertex_entry: str | None = None,
              fragment_entry: str | None = None, include_dirs: Sequence[str | Path] = (),
              material: MaterialDeclaration | None = None) -> WGPUShader:
        """Compile a WGSL module (a ``.wgsl`` path or ShaderSource) and check its stages; cached by ``name``.

        ``include_dirs`` are searched for ``#include`` files after the shader's own folder. ``material`` declares
        the module's Material block (fields, or a BlockLayout; by default the colour alone), which it declares with
        ``#include "material.wgsl"``. The entry points are the module's only ``@vertex`` and ``@fragment``
        functions, or the ones named.
        """
        if name in self._items:
            return self._items[name]
        kwargs = {"vertex_entry": vertex_entry, "fragment_entry": fragment_entry, "include_dirs": include_dirs,
                  "material": material}
        shader, src = self._compile(name, source, **kwargs)
        self._items[name] = shader
        self._data[name] = src
        self._remember(name, (source,), kwargs)
        return shader

    def _compile(self, name: str, source: str | Path | ShaderSource, *, vertex_entry: str | None,
                 fragment_entry: str | None, include_dirs: Sequence[str | Path], material: MaterialDeclaration | None,
                 texts: Mapping[Path, str] | None = None) -> tuple[WGPUShader, ShaderSource]:
        """The checked module and its source (``texts``: file text to use instead of the disk's, by path)."""
        declared, generated = declared_block(name, material)
        src = load_shader(source, None, "wgsl", include_dirs, generated, texts)
        block = used_block(name, declared, [src], material is not None)
        try:
            module = self.device.create_shader_module(code=src.text, label=src.filename)
        except wgpu.GPUError as exc:
            raise ShaderCompileError(compile_error(src, str(exc))) from None
        vertex = wgsl_entry(src, "vertex", vertex_entry)
        fragment = wgsl_entry(src, "fragment", fragment_entry)
        try:  # naga checks the stages against each other and the engine's vertex inputs
            check = self.device.create_render_pipeline(
                layout="auto", vertex={"module": module, "entry_point": vertex[0], "buffers": _ALL_INPUTS},
                fragment={"module": module, "entry_point": fragment[0],
                          "targets": [{"format": "rgba8unorm-srgb", "write_mask": 0}]},
                label=f"{src.filename} check")
        except wgpu.GPUError as exc:
            raise ShaderCompileError(f"shader '{name}': {stage_error(src, str(exc), vertex, fragment)}") from None
        self.stats["shaders_created"] += 1
        shader = WGPUShader(name, module, src, vertex[0], fragment[0], check.get_bind_group_layout(MATERIAL_GROUP),
                            block, wgsl_storage_layouts(src.text, MATERIAL_GROUP))
        return shader, src

    def group_layout(self, kinds: tuple[str, ...]) -> Any:
        """The bind group layout of a material's ``@group(1)``, one per sequence of binding kinds (in binding
        order: "uniform", "texture-2d", "texture-cube", "sampler", "storage"); built once."""
        layout = self._group_layouts.get(kinds)
        if layout is None:
            visible = wgpu.ShaderStage.VERTEX | wgpu.ShaderStage.FRAGMENT
            entries = [{"binding": i, "visibility": visible, **_LAYOUT_ENTRY[kind]} for i, kind in enumerate(kinds)]
            layout = self._group_layouts[kinds] = self.device.create_bind_group_layout(entries=entries,
                                                                                       label="material group")
        return layout


_LAYOUT_ENTRY: dict[str, dict[str, Any]] = {
    "uniform": {"buffer": {"type": "uniform"}},
    "storage": {"buffer": {"type": "read-only-storage"}},
    "texture-2d": {"texture": {"sample_type": "float", "view_dimension": "2d"}},
    "texture-cube": {"texture": {"sample_type": "float", "view_dimension": "cube"}},
    "sampler": {"sampler": {"type": "filtering"}},
}


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

    def _gpu_bytes(self, item: WGPUMesh, data: MeshData) -> int:
        return buffer_size(item.index_buffer) + sum(buffer_size(b) for b, _ in item.vertex_buffers.values())

    def _release(self, item: WGPUMesh) -> None:
        for buf, _ in item.vertex_buffers.values():
            buf.destroy()
        if item.index_buffer is not None:
            item.index_buffer.destroy()


# --- storage buffers -------------------------------------------------------------------------------
#: WebGPU's usage flag for each use a named buffer may be built for (:data:`..storage.BUFFER_USES`); copies to
#: and from it are always allowed.
USAGE_FLAGS = {"storage": wgpu.BufferUsage.STORAGE, "vertex": wgpu.BufferUsage.VERTEX,
               "index": wgpu.BufferUsage.INDEX, "indirect": wgpu.BufferUsage.INDIRECT,
               "uniform": wgpu.BufferUsage.UNIFORM}


def usage_flags(uses: tuple[str, ...]) -> int:
    flags = wgpu.BufferUsage.COPY_SRC | wgpu.BufferUsage.COPY_DST
    for use in uses:
        flags |= USAGE_FLAGS[use]
    return flags


class BufferLib(StorageBufferLib, ResourceLib[Any]):
    """Storage buffers by name, for materials that read them (vertex pulling) and the compute code that fills them.

    ``build(name, data)``: ``data`` is a numpy array (its bytes) or a size in bytes (zeros); building a name again
    writes the new data into its buffer (same size) or is an error (:class:`~gandalf_core.render.storage.
    StorageBufferLib`).
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
        usage = usage_flags(self.building_uses)
        if content is None:
            buf = self.device.create_buffer(size=size, usage=usage, label=name)
        else:
            buf = self.device.create_buffer_with_data(data=content, usage=usage, label=name)
        self.stats["buffers_created"] += 1
        return buf

    def _write(self, buffer: Any, content: bytes) -> None:
        self.device.queue.write_buffer(buffer, 0, content)

    def _gpu_bytes(self, item: Any, data: Any) -> int:
        return buffer_size(item)

    def _release(self, item: Any) -> None:
        item.destroy()


# --- materials ------------------------------------------------------------------------------------
class WGPUMaterial(MaterialValues):
    """A material instance: uniform buffer + bind group; values change without touching any pipeline.

    Its ``@group(1)`` follows from its declaration: the shader's Material block at binding 0 (when a stage includes
    it), then a texture and its sampler for each of the material's textures (2-D or cube, as the texture is), then
    its storage buffers. The uniform struct's members are filled by name from the material's colour and params with
    the one layout rule (:mod:`gandalf_core.resources.layout`: the same bytes as OpenGL's std140 Material block); a
    matrix may be given as 9 or 16 row-major floats.
    """

    def __init__(self, name: str, data: MaterialData, shader: WGPUShader, textures: list[tuple[str, WGPUTexture]],
                 device: Any, group_layout: Any, buffers: list[Any] | None = None) -> None:
        self.name, self.data, self.shader, self.device = name, data, shader, device
        self.uniform_buffer = None
        self._struct = shader.material_block
        entries: list[dict[str, Any]] = []
        kinds: list[str] = []
        if self._struct is not None:
            self.uniform_buffer = device.create_buffer(size=max(16, self._struct.size),
                                                       usage=wgpu.BufferUsage.UNIFORM | wgpu.BufferUsage.COPY_DST)
            entries.append({"binding": 0, "resource": {"buffer": self.uniform_buffer}})
            kinds.append("uniform")
        for _texture, item in textures:
            entries.append({"binding": len(entries), "resource": item.view})
            entries.append({"binding": len(entries), "resource": item.sampler})
            kinds += ["texture-cube" if item.cube else "texture-2d", "sampler"]
        for buffer_name, buffer in zip(data.buffers, buffers or [], strict=False):
            check_material_buffer(name, shader.name, buffer_name, buffer.size, shader.storage_layouts.get(len(entries)))
            entries.append({"binding": len(entries), "resource": {"buffer": buffer}})
            kinds.append("storage")
        if not _fits(device, shader.material_check, entries):
            try:
                device.create_bind_group(layout=shader.material_check, entries=entries)
            except wgpu.GPUError as exc:
                raise _group_error(name, data, shader, [t for t, _ in textures], str(exc)) from None
        #: What selects the material's group layout (part of a pipeline's key).
        self.layout_key = tuple(kinds)
        self.group_layout = group_layout(self.layout_key) if entries else None
        self.bind_group = device.create_bind_group(layout=self.group_layout, entries=entries) if entries else None
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


def _fits(device: Any, layout: Any, entries: list[dict[str, Any]]) -> bool:
    """Whether ``entries`` fit the layout naga derived from the stages, which leaves out what they never use: the
    whole group, or it without up to two samplers the shader declares but never samples (texels read with
    ``textureLoad``)."""
    samplers = [e for e in entries if isinstance(e["resource"], wgpu.GPUSampler)]
    for dropped in (0, 1, 2):
        for unused in itertools.combinations(samplers, dropped):
            try:
                device.create_bind_group(layout=layout, entries=[e for e in entries if e not in unused])
                return True
            except wgpu.GPUError:
                continue
    return False


_DIMENSION = re.compile(r"binding (\d+) expects dimension = (\w+), but given a view with dimension = (\w+)")
_COUNT = re.compile(r"descriptor \((\d+)\) does not match the number of bindings defined in the bind group layout "
                    r"\((\d+)\)")


def _binding_name(text: str, binding: int) -> str | None:
    """The name of the ``@group(1) @binding(binding)`` variable in WGSL ``text`` (a slot's name), or None."""
    m = re.search(rf"@group\(1\)\s*@binding\({binding}\)\s*var(?:<[^>]*>)?\s+([A-Za-z_]\w*)", text)
    return m.group(1) if m else None


def _group_error(name: str, data: MaterialData, shader: WGPUShader, textures: list[str], message: str) -> ResourceError:
    """The material's bind group against what the shader's ``@group(1)`` uses, as an error naming the material."""
    label, where = f"material '{name}'", f"shader '{shader.name}' ({shader.source.filename})"
    first = 1 if shader.material_block is not None else 0
    if (m := _DIMENSION.search(message)) is not None:
        binding, want = int(m.group(1)), m.group(2)
        texture = textures[(binding - first) // 2] if 0 <= (binding - first) // 2 < len(textures) else "?"
        kinds = {"D2": "a 2-D texture", "Cube": "a cube map"}
        slot = _binding_name(shader.source.text, binding)
        return ResourceError(label, "textures", f"texture '{texture}' is {kinds.get(m.group(3), m.group(3))}, but "
                             f"shader '{shader.name}' samples {kinds.get(want, want)} in slot "
                             f"{f'{slot!r} ' if slot else ''}(@group(1) @binding({binding}), {shader.source.filename})")
    if (m := _COUNT.search(message)) is not None:
        what = "buffers" if data.buffers else "textures"
        return ResourceError(label, what, f"{len(textures)} texture(s) given, {len(data.buffers)} buffer(s) given: "
                             f"{m.group(1)} binding(s), but {where} reads {m.group(2)} in @group(1) (its Material "
                             "block, then a texture and a sampler per texture, then the storage buffers)")
    return ResourceError(label, "textures", f"{where}: {first_cause(message)}")


class MaterialLib(ResourceLib[WGPUMaterial]):
    kind = "material"

    def __init__(self, device: Any, shaders: ShaderLib, textures: TextureLib, stats: Counter[str],
                 buffers: BufferLib | None = None) -> None:
        super().__init__(stats)
        self.device, self.shaders, self.textures, self.buffers = device, shaders, textures, buffers
        # A shader rebuilt from new text (or released) takes the materials built with it along.
        shaders.on_forget.append(lambda shader: self.renew_where(lambda material: material.shader.name == shader))

    def _create(self, name: str, data: MaterialData) -> WGPUMaterial:
        referrer = f"material '{name}'"
        data = prepare_builtin(self.shaders, name, data, "wgsl")  # gandalf.unlit, gandalf.blinn_phong
        shader = self.shaders.get(data.shader, referrer)
        textures = [(tex, self.textures.get(tex, referrer)) for tex in data.textures]
        if data.buffers and self.buffers is None:
            raise ResourceError(referrer, "buffers", "this material library has no buffer library")
        buffers = [self.buffers.get_for(buf, "storage", referrer) for buf in data.buffers]
        block = shader.material_block
        fields = {f.name: f.has_default for f in block.fields} if block is not None else {}
        check_parameters(name, shader.name, shader.source.filename, data.params, fields)
        return WGPUMaterial(name, data, shader, textures, self.device, self.shaders.group_layout, buffers)

    def _gpu_bytes(self, item: WGPUMaterial, data: MaterialData) -> int:
        return buffer_size(item.uniform_buffer)

    def _release(self, item: WGPUMaterial) -> None:
        if item.uniform_buffer is not None:
            item.uniform_buffer.destroy()
