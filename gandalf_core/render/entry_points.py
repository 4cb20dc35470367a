"""The entry points a shader declares, and the check that no stage is empty or cut short, for both APIs.

A driver may accept an empty stage (NVIDIA's GL compiler links an empty fragment shader; naga accepts an empty WGSL
module), so before any source reaches a compiler each GLSL stage must declare ``void main(`` and a WGSL module the
entry points it is used with: ``@vertex fn NAME`` / ``@fragment fn NAME`` (the one of its kind, or the name the
caller gives). Found by their declaration line, so an error names the file and line.
"""

from __future__ import annotations

import re

from ..resources.shader_source import ShaderSource
from .errors import ShaderCompileError

_WGSL_ENTRY = re.compile(r"@(vertex|fragment|compute)\s+fn\s+(\w+)")
_GLSL_MAIN = re.compile(r"\bvoid\s+main\s*\(")


def _code(src: ShaderSource) -> str:
    """The expanded text without ``//`` comments (lines kept, so positions still give line numbers)."""
    return "\n".join(line.split("//", 1)[0] for line in src.text.splitlines())


def check_glsl_main(src: ShaderSource) -> None:
    """Raise when a GLSL stage (after includes) declares no ``void main(``: an empty or truncated file."""
    if _GLSL_MAIN.search(_code(src)) is None:
        raise ShaderCompileError(src.format_error(
            len(src.line_map) or 1,
            f"the {src.stage} stage declares no 'void main()': the file is empty or cut short"))


def wgsl_entry(src: ShaderSource, stage: str, wanted: str | None) -> tuple[str, int]:
    """The ``@stage`` entry point to use and its line: ``wanted``, else the module's only one of that stage."""
    code = _code(src)
    found = [(m.group(2), code.count("\n", 0, m.start(2)) + 1) for m in _WGSL_ENTRY.finditer(code)
             if m.group(1) == stage]
    names = [name for name, _ in found]
    if wanted is not None:
        if wanted not in names:
            raise ShaderCompileError(f"{src.filename}: no @{stage} entry point named '{wanted}' (have: {names})")
        return wanted, dict(found)[wanted]
    if len(found) != 1:
        raise ShaderCompileError(
            f"{src.filename}: expected exactly one @{stage} entry point, found {len(found)} ({names}); name one"
        )
    return found[0]
