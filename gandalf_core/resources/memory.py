"""Giving freed memory back to the system between large allocations.

glibc's allocator keeps memory that was freed inside its heap (it returns only what lies free at the heap's top),
and after a large block is freed it raises the size from which blocks get memory of their own (up to 32 MiB). So
decoding the 16 MiB faces of a 2048² sky one after the other keeps earlier faces' memory with the process while a
later one is decoded, and the peak grows by a face or two. :func:`give_back_freed_memory` asks glibc to return what
is free (``malloc_trim``); elsewhere (macOS, Windows, musl) it does nothing.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import functools
import sys
from collections.abc import Callable


@functools.cache
def _malloc_trim() -> Callable[[int], int] | None:
    if not sys.platform.startswith("linux"):
        return None
    try:
        trim = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6").malloc_trim
    except (OSError, AttributeError):  # not glibc
        return None
    trim.argtypes, trim.restype = [ctypes.c_size_t], ctypes.c_int
    return trim


def give_back_freed_memory() -> None:
    """Return the allocator's free memory to the system where the C library can (glibc's ``malloc_trim(0)``)."""
    trim = _malloc_trim()
    if trim is not None:
        trim(0)
