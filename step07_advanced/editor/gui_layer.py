"""What both GUI backends share for the cached GUI layer.

The GUI is drawn into a transparent *layer* texture only on frames that run the panels, exactly as ImGui means it
(its sRGB bytes blended as bytes, premultiplied). Every frame then draws that layer over the finished frame, last
in the frame's own drawing (no pass or copy of its own), as two triangles per window rectangle: the layer's colour
is decoded to linear light and blended "over" the frame by the blending unit (``one, one-minus-src-alpha``), and
the sRGB target encodes the result. Where the GUI is opaque (the windows: their background is made opaque, see
:func:`step07_advanced.editor.editor.editor_style`) this gives exactly the GUI's bytes; only its anti-aliased rims
are mixed with the scene in linear light instead of ImGui's byte space (both backends alike).

A texture a panel shows live (the viewport's) would be frozen in the layer, so the layer gets a transparent hole
where it is drawn and the image itself is drawn into the frame every frame, before the layer: what the GUI draws
over it (the gizmo) stays on top.
"""

from __future__ import annotations

import ctypes
from typing import Any

import numpy as np
from imgui_bundle import imgui

_INDEX = np.uint32 if imgui.INDEX_SIZE == 4 else np.uint16


def gui_rects(draw_data: Any, width: int, height: int) -> list[tuple[int, int, int, int]]:
    """(x, y, w, h) pixel rectangles that hold the GUI: per draw list (a window), the box around its vertices,
    inside its commands' clip rectangles. Boxes inside another box are left out (drawn once)."""
    lists = [commands for commands in draw_data.cmd_lists if commands.vtx_buffer.size() > 0]
    if not lists:
        return []
    counts = [commands.vtx_buffer.size() for commands in lists]
    raw = b"".join(ctypes.string_at(commands.vtx_buffer.data_address(), count * imgui.VERTEX_SIZE)
                   for commands, count in zip(lists, counts))
    xy = np.frombuffer(raw, dtype=np.float32).reshape(-1, imgui.VERTEX_SIZE // 4)[:, :2]
    starts = np.cumsum([0, *counts[:-1]])
    lo, hi = np.minimum.reduceat(xy, starts, axis=0), np.maximum.reduceat(xy, starts, axis=0)  # per list, at once
    boxes: list[tuple[int, int, int, int]] = []
    for commands, (vx0, vy0), (vx1, vy1) in zip(lists, lo.tolist(), hi.tolist()):
        clips = [tuple(command.clip_rect) for command in commands.cmd_buffer]
        if not clips:
            continue
        x0, y0 = max(min(c[0] for c in clips), vx0), max(min(c[1] for c in clips), vy0)
        x1, y1 = min(max(c[2] for c in clips), vx1), min(max(c[3] for c in clips), vy1)
        ix0, iy0 = max(int(x0), 0), max(int(y0), 0)
        ix1, iy1 = min(int(x1 + 0.999) + 1, width), min(int(y1 + 0.999) + 1, height)  # + 1: anti-aliased edges
        if ix1 > ix0 and iy1 > iy0:
            boxes.append((ix0, iy0, ix1, iy1))
    return [(x0, y0, x1 - x0, y1 - y0) for x0, y0, x1, y1 in merge_boxes(boxes)]


def _area(b: tuple[int, int, int, int]) -> int:
    return (b[2] - b[0]) * (b[3] - b[1])


def merge_boxes(boxes: list[tuple[int, int, int, int]], slack: float = 0.05) -> list[tuple[int, int, int, int]]:
    """Fewer boxes covering the same pixels: two boxes become their union when that adds at most ``slack`` of it
    (panels side by side, a box inside another). Each box left is two more triangles per frame; boxes that still
    overlap composite their common pixels twice (the same bytes where the GUI is opaque)."""
    boxes = list(dict.fromkeys(boxes))
    merged = True
    while merged and len(boxes) > 1:
        merged = False
        for i in range(len(boxes)):
            for j in range(i + 1, len(boxes)):
                a, b = boxes[i], boxes[j]
                union = (min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3]))
                if _area(union) <= (_area(a) + _area(b)) + slack * _area(union):
                    boxes[i] = union
                    del boxes[j]
                    merged = True
                    break
            if merged:
                break
    return boxes


