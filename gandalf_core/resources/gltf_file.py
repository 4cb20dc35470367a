"""A glTF file's JSON document and binary buffers (``.gltf`` or ``.glb``), its URIs read inside its folder, and the
warnings for what the engine leaves out of it: shared by the model loader (:mod:`.gltf`) and the mesh loader
(:mod:`.mesh_loader`, which reads the geometry through trimesh)."""

from __future__ import annotations

import base64
import json
import struct
import warnings
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from gandalf_core.resources.confine import inside_folder
from gandalf_core.resources.errors import MeshFileWarning, ResourceError


class GLTFWarning(MeshFileWarning):
    """Something in a glTF file that the engine leaves out (an optional extension, a primitive that is not made of
    triangles, an animation): named, never dropped silently."""


class GLTFFile:
    """The JSON document and binary buffers of one .gltf or .glb file, with error labels naming it."""

    def __init__(self, path: Path, allow_outside: bool = False) -> None:
        self.path = path
        self.allow_outside = allow_outside
        self.label = f"glTF file '{path}'"
        if path.suffix.lower() not in (".gltf", ".glb"):
            raise ResourceError(self.label, "path", f"expected a .gltf or .glb file, got {path.suffix or '(none)'!r}")
        if not path.is_file():
            raise ResourceError(self.label, "path", "file not found")
        raw = path.read_bytes()
        self.bin: bytes | None = None
        try:
            if path.suffix.lower() == ".glb":
                magic, _version, _length = struct.unpack_from("<4sII", raw, 0)
                if magic != b"glTF":
                    raise ValueError("not a GLB file (no 'glTF' magic)")
                offset, chunks = 12, []
                while offset + 8 <= len(raw):
                    size, kind = struct.unpack_from("<II", raw, offset)
                    chunks.append((kind, raw[offset + 8 : offset + 8 + size]))
                    offset += 8 + size
                self.doc = json.loads(chunks[0][1].decode("utf-8"))
                self.bin = next((data for kind, data in chunks[1:] if kind == 0x004E4942), None)
            else:
                self.doc = json.loads(raw.decode("utf-8"))
        except (ValueError, struct.error, IndexError, UnicodeDecodeError) as exc:
            raise ResourceError(self.label, "contents", f"cannot be read as glTF: {exc}") from None

    def items(self, key: str) -> list[dict[str, Any]]:
        return list(self.doc.get(key, []))

    def _uri_bytes(self, uri: str, where: str) -> bytes:
        if uri.startswith("data:"):
            try:
                return base64.b64decode(uri.split(",", 1)[1])
            except (IndexError, ValueError) as exc:
                raise ResourceError(self.label, where, f"bad data URI: {exc}") from None
        file = inside_folder(self.path, uri, self.label, where, "the URI", self.allow_outside)
        if not file.is_file():
            raise ResourceError(self.label, where, f"file not found: '{uri}' (looked for {file})")
        return file.read_bytes()

    def buffer(self, index: int, where: str) -> bytes:
        buffer = self.items("buffers")[index]
        if "uri" not in buffer:
            if self.bin is None:
                raise ResourceError(self.label, where, f"buffer {index} has no uri and the file no binary chunk")
            return self.bin
        return self._uri_bytes(buffer["uri"], where)

    def image_bytes(self, index: int, where: str) -> bytes:
        image = self.items("images")[index]
        if "uri" in image:
            return self._uri_bytes(image["uri"], where)
        view = self.items("bufferViews")[image["bufferView"]]
        data = self.buffer(view["buffer"], where)
        start = view.get("byteOffset", 0)
        return data[start : start + view["byteLength"]]


#: glTF's primitive modes; trimesh draws TRIANGLES and TRIANGLE_STRIP (as triangles), the rest are no triangles.
_MODES = {0: "POINTS", 1: "LINES", 2: "LINE_LOOP", 3: "LINE_STRIP", 4: "TRIANGLES", 5: "TRIANGLE_STRIP",
          6: "TRIANGLE_FAN"}
_DRAWN_MODES = (4, 5)
#: Top-level arrays the engine does not read, and what the model looks like without them.
_LEFT_OUT = {"animations": "the model is drawn at rest", "skins": "the skinned meshes are drawn unskinned",
             "cameras": "a scene's own camera is used"}


