"""``import gandalf_core`` stays light: no GPU, USD, ImGui, mesh, window or image library until one is used.

Each check runs in a fresh interpreter, since this test process may already have imported those libraries.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HEAVY = ("moderngl", "wgpu", "pxr", "imgui_bundle", "trimesh", "glfw", "PIL")


def run_python(code: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120, check=False
    )


def test_import_gandalf_core_loads_no_heavy_library() -> None:
    result = run_python(
        "import sys, gandalf_core, gandalf_core.ecs, gandalf_core.math, gandalf_core.systems, gandalf_core.app\n"
        f"print(','.join(m for m in {HEAVY!r} if m in sys.modules))"
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "", f"imported by 'import gandalf_core': {result.stdout.strip()}"


def test_the_check_itself_detects_an_import() -> None:
    # Guards the test above against always passing: a heavy import does show up in the list.
    result = run_python(f"import sys, gandalf_core, PIL\nprint(','.join(m for m in {HEAVY!r} if m in sys.modules))")
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "PIL"


def test_unknown_backend_fails_before_any_gpu_import() -> None:
    result = run_python(
        "import sys\n"
        "from gandalf_core import Application\n"
        "from gandalf_core.render import UnknownBackendError\n"
        "try:\n"
        "    Application('vulkan', headless=True)\n"
        "except UnknownBackendError as error:\n"
        "    print('MESSAGE:' + str(error))\n"
        "else:\n"
        "    print('MESSAGE:none raised')\n"
        f"print('LOADED:' + ','.join(m for m in {HEAVY!r} if m in sys.modules))"
    )
    assert result.returncode == 0, result.stderr
    lines = dict(line.partition(":")[::2] for line in result.stdout.splitlines())
    assert lines["MESSAGE"] == "unknown backend 'vulkan': choose one of opengl, webgpu"
    assert lines["LOADED"] == "", f"imported before the backend was checked: {lines['LOADED']}"


def test_unknown_backend_error_is_a_value_error() -> None:
    from gandalf_core.render import UnknownBackendError, check_backend

    assert issubclass(UnknownBackendError, ValueError)
    assert check_backend("OpenGL") == "opengl" and check_backend("wgpu") == "webgpu"
