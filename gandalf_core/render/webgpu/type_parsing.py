"""wgpu-py's C types parsed in about a millisecond each instead of fifteen.

wgpu-py makes every struct it hands to wgpu-native with cffi (``ffi.new("WGPUTextureDescriptor *")``). cffi parses
each type string once per process with pycparser, and before each parse it declares, as C source, every typedef
that the FFI knows: wgpu-native's 432, for a one-line type. That is ~15 ms a type, and a renderer meets ~55 types
before its first frame: ~0.8 s of every process that draws with WebGPU (the grader starts one for each student and
step; the tests start hundreds).

A typedef changes a parse only where its name occurs in the parsed text (it tells pycparser that the name is a
type), so :func:`parse_only_mentioned_typedefs` has cffi declare just those. The types cffi builds are the same
(``tests/core/test_webgpu_type_parsing.py`` compares every struct type wgpu-native declares). Where cffi's parser
is not as expected, nothing is changed: this only makes start-up faster.
"""

from __future__ import annotations

import re
from typing import Any

_IDENTIFIER = re.compile(r"[A-Za-z_]\w*")
_TYPEDEF = "typedef "


def _declaring_only_mentioned(parse: Any) -> Any:
    """Wrap cffi's ``Parser._parse`` so that it sees only the typedefs that the parsed text names."""

    def _parse(self: Any, csource: str) -> Any:
        mentioned = set(_IDENTIFIER.findall(csource))
        everything = self._declarations
        self._declarations = {name: value for name, value in everything.items()
                              if not name.startswith(_TYPEDEF) or name[len(_TYPEDEF):] in mentioned}
        try:
            return parse(self, csource)
        finally:
            self._declarations = everything

    return _parse


def parse_only_mentioned_typedefs(ffi: Any = None) -> bool:
    """Make ``ffi`` (default: wgpu-native's) parse new type strings with only the typedefs they name; True when done
    (now or before). cffi calls the parser under the FFI's own lock, so the swap is never seen half done."""
    if ffi is None:
        from wgpu.backends.wgpu_native._ffi import ffi
    parser = getattr(ffi, "_parser", None)
    parse = getattr(type(parser), "_parse", None)
    if parse is None or not isinstance(getattr(parser, "_declarations", None), dict):
        return False
    if "_parse" not in vars(parser):
        parser._parse = _declaring_only_mentioned(parse).__get__(parser)
    return True
