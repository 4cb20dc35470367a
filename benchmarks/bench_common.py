"""What the benchmark scripts share: the paper's scenes, one fresh process per configuration, peak memory, the sky's
PNG faces and the grid the models stand on. A script imports it by name (``python benchmarks/<script>.py`` puts
this folder on the path)."""

from __future__ import annotations

import argparse
import json
import math
import resource
import subprocess
import sys
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
SHADERS = HERE / "shaders"
BACKENDS = ("opengl", "webgpu")
#: scene -> (models, whether they rotate): the paper's scenes 1-5
PAPER_SCENES: dict[str, tuple[int, bool]] = {
    "scene1": (1, False),
    "scene2": (10, False),
    "scene3": (50, False),
    "scene4": (50, True),
    "scene5": (100, True),
}


def run_child(script: str, cfg: dict[str, Any], failure: dict[str, Any]) -> dict[str, Any] | None:
    """Run ``script --child CFG`` in a fresh process (from the repository root) and print its last JSON line;
    returns that record, or None after printing ``failure`` with the child's exit status."""
    proc = subprocess.run([sys.executable, str(Path(script).resolve()), "--child", json.dumps(cfg)],
                          cwd=ROOT, stdout=subprocess.PIPE, text=True)
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith("{")]
    if proc.returncode != 0 or not lines:
        print(json.dumps({**failure, "error": f"child exited with {proc.returncode}"}), flush=True)
        return None
    print(lines[-1], flush=True)
    return json.loads(lines[-1])