def warn_left_out(doc: Mapping[str, Any], label: str) -> None:
    """A :class:`GLTFWarning` for each part of the document the engine does not draw or read (materials and
    textures warn for their own extensions where they are read): a primitive that is not made of triangles,
    morph targets, animations, skins and cameras, extensions of the file, a node, a mesh or a primitive
    (``KHR_lights_punctual``'s lights, ``EXT_mesh_gpu_instancing``'s instances)."""
    def warn(where: str, what: str) -> None:
        warnings.warn(f"{label}: {where}: {what}", GLTFWarning, stacklevel=4)

    for key, without in _LEFT_OUT.items():
        if doc.get(key):
            warn(key, f"{len(doc[key])} {key[:-1]}(s) not supported: ignored ({without})")
    for extension in doc.get("extensions", {}) or {}:
        warn("extensions", f"extension {extension} is not supported: it is ignored")
    for n, node in enumerate(doc.get("nodes", []) or []):
        for extension in node.get("extensions", {}) or {}:
            warn(f"node '{node.get('name', n)}'", f"extension {extension} is not supported: it is ignored")
    for m, mesh in enumerate(doc.get("meshes", []) or []):
        name = f"mesh '{mesh.get('name', m)}'"
        for extension in mesh.get("extensions", {}) or {}:
            warn(name, f"extension {extension} is not supported: it is ignored")
        for k, primitive in enumerate(mesh.get("primitives", []) or []):
            mode = primitive.get("mode", 4)
            if mode not in _DRAWN_MODES:
                warn(f"{name} primitive {k}", f"mode {_MODES.get(mode, mode)} ({mode}) is not drawn: only TRIANGLES "
                                              "and TRIANGLE_STRIP are")
            if primitive.get("targets"):
                warn(f"{name} primitive {k}", f"{len(primitive['targets'])} morph target(s) not supported: "
                                              "ignored (the base shape is drawn)")
            for extension in primitive.get("extensions", {}) or {}:
                warn(f"{name} primitive {k}", f"extension {extension} is not supported: it is ignored")
            if "COLOR_0" in primitive.get("attributes", {}) and "material" in primitive:
                warn(f"{name} primitive {k}", "vertex colours (COLOR_0) beside a material are not read: ignored")


_COMPONENT_TYPES = {5120: "BYTE", 5121: "UNSIGNED_BYTE", 5122: "SHORT", 5123: "UNSIGNED_SHORT", 5125: "UNSIGNED_INT",
                    5126: "FLOAT"}


def refuse_misread(doc: Mapping[str, Any], label: str) -> None:
    """A :class:`ResourceError` naming the mesh, primitive, attribute and accessor for what trimesh would read into
    wrong numbers without a word: a sparse accessor (its substitutions are not applied) and texture coordinates
    stored as (normalized) integers (read as whole numbers, not 0..1)."""
    accessors = doc.get("accessors", []) or []
    for m, mesh in enumerate(doc.get("meshes", []) or []):
        for k, primitive in enumerate(mesh.get("primitives", []) or []):
            used = dict(primitive.get("attributes", {}))
            if "indices" in primitive:
                used["indices"] = primitive["indices"]
            for attribute, index in used.items():
                if not isinstance(index, int) or not 0 <= index < len(accessors):
                    continue  # the model loader names a missing accessor; trimesh fails on it
                accessor = accessors[index]
                where = f"mesh '{mesh.get('name', m)}' primitive {k} {attribute} (accessor {index})"
                if "sparse" in accessor:
                    raise ResourceError(label, where, "is a sparse accessor, which is not supported (its substituted "
                                                      "values would be left out): store the values whole")
                kind = accessor.get("componentType")
                if attribute.startswith("TEXCOORD_") and kind != 5126:
                    normalized = "normalized " if accessor.get("normalized") else ""
                    raise ResourceError(label, where, f"{normalized}{_COMPONENT_TYPES.get(kind, kind)} texture "
                                                      "coordinates are not supported (they would be read as whole "
                                                      "numbers, not 0..1): store them as FLOAT")
