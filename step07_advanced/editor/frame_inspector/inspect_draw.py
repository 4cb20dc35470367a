"""What a captured draw records, per API: pipeline state, uniform blocks decoded by field name, textures, buffers.

Called by :class:`~.capture.FrameRecorder` only while a frame is captured. OpenGL's state is read
back from the context (``glGet``) at the moment of the draw, so a state the renderer did not mean to leave shows as
it was; WebGPU's pipelines cannot be read back, so their state is the one each was created with (the renderer keeps
the descriptors' primitive, depth-stencil and target parts by pipeline).
"""

from __future__ import annotations

import ctypes
from typing import Any

from gandalf_core.render.frame import INSTANCE_STRIDE, SHADOW_MAP_SIZE
from gandalf_core.resources.blocks import BLOCK_BINDINGS, WGSL_BINDINGS

from .frame_records import DrawRecord

_GL_ENUMS = {
    0x0200: "GL_NEVER", 0x0201: "GL_LESS", 0x0202: "GL_EQUAL", 0x0203: "GL_LEQUAL", 0x0204: "GL_GREATER",
    0x0205: "GL_NOTEQUAL", 0x0206: "GL_GEQUAL", 0x0207: "GL_ALWAYS", 0x0404: "GL_FRONT", 0x0405: "GL_BACK",
    0x0408: "GL_FRONT_AND_BACK", 0x0900: "GL_CW", 0x0901: "GL_CCW", 0: "GL_ZERO", 1: "GL_ONE",
    0x0302: "GL_SRC_ALPHA", 0x0303: "GL_ONE_MINUS_SRC_ALPHA",
}
_GL_STATE = {"depth_test": 0x0B71, "depth_write": 0x0B72, "depth_func": 0x0B74, "cull": 0x0B44,
             "cull_face": 0x0B45, "front_face": 0x0B46, "blend": 0x0BE2, "blend_src": 0x80C9, "blend_dst": 0x80C8,
             "blend_src_alpha": 0x80CB, "blend_dst_alpha": 0x80CA}


def _gl_state() -> dict[str, Any]:
    """The current GL context's depth, cull and blend state, named."""
    from gandalf_core.render.opengl.raw_gl import gl_function

    get = gl_function("glGetIntegerv", (ctypes.c_uint, ctypes.POINTER(ctypes.c_int)))
    raw = {}
    value = ctypes.c_int()
    for key, enum in _GL_STATE.items():
        get(enum, ctypes.byref(value))
        raw[key] = value.value
    name = lambda v: _GL_ENUMS.get(v, hex(v))  # noqa: E731
    state: dict[str, Any] = {
        "depth_test": bool(raw["depth_test"]),
        "depth_compare": name(raw["depth_func"]) if raw["depth_test"] else "off (GL_DEPTH_TEST disabled)",
        "depth_write": bool(raw["depth_write"]),
        "cull": name(raw["cull_face"]) if raw["cull"] else "none",
        "front_face": name(raw["front_face"]),
        "blend": (f"{name(raw['blend_src'])}, {name(raw['blend_dst'])} / alpha {name(raw['blend_src_alpha'])}, "
                  f"{name(raw['blend_dst_alpha'])}") if raw["blend"] else "off",
    }
    return state


def _wgpu_state(renderer: Any, pipeline: Any) -> dict[str, Any]:
    """The state ``pipeline`` was created with (the renderer keeps it: a GPU pipeline cannot be read back)."""
    created = renderer.pipeline_states.get(id(pipeline)) if pipeline is not None else None
    if created is None:
        return {"pipeline": "not recorded"}
    primitive, depth, targets = created["primitive"], created["depth_stencil"], created["targets"]
    blend = targets[0].get("blend") if targets else None
    return {
        "depth_compare": depth["depth_compare"], "depth_write": bool(depth["depth_write_enabled"]),
        "cull": primitive.get("cull_mode", "none"), "front_face": primitive.get("front_face", "ccw"),
        "blend": ("none (depth only)" if not targets else "none" if blend is None else
                  f"{blend['color']['src_factor']}, {blend['color']['dst_factor']} / alpha "
                  f"{blend['alpha']['src_factor']}, {blend['alpha']['dst_factor']}"),
        "topology": primitive["topology"],
    }


def _texture_info(renderer: Any, slot: str, name: str) -> dict[str, Any]:
    data = renderer.textures.data_of(name) if name in renderer.textures else None
    info: dict[str, Any] = {"slot": slot, "name": name}
    if data is not None:
        cube = hasattr(data, "size") and not hasattr(data, "width")
        info.update(kind="cube" if cube else "2d",
                    size=(data.size, data.size) if cube else (data.width, data.height),
                    levels=data.mip_levels, srgb=getattr(data, "srgb", None))
    return info


