"""Are GPU times present, and do the passes' times add up to the frame's? Step 07's showcase (a compute dispatch,
a shadow map, some forty draws, a sky) at 1280x720 in both APIs, headless.

For each backend: 30 frames to warm up, then 15 captured frames with GPU timing (``capture_frame(app,
describe=False)``: passes, draws and timestamps only). Per frame it takes the sum of the render passes' GPU times
(the compute pass is submitted before the frame's encoder, so it is left out of both sides) and the frame's GPU time
from the same timer (first timestamp of the frame's render() to its last), and, on OpenGL, an independent clock: a
``GL_TIME_ELAPSED`` query (moderngl's ``ctx.query(time=True)``) around the whole ``app.step()``, against which it
prints the ratio of all the passes' time (the compute pass included) too. Prints one JSON
line per backend (medians over the captured frames) and exits 1 when a time is missing or the median sum of the
passes lies more than 20 % from the median frame time.

    python benchmarks/check_gpu_timing.py                   # both APIs
    python benchmarks/check_gpu_timing.py --backends opengl --frames 30
"""

from __future__ import annotations

import argparse
import statistics
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from bench_common import backends_parser, per_backend, request_gpu_timing  # noqa: E402


def check(backend: str, width: int, height: int, frames: int) -> dict:
    import importlib

    from step07_advanced.editor.frame_inspector.capture import capture_frame

    module = importlib.import_module(f"step07_advanced.showcase.{backend}")
    app = module.create_app(headless=True, width=width, height=height)
    try:
        app.run(frames=30)
        sums, totals, elapsed, everything, missing, passes = [], [], [], [], 0, {}
        for _ in range(frames):
            query = app.renderer.ctx.query(time=True) if backend == "opengl" else None
            if query is not None:
                with query:
                    capture = capture_frame(app, describe=False)
                elapsed.append(query.elapsed / 1e6)
            else:
                capture = capture_frame(app, describe=False)
            drawn = [p for p in capture.passes if p.name != "compute"]
            missing += sum(p.gpu_ms is None for p in capture.passes) + sum(d.gpu_ms is None for d in capture.draws)
            if not capture.frame_gpu_ms or any(p.gpu_ms is None for p in drawn):
                continue
            sums.append(sum(p.gpu_ms for p in drawn))
            everything.append(sum(p.gpu_ms for p in capture.passes if p.gpu_ms is not None))
            totals.append(capture.frame_gpu_ms[-1])
            for p in capture.passes:
                if p.gpu_ms is not None:
                    passes.setdefault(p.name, []).append(p.gpu_ms)
        result = {
            "backend": backend, "size": f"{width}x{height}", "renderer": app.renderer.ctx.info["GL_RENDERER"]
            if backend == "opengl" else app.renderer.adapter.info.get("device", "?"),
            "timing": capture.timing, "frames": frames, "timed_frames": len(sums), "missing_times": missing,
            "passes_ms": {k: round(statistics.median(v), 4) for k, v in passes.items()},
            "sum_of_passes_ms": round(statistics.median(sums), 4) if sums else None,
            "frame_gpu_ms": round(statistics.median(totals), 4) if totals else None,
        }
        if elapsed and len(elapsed) == len(everything):  # every pass, the compute one too, against the other clock
            result["gl_time_elapsed_step_ms"] = round(statistics.median(elapsed), 4)
            result["all_passes_over_gl_time_elapsed"] = round(statistics.median(
                s / e for s, e in zip(everything, elapsed) if e > 0), 4)
        if sums:
            result["sum_over_frame"] = round(statistics.median(s / t for s, t in zip(sums, totals)), 4)
        result["ok"] = bool(sums) and missing == 0 and abs(result["sum_over_frame"] - 1.0) <= 0.2
        return result
    finally:
        app.close()


def main(argv: list[str] | None = None) -> int:
    args = backends_parser(__doc__, 15, "timed frames", formatter_class=argparse.RawDescriptionHelpFormatter,
                           epilog=__doc__).parse_args(argv)
    request_gpu_timing()  # WebGPU devices get the timestamp features (before any is made)
    return 0 if all(result["ok"] for result in per_backend(args, check)) else 1


if __name__ == "__main__":
    raise SystemExit(main())
