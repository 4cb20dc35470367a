"""A material's parameters against its shader, checked when the material is built, the same way in both APIs.

Nothing is matched silently by name: a parameter the shader does not declare (a typo, or a GLSL name given with
its ``u_`` prefix) and a shader value the material never sets (it would read 0) are errors that name the
material, the shader file and the field, with the names that were meant when they are close.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

from ..resources import ResourceError


def check_parameters(material: str, shader: str, source: str, params: Iterable[str], fields: dict[str, bool],
                     prefix: str = "", legacy_prefix: str = "") -> None:
    """``params``: the material's parameter names (its colour is always given, and a shader need not read it);
    ``fields``: the shader's value names (without ``prefix``) -> whether the shader states a default for it (then
    the material may leave it out). A parameter given with ``prefix`` or ``legacy_prefix`` (GLSL's old ``u_``) in
    front of a field's name gets an error saying to leave the prefix out."""
    params = list(params)
    given = [*params, "color"]
    label = f"material '{material}'"
    for key in params:
        if key in fields:
            continue
        if legacy_prefix and key.startswith(legacy_prefix) and key[len(legacy_prefix):] in fields:
            raise ResourceError(label, f"params['{key}']", f"give it without the '{legacy_prefix}' prefix: "
                                f"'{key[len(legacy_prefix):]}' (the field of shader '{shader}''s Material block)")
        if prefix and key.startswith(prefix) and key[len(prefix):] in fields:
            raise ResourceError(label, f"params['{key}']", f"give it without the '{prefix}' prefix: "
                                f"'{key[len(prefix):]}' (the shader's {prefix}{key[len(prefix):]})")
        close = difflib.get_close_matches(key, list(fields), n=3, cutoff=0.6)
        hint = f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""
        raise ResourceError(label, f"params['{key}']",
                            f"shader '{shader}' ({source}) has no value '{prefix}{key}' "
                            f"(it has: {', '.join(sorted(fields)) or 'none'}){hint}")
    missing = [name for name, has_default in fields.items() if name not in given and not has_default]
    if missing:
        raise ResourceError(label, "params", f"shader '{shader}' ({source}) reads "
                            f"{', '.join(repr(prefix + m) for m in sorted(missing))}, which the material never "
                            "sets (it would read 0): give a value in params (or the colour), or a default in "
                            "the shader")