def _shader_files(renderer: Any, shader: Any) -> list[str]:
    source = shader.source
    if renderer.backend == "opengl":
        return [f.strip() for f in str(source).split(",") if f.strip()]
    files = [source.filename] + [f for f in getattr(source, "files", ()) if f != source.filename]
    return list(dict.fromkeys(files))


def describe_draw(renderer: Any, index: int, pass_name: str, shader: Any, batch: Any, material: Any, mesh: Any,
                  reverse_z: bool, engine_blocks: dict[str, dict[str, Any]], sky: str | None = None,
                  pipeline: Any = None) -> DrawRecord:
    """The record of one draw (see :class:`~.capture.DrawRecord`)."""
    gl = renderer.backend == "opengl"
    shadow = pass_name == "shadow"
    data = material.data if material is not None else None
    # --- pipeline state ---
    state = _gl_state() if gl else _wgpu_state(renderer, pipeline)
    patch = getattr(shader, "patch_vertices", None) if gl else None
    indirect = mesh is not None and mesh.data.indirect is not None
    if gl:
        state["topology"] = "patches" if patch else "triangles"
    if indirect and "topology" in state:
        state["topology"] += " (indirect)"
    state["patch_size"] = patch if patch else (mesh.data.patch_size if mesh is not None else None)
    # --- uniform blocks ---
    blocks = dict(engine_blocks) if not shadow else {"Frame": engine_blocks.get("Frame"),
                                                     "Lights": engine_blocks.get("Lights")}
    block = getattr(shader, "material_block", None) if not shadow else None
    if block is not None and material is not None:
        if gl:
            written = material.block_buffer.read() if material.block_buffer is not None else b""
            binding = f"binding {BLOCK_BINDINGS['Material']}"
        else:
            written = getattr(material, "block_bytes", b"")
            binding = "@group({}) @binding({})".format(*WGSL_BINDINGS["Material"])
        if written:
            blocks["Material"] = {"binding": binding, "values": block.unpack(written)}
    # --- textures and buffers ---
    textures: list[dict[str, Any]] = []
    buffers: list[dict[str, Any]] = []
    if material is not None and not shadow:
        slots = shader.samplers if gl else [f"@binding({2 * i + 1})" for i in range(len(data.textures))]
        textures = [_texture_info(renderer, slot, name) for slot, name in zip(slots, data.textures)]
        for i, name in enumerate(data.buffers):
            size = renderer.buffers.get(name).size if name in renderer.buffers else None
            buffers.append({"slot": f"storage {i}", "name": name, "bytes": size})
    elif sky is not None:
        textures = [_texture_info(renderer, "sky cube", sky)]
    samples_shadow = ("u_shadow_map" in shader.uniforms) if gl else ("shadow_map" in shader.source.text)
    if samples_shadow and not shadow and engine_blocks.get("Lights", {}).get("values", {}).get("shadow", [0])[0]:
        textures.append({"slot": "shadow map", "name": "shadow map", "kind": "depth",
                         "size": (SHADOW_MAP_SIZE, SHADOW_MAP_SIZE), "levels": 1})
    layout: list[str] = []
    if mesh is not None:
        built = list(mesh.vertex_buffers)
        if built:
            if gl:
                _data, vlayout = mesh.data.interleaved(built[-1])
            else:
                vlayout = mesh.vertex_buffers[built[-1]][1]
            fmt = (lambda a: a.gl_format) if gl else (lambda a: a.wgpu_format)
            layout = [f"{a.name}: {fmt(a)} @{a.offset_bytes} (location {a.location})" for a in vlayout.attributes]
            buffers.append({"slot": "vertex", "name": f"{mesh.name} vertices", "bytes":
                            vlayout.stride * mesh.data.vertex_count, "stride": vlayout.stride})
        if mesh.index_buffer is not None:
            buffers.append({"slot": "index", "name": f"{mesh.name} indices", "bytes": 4 * mesh.data.index_count})
    if batch is not None:
        buffers.append({"slot": "instances", "name": "instance rows", "offset": batch.first_instance * INSTANCE_STRIDE,
                        "bytes": batch.count * INSTANCE_STRIDE, "stride": INSTANCE_STRIDE})
    return DrawRecord(
        index=index, pass_name=pass_name,
        mesh=mesh.name if mesh is not None else None,
        material=material.name if material is not None else None,
        shader=shader.name, shader_files=_shader_files(renderer, shader),
        instances=batch.count if batch is not None else 1,
        first_instance=batch.first_instance if batch is not None else 0,
        rows=batch.rows.tolist() if batch is not None else [],
        vertex_count=mesh.data.vertex_count if mesh is not None else 3,
        index_count=mesh.data.index_count if mesh is not None and mesh.index_buffer is not None else 0,
        layout=layout, state=state, blocks={k: v for k, v in blocks.items() if v is not None},
        textures=textures, buffers=buffers, mirrored=bool(batch is not None and batch.mirrored), sky=sky,
    )
