"""A check the techniques share for their materials' and components' numeric parameters.

The error is a :class:`~gandalf_core.resources.ResourceError` that names the material (or component) and the
parameter, and states the rule the value broke.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from gandalf_core.resources import ResourceError


def checked_number(label: str, key: str, value: Any, rule: str, ok: Callable[[float], bool],
                   expected: str = "a number") -> float:
    """``value`` as a finite float for which ``ok`` holds, or a ResourceError naming ``label``'s ``key``.

    ``rule`` says in words what ``ok`` checks (e.g. ``">= 0"``); ``expected`` says what was expected when the value is
    not a number at all.
    """
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ResourceError(label, key, f"expected {expected}, got {value!r}") from None
    if not (math.isfinite(number) and ok(number)):
        raise ResourceError(label, key, f"must be finite and {rule}, got {value!r}")
    return number
