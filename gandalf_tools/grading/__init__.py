"""The autograder: a pytest plugin (``plugin``) and the ``python -m gandalf_tools.grading`` front end.

Also the options every grading process shares (the front end, the batch grader, the mutation check): what
makes a grading process start fast without changing what it checks.
"""

from __future__ import annotations

import os
import sys
import tempfile

# Hypothesis's pytest plugin imports hypothesis itself (about 1.2 s per process, paid again by each xdist worker);
# no graded test uses it (``@given`` works without the plugin anyway).
SPEED_OPTIONS = ("-p", "no:hypothesispytest")

PYCACHE_ENV = "GANDALF_PYCACHE"


def pycache_dir() -> str | None:
    """Where grading processes keep compiled bytecode: ``$GANDALF_PYCACHE`` ("off": nowhere), else
    ``$PYTHONPYCACHEPREFIX``, else a folder in the system's temporary folder."""
    value = os.environ.get(PYCACHE_ENV, "").strip()
    if value.lower() in ("off", "0", "no", "none"):
        return None
    return value or os.environ.get("PYTHONPYCACHEPREFIX") or os.path.join(
        tempfile.gettempdir(), f"gandalf-pycache-{os.getuid() if hasattr(os, 'getuid') else 'user'}"
    )


def bytecode_cache_env(env: dict[str, str]) -> dict[str, str]:
    """``env`` for a grading process that caches bytecode OUTSIDE the checkout and the submissions.

    With ``PYTHONDONTWRITEBYTECODE`` (set on shared machines to keep folders clean) every grading process
    compiled, and pytest assertion-rewrote, every module and test file again (about 1.5 s per process). A
    ``PYTHONPYCACHEPREFIX`` keeps folders just as clean (nothing is written next to a source, a student's
    included) and lets the next process, the next student, reuse the bytecode of the course's own files.
    """
    folder = pycache_dir()
    env = dict(env)
    if folder is None:
        env["PYTHONDONTWRITEBYTECODE"] = "1"
        return env
    env["PYTHONPYCACHEPREFIX"] = folder
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def use_bytecode_cache() -> None:
    """:func:`bytecode_cache_env` for this process (and the processes it starts, such as xdist's workers)."""
    folder = pycache_dir()
    if folder is None:
        return
    os.environ.update(bytecode_cache_env(dict(os.environ)))
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
    sys.pycache_prefix = folder
    sys.dont_write_bytecode = False
