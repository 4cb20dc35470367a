"""``python -m gandalf_core.grading [TESTS ...] [--json FILE]``: grade your exercises.

A thin front end over ``pytest --student`` that prints one line per failed test and the score table
(``pytest --student`` itself shows full tracebacks). Other arguments go to pytest.
"""

from __future__ import annotations

import argparse
import sys

import pytest


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="python -m gandalf_core.grading", description=__doc__.splitlines()[0])
    parser.add_argument("tests", nargs="*", default=["tests"], help="test folders or files (default: tests)")
    parser.add_argument("--json", metavar="FILE", help="also write the score as JSON to FILE")
    args, extra = parser.parse_known_args(argv)
    options = ["--student", "-q", "-p", "no:cacheprovider", "--tb=line", "-rN"]
    if args.json:
        options += ["--grade-json", args.json]
    code = pytest.main(options + extra + args.tests)
    # 1 = some tests failed: that's a grade, not an error of the grader.
    return 0 if code in (pytest.ExitCode.OK, pytest.ExitCode.TESTS_FAILED) else int(code)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