def parse_or_answer(parser: argparse.ArgumentParser, argv: list[str] | None, run: Any) -> argparse.Namespace | None:
    """Parse the command line, with the hidden ``--child CFG`` through which :func:`run_child` hands a child its
    configuration. In such a child: print ``run(cfg)`` as one JSON line and return None (the child is done)."""
    parser.add_argument("--child", default=None, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child is None:
        return args
    print(json.dumps(run(json.loads(args.child))), flush=True)
    return None


def backends_parser(doc: str, frames: int, frames_help: str = "measured frames", **options: Any
                    ) -> argparse.ArgumentParser:
    """The command line of a benchmark measured once per API: ``--backends``, ``--size WIDTHxHEIGHT`` and
    ``--frames`` (``options`` go to the parser; add more arguments before parsing)."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0], **options)
    parser.add_argument("--backends", default=",".join(BACKENDS))
    parser.add_argument("--size", default="1280x720", help="WIDTHxHEIGHT")
    parser.add_argument("--frames", type=int, default=frames, help=frames_help)
    return parser


def per_backend(args: argparse.Namespace, measure: Any, *extra: Any) -> list[dict[str, Any]]:
    """``measure(backend, width, height, frames, *extra)`` for each of ``--backends``, each result printed as one
    JSON line as it comes; the results."""
    width, height = (int(v) for v in args.size.lower().split("x"))
    results = []
    for backend in args.backends.split(","):
        results.append(measure(backend.strip(), width, height, args.frames, *extra))
        print(json.dumps(results[-1]), flush=True)
    return results


def rss_mb() -> float:
    """Peak resident set size of this process so far, in MiB (Linux reports KiB, macOS bytes)."""
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return round(rss / (1024 * 1024 if sys.platform == "darwin" else 1024), 1)


def sky_files(cache: Path, size: int) -> list[Path]:
    """Six ``size``² PNG faces of a sky (with a little noise, so PNG cannot compress them away), written once."""
    import numpy as np
    from PIL import Image

    from gandalf_core.resources import sky_cube

    cache.mkdir(parents=True, exist_ok=True)
    paths = [cache / f"sky{size}_{face}.png" for face in ("px", "nx", "py", "ny", "pz", "nz")]
    if all(p.is_file() for p in paths):
        return paths
    base = sky_cube(min(size, 256))
    rng = np.random.default_rng(7)
    for path, face in zip(paths, base.faces):
        arr = np.asarray(Image.fromarray(face).resize((size, size), Image.BILINEAR)).copy()
        noise = rng.integers(-3, 4, arr[..., :3].shape)
        arr[..., :3] = np.clip(arr[..., :3].astype(np.int16) + noise, 0, 255)
        Image.fromarray(arr.astype(np.uint8)).save(path, compress_level=1)
    return paths


def grid_positions(n: int) -> Any:
    """``n`` positions on a cubic grid of spacing 1.8 in front of the camera (same layout as raw_ceiling.py)."""
    import numpy as np

    g = math.ceil(round(n ** (1.0 / 3.0), 9))
    i = np.arange(n)
    return np.stack([(i % g) - (g - 1) / 2, (i // g % g) - (g - 1) / 2, -(i // (g * g)) - 2.0], 1) * 1.8


def request_gpu_timing() -> None:
    """Have WebGPU devices made from now on requested with the timestamp features (before the app is made)."""
    import os

    from gandalf_core.render.gpu_timing import TIMING_VARIABLE

    os.environ[TIMING_VARIABLE] = "1"


def gpu_ms_per_pass(app: Any, frames: int, warmup: int = 3) -> dict[str, float]:
    """Median GPU milliseconds of each pass, and of the whole frame, over ``frames`` frames captured after the
    measured ones (the frame inspector's timer: timestamp queries; not part of the fps figures).

    The captures run back to back, after ``warmup`` captured frames that are not counted, and name no entities
    (``name=False``): a capture's own CPU work between frames (naming a million instances takes about 0.3 s) would
    leave the GPU idle long enough to lower its clocks, and its passes would be timed slower than the frames whose
    fps are reported. Passes of one name in a frame (two dispatches, say) add up, and so do the frame's
    render() calls (the editor's viewport and window) in ``frame``."""
    import statistics

    from step07_advanced.editor.frame_inspector.capture import capture_frame

    times: dict[str, list[float]] = {}
    for frame in range(warmup + frames):
        capture = capture_frame(app, describe=False, name=False)
        if frame < warmup:
            continue
        this_frame: dict[str, float] = {}
        for gpu_pass in capture.passes:
            if gpu_pass.gpu_ms is not None:
                this_frame[gpu_pass.name] = this_frame.get(gpu_pass.name, 0.0) + gpu_pass.gpu_ms
        if capture.frame_gpu_ms:
            this_frame["frame"] = sum(capture.frame_gpu_ms)
        for name, ms in this_frame.items():
            times.setdefault(name, []).append(ms)
    return {name: round(statistics.median(values), 3) for name, values in times.items()}


# ------------------------------------------------------------------------------------------------
# Frame pacing: two frames in flight
# ------------------------------------------------------------------------------------------------
class GLFramesInFlight:
    """Wait as a swap chain of two images does: each call copies one pixel of the frame just drawn into a read-back
    buffer of its own (a pixel-pack buffer, asynchronous), sends the frame to the GPU (glFlush) and then waits for
    the previous frame's pixel. The GPU draws frame N while the CPU builds frame N+1, and the CPU is never more than
    one frame ahead. ``drain()`` waits for the last frame. ``pixel`` is the last pixel read (RGBA bytes; None before
    the second call)."""

    def __init__(self, ctx: Any, framebuffer: Any, x: int, y: int) -> None:
        from gandalf_core.render.opengl.raw_gl import gl_function

        self._framebuffer, self._viewport = framebuffer, (int(x), int(y), 1, 1)
        self._buffers = [ctx.buffer(reserve=4), ctx.buffer(reserve=4)]
        self._flush = gl_function("glFlush", ())
        self._count = 0
        self.pixel: bytes | None = None

    def __call__(self) -> None:
        self._framebuffer.read_into(self._buffers[self._count % 2], viewport=self._viewport, components=4)
        self._flush()
        if self._count:
            self.pixel = self._buffers[(self._count - 1) % 2].read()
        self._count += 1

    def drain(self) -> None:
        if self._count:
            self.pixel = self._buffers[(self._count - 1) % 2].read()


class WgpuFramesInFlight:
    """:class:`GLFramesInFlight` in WebGPU: each call copies one pixel of ``texture()`` (the frame just drawn) into a
    mappable buffer of its own, then waits until the previous frame's buffer is mapped (its copy, and so its frame,
    has finished) and maps this frame's buffer asynchronously."""

    def __init__(self, device: Any, texture: Any, x: int, y: int) -> None:
        import wgpu

        self._device, self._texture, self._origin = device, texture, (int(x), int(y), 0)
        usage = wgpu.BufferUsage.MAP_READ | wgpu.BufferUsage.COPY_DST
        self._buffers = [device.create_buffer(size=256, usage=usage) for _ in range(2)]
        self._pending: Any = None
        self._count = 0
        self.pixel: bytes | None = None

    def __call__(self) -> None:
        buffer = self._buffers[self._count % 2]
        encoder = self._device.create_command_encoder()
        encoder.copy_texture_to_buffer({"texture": self._texture(), "origin": self._origin},
                                       {"buffer": buffer, "offset": 0, "bytes_per_row": 256, "rows_per_image": 1},
                                       (1, 1, 1))
        self._device.queue.submit([encoder.finish()])
        self.drain()
        self._pending = (buffer, buffer.map_async("READ"))
        self._count += 1

    def drain(self) -> None:
        if self._pending is not None:
            buffer, promise = self._pending
            promise.sync_wait()
            self.pixel = bytes(buffer.read_mapped(0, 4))
            buffer.unmap()
            self._pending = None
