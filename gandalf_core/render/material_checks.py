"""A material's parameters against its shader, checked when the material is built, the same way in both APIs.

Nothing is matched silently by name: a parameter the shader does not declare (a typo, or a GLSL name given with
its ``u_`` prefix) and a shader value the material never sets (it would read 0) are errors that name the
material, the shader file and the field, with the names that were meant when they are close.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

from ..resources import ResourceError


def check_parameters(material: str, shader: str, source: str, params: Iterable[str], fields: dict[str, bool]) -> None:
    """``params``: the material's parameter names (its colour is always given, and a shader need not read it);
    ``fields``: the fields of the shader's Material block -> whether the shader states a default for it (then the
    material may leave it out). A parameter given with GLSL's old ``u_`` prefix in front of a field's name gets an
    error saying to leave the prefix out, in both APIs."""
    params = list(params)
    given = [*params, "color"]
    label = f"material '{material}'"
    for key in params:
        if key in fields:
            continue
        if key.startswith("u_") and key[2:] in fields:
            raise ResourceError(label, f"params['{key}']", f"give it without the 'u_' prefix: "
                                f"'{key[2:]}' (the field of shader '{shader}''s Material block)")
        close = difflib.get_close_matches(key, list(fields), n=3, cutoff=0.6)
        hint = f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""
        raise ResourceError(label, f"params['{key}']",
                            f"shader '{shader}' ({source}) has no value '{key}' "
                            f"(it has: {', '.join(sorted(fields)) or 'none'}){hint}")
    missing = [name for name, has_default in fields.items() if name not in given and not has_default]
    if missing:
        raise ResourceError(label, "params", f"shader '{shader}' ({source}) reads "
                            f"{', '.join(repr(m) for m in sorted(missing))}, which the material never "
                            "sets (it would read 0): give a value in params (or the colour), or a default in "
                            "the shader")
