#!/usr/bin/env bash
# gandalf's two entry points; each sets everything up first (scripts/setup.sh).
#   ./run.sh tour [--out DIR]   the course tour: windows with a display, PNGs in DIR (default out/) without
#   ./run.sh test [PYTEST ARGS] the whole test suite (window tests run under Xvfb when it is installed)
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
# A machine that sets PYTHONDONTWRITEBYTECODE (to keep folders clean) made every process compile the course's modules,
# and pytest rewrite every test file, again: 6 s of each test worker's start, ~1 s of every tour or grading process.
# Their bytecode goes to the grader's cache folder outside the checkout instead (gandalf_tools.grading.pycache_dir;
# GANDALF_PYCACHE=off turns this off).
if [ -n "${PYTHONDONTWRITEBYTECODE:-}" ] && [ -z "${PYTHONPYCACHEPREFIX:-}" ]; then
    cache=$(.venv/bin/python -c 'from gandalf_tools.grading import pycache_dir; print(pycache_dir() or "")')
    if [ -n "$cache" ]; then
        export PYTHONPYCACHEPREFIX="$cache"
        unset PYTHONDONTWRITEBYTECODE
    fi
fi
chmod 700 "$XDG_RUNTIME_DIR"
cmd=${1:-tour}
shift || true
case "$cmd" in
    tour)
        exec .venv/bin/python -m gandalf_tools.tour "$@"
        ;;
    test)
        # One pytest worker per core (pytest-xdist; the window tests take turns on the display through a lock, see
        # tests/conftest.py). Each worker starts with a contiguous half of the suite and takes tests from the other's
        # queue when its own runs out (--dist worksteal): the default dealing left one worker alone for the last
        # ~2 minutes. `./run.sh test -n 0 ...` runs in one process.
        parallel=(-n auto --dist worksteal)
        # One BLAS thread per process: numpy's OpenBLAS otherwise starts a thread per core in every process, and
        # with a worker per core they only take turns with the other worker (the suite ran ~10 % longer).
        export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
        if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null 2>&1; then
            exec xvfb-run -a -s "-screen 0 1280x720x24" .venv/bin/python -m pytest "${parallel[@]}" "$@"
        fi
        exec .venv/bin/python -m pytest "${parallel[@]}" "$@"
        ;;
    *)
        echo "usage: ./run.sh tour [--out DIR] | ./run.sh test [pytest args]" >&2
        exit 2
        ;;
esac
