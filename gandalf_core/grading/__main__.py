"""``python -m gandalf_core.grading tests/step01_window [--json out.json]``: grade your exercises.

A thin front end over ``pytest --student``; extra arguments go to pytest.
"""

from __future__ import annotations

import sys

import pytest


def main(argv: list[str]) -> int:
    args = ["--student", "-q", "-p", "no:cacheprovider"]
    rest = list(argv)
    if "--json" in rest:
        i = rest.index("--json")
        args += ["--grade-json", rest[i + 1]]
        del rest[i : i + 2]
    code = pytest.main(args + (rest or ["tests"]))
    # 1 = some tests failed: that's a grade, not an error of the grader.
    return 0 if code in (pytest.ExitCode.OK, pytest.ExitCode.TESTS_FAILED) else int(code)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
