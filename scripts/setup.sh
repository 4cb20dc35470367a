#!/usr/bin/env bash
# Set up everything gandalf needs on a fresh Debian/Ubuntu machine, idempotently:
#   system packages (software OpenGL/EGL + Vulkan for headless rendering, Xvfb for windows) when root,
#   a virtual environment in .venv, and the project with its development extras.
set -euo pipefail
cd "$(dirname "$0")/.."

# --8<-- [start:packages]
APT_PACKAGES=(libegl1 libegl-mesa0 libgl1 libgl1-mesa-dri mesa-vulkan-drivers libvulkan1 xvfb xauth x11-utils chromium)
# --8<-- [end:packages]
if command -v dpkg-query >/dev/null 2>&1; then
    missing=()
    for pkg in "${APT_PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
    done
    if [ ${#missing[@]} -gt 0 ]; then
        if [ "$(id -u)" = 0 ]; then
            echo "setup: installing ${missing[*]} (Debian packages; waits up to 5 minutes for another apt to finish)"
            export DEBIAN_FRONTEND=noninteractive
            apt-get -o DPkg::Lock::Timeout=300 update -qq
            apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
        else
            echo "setup: please install: sudo apt-get install ${missing[*]}" >&2
        fi
    fi
fi

PYTHON=${PYTHON:-python3}
if [ ! -x .venv/bin/python ]; then
    echo "setup: creating the virtual environment .venv"
    "$PYTHON" -m venv .venv
fi
stamp=.venv/.gandalf-installed
# The dev extra includes the grader's pytest-xdist and pytest-timeout; an older venv without them is refreshed.
if [ ! -f "$stamp" ] || [ pyproject.toml -nt "$stamp" ] \
    || ! .venv/bin/python -c "import xdist, pytest_timeout" >/dev/null 2>&1; then
    echo "setup: installing the course and its tools into .venv (about a minute on a fresh machine)"
    .venv/bin/python -m pip install -q --upgrade pip
    # setuptools warns at length that an editable install's folders take precedence: that is what the course wants.
    PYTHONWARNINGS=ignore .venv/bin/python -m pip install -q -e ".[dev]"
    touch "$stamp"
    echo "setup: done"
fi
