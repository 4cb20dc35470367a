"""What this machine offers the course: ``python -m gandalf_tools.doctor``, the first thing to run.

Prints the Python packages that draw (moderngl, wgpu, glfw), the OpenGL context the engine gets (vendor,
renderer, version, how many extensions), every WebGPU adapter wgpu finds (backend, type, the limits the course
cares about), and a table of every step, concept and technique: where it runs here, and where it needs something
this machine lacks, what that is and what to run instead. Takes a few seconds; exits with 1 when neither API
works.
"""

from __future__ import annotations

import argparse
import importlib
import importlib.metadata
import os
import platform
import sys

from gandalf_core.app.cli import plain
from gandalf_core.render.capabilities import WEBGPU_DEFAULT_LIMITS, Needs, Offer, opengl_offer, webgpu_offer

from .tour import REPO_ROOT, find_steps, step_parts

#: Environment variables that change which implementation answers (shown when set).
ENVIRONMENT = ("GALLIUM_DRIVER", "MESA_GL_VERSION_OVERRIDE", "MESA_GLSL_VERSION_OVERRIDE", "LIBGL_ALWAYS_SOFTWARE",
               "WGPU_BACKEND_TYPE", "WGPUPY_WGPU_ADAPTER_NAME", "VK_ICD_FILENAMES", "VK_DRIVER_FILES", "DISPLAY")
#: The WebGPU limits the course's parts lean on, shown per adapter (``--all-limits``: every one).
KEY_LIMITS = ("max-texture-dimension-2d", "max-bind-groups", "max-storage-buffers-per-shader-stage",
              "max-storage-textures-per-shader-stage", "max-sampled-textures-per-shader-stage",
              "max-compute-invocations-per-workgroup", "max-compute-workgroup-storage-size",
              "max-storage-buffer-binding-size")


def _version(package: str) -> str:
    try:
        return importlib.metadata.version(package)
    except importlib.metadata.PackageNotFoundError:
        return "not installed"


def opengl_report() -> tuple[list[str], Offer | None]:
    """Lines about the engine's headless OpenGL context, and what it offers (None: no OpenGL)."""
    try:
        from gandalf_core.render.opengl.renderer import _standalone_context

        ctx = _standalone_context()
    except Exception as exc:  # noqa: BLE001 - any failure here is the answer: no OpenGL context
        return [f"  no context: {exc}"], None
    try:
        info = ctx.info
        lines = [f"  vendor      {info.get('GL_VENDOR', '?')}",
                 f"  renderer    {info.get('GL_RENDERER', '?')}",
                 f"  version     {info.get('GL_VERSION', '?')}",
                 f"  extensions  {len(ctx.extensions)}"]
        return lines, opengl_offer(ctx)
    finally:
        ctx.release()


def webgpu_report(all_limits: bool = False) -> tuple[list[str], Offer | None]:
    """Lines about every wgpu adapter, and what the one the engine picks offers (None: no adapter)."""
    try:
        import wgpu

        from gandalf_core.render.webgpu.device import _quiet_runtime_dir

        _quiet_runtime_dir()
        adapters = wgpu.gpu.enumerate_adapters_sync()
        picked = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    except Exception as exc:  # noqa: BLE001 - any failure here is the answer: no WebGPU
        return [f"  no adapter: {exc}"], None
    if picked is None:
        return ["  no adapter: install a Vulkan driver (on Debian: mesa-vulkan-drivers libvulkan1)"], None
    from wgpu.backends import wgpu_native

    lines = [f"  wgpu-native {'.'.join(str(x) for x in wgpu_native.lib_version_info)}"]
    for adapter in adapters:
        info = adapter.info
        mark = "*" if (info["device"], info["backend_type"]) == (picked.info["device"], picked.info["backend_type"]) \
            else "-"
        lines.append(f"  {mark} {info['device']} · {info['backend_type']} · {info['adapter_type']} · "
                     f"{len(adapter.features)} optional features")
        names = sorted(WEBGPU_DEFAULT_LIMITS) if all_limits else KEY_LIMITS
        limits = dict(adapter.limits)
        lines += [f"      {name:<42} {limits.get(name, '?'):>11}   (default {WEBGPU_DEFAULT_LIMITS[name]})"
                  for name in names]
    lines.append("  (* the adapter the engine picks; its devices get the default limits plus what a part declares)")
    return lines, webgpu_offer(picked)


