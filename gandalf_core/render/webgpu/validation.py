"""wgpu's (naga's) validation messages turned into the project's errors, naming the shader file and line.

The WebGPU renderer does not read a WGSL module itself: naga compiles it, and a render pipeline checks the stages
against each other and against the vertex buffers and bind group layouts. What those checks report is mapped here:
a compile error to the file and line it came from (includes resolved), a ``@location`` no stage provides to the
entry point that reads it, a material's bind group that does not fit the shader's ``@group(1)`` to the material.
"""

from __future__ import annotations

import re

from ...resources import ATTRIBUTE_LOCATIONS, ShaderSource

_NAGA_LINE = re.compile(r"(?:wgsl|<[^>]*>|\S+\.wgsl):(\d+):(\d+)")
_MISSING_INPUT = re.compile(r"ShaderStages\((VERTEX|FRAGMENT)\).*?Location\[(\d+)\] (\w+)", re.S)
_BY_LOCATION = {loc: name for name, loc in ATTRIBUTE_LOCATIONS.items()}


def first_cause(message: str) -> str:
    """The innermost line of a wgpu error (what went wrong, without the call chain above it)."""
    lines = [ln.strip() for ln in message.splitlines() if ln.strip() and not ln.strip().startswith(("Caused", "In "))]
    return lines[-1] if lines else message.strip()


def compile_error(src: ShaderSource, message: str) -> str:
    """naga's compile error as ``file:line: error`` in the file the line came from."""
    match = _NAGA_LINE.search(message)
    if match is None:
        return f"{src.filename}: {first_cause(message)}"
    first = next((ln.strip() for ln in message.splitlines() if ln.strip().startswith("error")), None)
    if first is None:
        first = next((ln.split("error:", 1)[-1].strip() for ln in message.splitlines() if "error:" in ln),
                     first_cause(message))
    return src.format_error(int(match.group(1)), first)


def missing_input(message: str) -> tuple[str, int, str] | None:
    """(stage, location, format) when a stage reads a ``@location`` nothing before it provides, else None."""
    match = _MISSING_INPUT.search(message)
    if match is None or "not provided" not in message:
        return None
    return match.group(1).lower(), int(match.group(2)), match.group(3)


def stage_error(src: ShaderSource, message: str, vertex: tuple[str, int], fragment: tuple[str, int]) -> str:
    """A pipeline's complaint about the module's stages, at the line of the entry point it concerns."""
    missing = missing_input(message)
    if missing is None:
        return src.format_error(vertex[1], first_cause(message))
    stage, location, fmt = missing
    if stage == "fragment":
        return src.format_error(fragment[1], f"fragment entry point '{fragment[0]}' reads @location({location}) "
                                f"({fmt}), which vertex entry point '{vertex[0]}' never returns (not at that "
                                "location, or with fewer components or another type)")
    return src.format_error(vertex[1], f"vertex entry point '{vertex[0]}' reads @location({location}) ({fmt}), "
                            f"which is no engine attribute (mesh: {ATTRIBUTE_LOCATIONS}; the instance rows are no "
                            "attributes: take an `inst: Instance` parameter and call instance_model(inst))")


def attribute_of(location: int) -> str | None:
    """The mesh attribute at ``location``, or None."""
    return _BY_LOCATION.get(location)
