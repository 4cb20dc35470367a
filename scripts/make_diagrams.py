"""Draw the course site's diagrams: ``python scripts/make_diagrams.py [--out DIR] [--force] [--only NAME]``.

Writes SVG files (``docs/images/diagram_*.svg`` by default), each shown on the page that teaches it:

| file | page | what it shows |
|---|---|---|
| ``diagram_pipeline.svg`` | step 02 | the pipeline stages in OpenGL and WebGPU (no tessellation, no geometry stage) |
| ``diagram_sampling.svg`` | step 03 | nearest against linear magnification; minification without and with mipmaps |
| ``diagram_spaces.svg`` | step 04 | the coordinate spaces and their matrices; depth against distance in both ranges |
| ``diagram_frustum.svg`` | step 04 | the frustum in camera space, and the same points in NDC for both depth ranges |
| ``diagram_ecs_frame.svg`` | architecture | one frame's data flow: components, systems, render system, renderer |
| ``diagram_frame_passes.svg`` | architecture | the render system's passes in one frame |
| ``diagram_uniform_block.svg`` | architecture | a uniform block's bytes as the engine lays them out, padding shown |
| ``diagram_tbn.svg`` | step 07 showcase | the tangent frame and a normal-map texel turned into a world normal |
| ``diagram_shadow_pass.svg`` | step 07 showcase | the depth pass from the light and the comparison from the camera |
| ``diagram_microfacets.svg`` | step 07 PBR model | microfacets, the half vector, and GGX's D for four roughnesses |
| ``diagram_tess_levels.svg`` | step 07 terrain | patches cut by the tessellation level their distance deserves |
| ``diagram_workgroups.svg`` | step 07 filter | a compute dispatch, one work group, its shared-memory tile and apron |
| ``diagram_path_bounce.svg`` | step 07 path tracer | one path: a diffuse, a mirror and a glass bounce, then the sky |

The drawings are computed from what they show (the engine's own ``perspective`` and ``BlockLayout``, GGX, the
level-of-detail formula). Existing files are kept unless ``--force`` is given. Needs matplotlib (the dev extra);
runs headless (Agg).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path

import diagrams_advanced as advanced
import diagrams_course as course

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_OUT = ROOT / "docs" / "images"

DIAGRAMS: dict[str, Callable[[Path], None]] = {
    "diagram_pipeline.svg": course.pipeline,
    "diagram_sampling.svg": course.sampling,
    "diagram_spaces.svg": course.spaces,
    "diagram_frustum.svg": advanced.frustum,
    "diagram_ecs_frame.svg": course.ecs_frame,
    "diagram_frame_passes.svg": advanced.frame_passes,
    "diagram_uniform_block.svg": advanced.uniform_block,
    "diagram_tbn.svg": advanced.tbn,
    "diagram_shadow_pass.svg": advanced.shadow_pass,
    "diagram_microfacets.svg": advanced.microfacets,
    "diagram_tess_levels.svg": advanced.tess_levels,
    "diagram_workgroups.svg": advanced.workgroups,
    "diagram_path_bounce.svg": advanced.path_bounce,
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help=f"folder for the SVG files ({DEFAULT_OUT})")
    parser.add_argument("--force", action="store_true", help="overwrite diagrams that already exist")
    parser.add_argument("--only", choices=sorted(DIAGRAMS), action="append", help="draw only this diagram "
                        "(repeatable)")
    args = parser.parse_args(argv)
    try:
        import matplotlib
    except ImportError:
        print("make_diagrams: needs matplotlib (pip install -e '.[dev]')", file=sys.stderr)
        return 2
    matplotlib.use("Agg")
    names = args.only or list(DIAGRAMS)
    existing = [name for name in names if (args.out / name).exists()]
    if existing and not args.force:
        print(f"make_diagrams: {', '.join(existing)} already exist in {args.out}; pass --force to overwrite",
              file=sys.stderr)
        return 1
    args.out.mkdir(parents=True, exist_ok=True)
    for name in names:
        DIAGRAMS[name](args.out / name)
        print(f"wrote {args.out / name} ({(args.out / name).stat().st_size // 1024} KiB)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