def part_needs(part: str) -> Needs:
    """The needs the part's ``scene.py`` declares in its ``PART``."""
    return importlib.import_module(f"{part}.scene").PART.needs


def verdict(part: str, api: str, needs: Needs, offer: Offer | None, other: Offer | None) -> str:
    """"runs", or what is missing and what to use instead."""
    if offer is None:
        return f"no {'OpenGL' if api == 'opengl' else 'WebGPU'} here"
    gap = needs.missing(offer)
    if not gap:
        return "runs"
    other_api = "webgpu" if api == "opengl" else "opengl"
    other_runs = other is not None and not needs.missing(other)
    return f"needs {gap}" + (f" -> run python -m {part}.{other_api}" if other_runs else "")


def table(opengl: Offer | None, webgpu: Offer | None) -> list[str]:
    """One row per step, concept and technique: its verdict in each API."""
    parts = [p for step in find_steps() for p in step_parts(step)]
    width = max(len(p) for p in parts) + 2
    rows = [f"  {'part':<{width}}{'OpenGL':<20}WebGPU"]
    for part in parts:
        needs = part_needs(part)
        gl, wg = verdict(part, "opengl", needs, opengl, webgpu), verdict(part, "webgpu", needs, webgpu, opengl)
        if gl == wg == "runs":
            rows.append(f"  {part:<{width}}{'runs':<20}runs")
        else:
            rows.append(f"  {part:<{width}}{gl if gl == 'runs' else '':<20}{wg if wg == 'runs' else ''}")
            for api, text in (("OpenGL", gl), ("WebGPU", wg)):
                if text != "runs":  # what is missing, then (on its own line) where to go instead
                    need, _, instead = text.partition(" -> ")
                    rows.append(f"      {api}: {need}")
                    rows += [f"      {'':<{len(api)}}  {instead} instead"] if instead else []
    return rows


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m gandalf_tools.doctor", description=plain(__doc__),
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--all-limits", action="store_true", help="show every WebGPU limit, not only the key ones")
    args = parser.parse_args(argv)
    if str(REPO_ROOT) not in sys.path:
        sys.path.insert(0, str(REPO_ROOT))
    print(f"Python {platform.python_version()} on {platform.system()} {platform.machine()} · "
          + " · ".join(f"{p} {_version(p)}" for p in ("numpy", "moderngl", "glcontext", "wgpu", "glfw")))
    env = [f"{name}={os.environ[name]}" for name in ENVIRONMENT if os.environ.get(name)]
    print("environment: " + (" ".join(env) if env else "no variable that picks a driver is set"))
    print("\nOpenGL (moderngl, the engine's headless EGL context)")
    gl_lines, gl = opengl_report()
    print("\n".join(gl_lines))
    print("\nWebGPU (wgpu adapters)")
    wgpu_lines, wg = webgpu_report(args.all_limits)
    print("\n".join(wgpu_lines))
    print("\nWhat runs here (every part needs at least OpenGL 3.3 core or WebGPU's default limits)")
    print("\n".join(table(gl, wg)))
    print("\n".join(grading_report()))
    return 0 if gl is not None or wg is not None else 1


def grading_report() -> list[str]:
    """How the grader would keep a student's code from the checkout on this machine, as this user."""
    from gandalf_tools.grading.sandbox import MEANING, isolation, isolation_warning

    mode = isolation()
    return ["", f"Grading isolation (as uid {os.geteuid() if hasattr(os, 'geteuid') else '?'}): {mode}",
            f"  {isolation_warning(mode) or MEANING[mode]}"]


if __name__ == "__main__":
    raise SystemExit(main())