def rect_vertices(rects: list[tuple[int, int, int, int]], width: int, height: int) -> bytes:
    """The pixel rectangles ``rects`` (x, y, w, h; origin top-left) as two triangles each, in clip space
    (float32 x, y): the composite draws them in one call, with no scissor per rectangle. Their edges fall on
    pixel edges, so exactly the rectangles' pixels are drawn."""
    quads = np.empty((len(rects), 6, 2), dtype=np.float32)
    for i, (x, y, w, h) in enumerate(rects):
        x0, x1 = 2.0 * x / width - 1.0, 2.0 * (x + w) / width - 1.0
        y0, y1 = 1.0 - 2.0 * y / height, 1.0 - 2.0 * (y + h) / height  # clip space: y up
        quads[i] = ((x0, y0), (x1, y0), (x0, y1), (x0, y1), (x1, y0), (x1, y1))
    return quads.tobytes()


def clip_box(command: Any, width: int, height: int) -> tuple[int, int, int, int] | None:
    """The command's clip rectangle in whole pixels (x0, y0, x1, y1) inside the frame, or None when empty."""
    x0, y0, x1, y1 = command.clip_rect
    x0, y0 = max(int(x0), 0), max(int(y0), 0)
    x1, y1 = min(int(x1), width), min(int(y1), height)
    return (x0, y0, x1, y1) if x1 > x0 and y1 > y0 else None


def merged_draw_lists(draw_data: Any) -> tuple[bytes, np.ndarray, list[int]]:
    """Every draw list's vertices in one buffer and its indices in one uint32 array, rebased onto it (a command's
    ``vtx_offset`` folded in), and where each list's indices start: one upload per GUI frame instead of one per
    window (writing a buffer the GPU may still be reading can make the driver wait)."""
    vertices: list[bytes] = []
    indices: list[np.ndarray] = []
    starts: list[int] = []
    base = first = 0
    for commands in draw_data.cmd_lists:
        count, index_count = commands.vtx_buffer.size(), commands.idx_buffer.size()
        vertices.append(ctypes.string_at(commands.vtx_buffer.data_address(), count * imgui.VERTEX_SIZE))
        raw = ctypes.string_at(commands.idx_buffer.data_address(), index_count * imgui.INDEX_SIZE)
        rebased = np.frombuffer(raw, dtype=_INDEX).astype(np.uint32) + np.uint32(base)
        for command in commands.cmd_buffer:
            if command.vtx_offset:
                rebased[command.idx_offset:command.idx_offset + command.elem_count] += np.uint32(command.vtx_offset)
        indices.append(rebased)
        starts.append(first)
        base += count
        first += index_count
    merged = np.concatenate(indices) if indices else np.zeros(0, dtype=np.uint32)
    return b"".join(vertices), merged, starts


def command_vertices(commands: Any, command: Any) -> bytes:
    """The vertices of one draw command as a plain triangle list (ImGui's vertex layout), for drawing it again."""
    indices = np.frombuffer(ctypes.string_at(commands.idx_buffer.data_address() + command.idx_offset * imgui.INDEX_SIZE,
                                             command.elem_count * imgui.INDEX_SIZE), dtype=_INDEX)
    vertices = np.frombuffer(ctypes.string_at(commands.vtx_buffer.data_address(),
                                              commands.vtx_buffer.size() * imgui.VERTEX_SIZE), dtype=np.uint8)
    rows = vertices.reshape(-1, imgui.VERTEX_SIZE)
    return rows[indices.astype(np.int64) + command.vtx_offset].tobytes()
