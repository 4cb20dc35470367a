"""The diagrams of the later pages, each computed from the maths it illustrates (scripts/make_diagrams.py draws them):

* ``frustum``: the view frustum in camera space and the same points in normalised device coordinates, through the
  engine's own ``perspective`` (both depth ranges);
* ``uniform_block``: a Material block's bytes as the engine lays them out (std140 = WGSL uniform), padding shown;
* ``frame_passes``: the passes of one frame in the render system, in order;
* ``tbn``: the tangent frame at a point of a surface, and a normal-map texel turned into a world normal;
* ``microfacets``: a rough surface as tiny mirrors, the half vector, and GGX's D for four roughnesses;
* ``shadow_pass``: the depth pass from the light and the comparison in the camera's pass;
* ``tess_levels``: the terrain's patches cut by the tessellation level their distance to the eye deserves;
* ``workgroups``: a compute dispatch over an image, one invocation's ids, and the tiled blur's shared rows;
* ``path_bounce``: one path through a scene: a diffuse, a mirror and a glass bounce, then the sky.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from diagram_kit import DATA, EDGE, FIXED, PROGRAMMABLE, SYSTEM, arrow, box, canvas, save

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

BLUE, RED, GREEN, ORANGE, GREY = "#1155cc", "#cc4125", "#38761d", "#b45f06", "#888888"


def frustum(path: Path) -> None:
    """Camera space (side view: y against -z) and the same points after projection and the divide by w."""
    import matplotlib.pyplot as plt

    from gandalf_core.math import perspective

    near, far, fovy = 1.0, 6.0, 60.0
    t = np.tan(np.radians(fovy) / 2)
    depths = np.array([1.0, 1.5, 2.25, 3.5, 6.0])
    heights = np.linspace(-1.0, 1.0, 5)
    fig, (ax0, ax1, ax2) = plt.subplots(1, 3, figsize=(12.0, 3.8), gridspec_kw={"width_ratios": [1.6, 1, 1]})
    ax0.plot([0, far, far, 0], [0, far * t, -far * t, 0], color=EDGE, lw=1.0)
    ax0.plot([near, near], [-near * t, near * t], color=BLUE, lw=2)
    ax0.plot([far, far], [-far * t, far * t], color=RED, lw=2)
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(depths)))
    for d, c in zip(depths, colours):
        ax0.scatter(np.full(heights.shape, d), heights * d * t * 0.9, color=c, s=18, zorder=3)
    ax0.scatter([0], [0], color="black", s=30)
    ax0.text(0.05, 0.35, "eye", fontsize=9)
    ax0.text(near, -near * t - 0.5, "near", color=BLUE, ha="center", fontsize=9)
    ax0.text(far, -far * t - 0.5, "far", color=RED, ha="center", fontsize=9)
    ax0.annotate("", xy=(1.6, 0), xytext=(0, 0), arrowprops={"arrowstyle": "-|>", "color": GREY})
    ax0.text(1.7, 0.1, "-z (the view direction)", fontsize=8, color=GREY)
    ax0.set_title(f"camera space: the frustum (fovy {fovy:.0f}°, near {near:g}, far {far:g})", fontsize=9)
    ax0.set_aspect("equal")
    ax0.axis("off")
    for ax, rng, lo in ((ax1, "opengl", -1.0), (ax2, "webgpu", 0.0)):
        p = perspective(fovy, 1.0, near, far, rng)
        ax.add_patch(plt.Rectangle((lo, -1), 1 - lo, 2, fill=False, color=EDGE))
        for d, c in zip(depths, colours):
            pts = np.stack([np.zeros_like(heights), heights * d * t * 0.9, np.full(heights.shape, -d),
                            np.ones_like(heights)])
            clip = p @ pts
            ndc = clip[:3] / clip[3]
            ax.scatter(ndc[2], ndc[1], color=c, s=18, zorder=3)
        ax.axvline(lo, color=BLUE, lw=2)
        ax.axvline(1, color=RED, lw=2)
        ax.set_xlim(lo - 0.15, 1.15)
        ax.set_ylim(-1.25, 1.25)
        ax.set_xlabel("$z_{ndc}$", fontsize=9)
        ax.set_ylabel("$y_{ndc}$", fontsize=9)
        ax.tick_params(labelsize=7)
        name = "OpenGL" if lo == -1 else "WebGPU"
        ax.set_title(f"{name}: after P and the divide by w\n$z_{{ndc}} \\in [{lo:g}, 1]$", fontsize=9)
    fig.text(0.5, -0.02, "The same points, coloured by distance: the frustum becomes a box, far points crowd "
             "towards the far end of the depth range.", ha="center", fontsize=8.5, color="#444444")
    save(fig, path)


def uniform_block(path: Path) -> None:
    """A Material block's bytes, laid out by the engine's BlockLayout (std140 / WGSL uniform rules)."""
    import matplotlib.pyplot as plt

    from gandalf_core.resources.layout import BlockLayout

    fields = [("shininess", "float"), ("specular", "vec3"), ("color", "vec4"), ("uv_scale", "vec2"),
              ("strength", "float")]
    layout = BlockLayout("Material", fields)
    sizes = {"float": 4, "vec2": 8, "vec3": 12, "vec4": 16}
    fig, ax = plt.subplots(figsize=(12.0, 2.6))
    unit = 12.0 / layout.size
    palette = [PROGRAMMABLE, SYSTEM, DATA, "#d9d2e9", "#fff2cc"]
    ax.add_patch(plt.Rectangle((0, 0), layout.size * unit, 1, facecolor="#f3f3f3", hatch="///", edgecolor="#bbbbbb"))
    for (name, kind), colour in zip(fields, palette):
        offset = layout.offset(name)
        ax.add_patch(plt.Rectangle((offset * unit, 0), sizes[kind] * unit, 1, color=colour, ec=EDGE))
        ax.text((offset + sizes[kind] / 2) * unit, 0.5, f"{name}\n{kind}", ha="center", va="center", fontsize=8)
    for b in range(0, layout.size + 1, 4):
        ax.plot([b * unit] * 2, [-0.08 if b % 16 else -0.2, 0], color=EDGE, lw=0.8)
        if b % 16 == 0:
            ax.text(b * unit, -0.35, str(b), ha="center", fontsize=8)
    ax.text(layout.size * unit / 2, -0.7, "byte offset (16-byte rows); hatched: padding the layout inserts",
            ha="center", fontsize=8.5, color="#444444")
    decl = "  ".join(f"{kind} {name};" for name, kind in fields)
    ax.text(0, 1.25, f"uniform Material {{ {decl} }}  ->  {layout.size} bytes", fontsize=9, family="monospace")
    ax.set_xlim(-0.1, layout.size * unit + 0.1)
    ax.set_ylim(-0.9, 1.5)
    ax.axis("off")
    save(fig, path)


def frame_passes(path: Path) -> None:
    """The render system's passes in one frame, in order, and what each reads and writes."""
    fig, ax = canvas(12.0, 3.6, 12.0, 3.6)
    steps = [
        ("upload", "Frame + Lights blocks,\ninstance rows (float32)", FIXED),
        ("shadow pass", "only with a shadow-casting light:\nopaque batches, depth only,\ninto a 2048² shadow map",
         PROGRAMMABLE),
        ("main pass", "clear; opaque batches\n(instanced); the sky;\nblended batches last", PROGRAMMABLE),
        ("overlays", "the editor's panels\n(when it is on)", SYSTEM),
        ("present", "sRGB target to the\nwindow, or capture()", FIXED),
    ]
    ax.set_ylim(0.9, 3.6)
    w, gap = 2.0, 0.4
    for i, (name, what, colour) in enumerate(steps):
        x = 0.2 + i * (w + gap)
        box(ax, x, 1.9, w, 0.9, name, colour, size=9, weight="bold", dashed=name == "shadow pass")
        ax.text(x + w / 2, 1.75, what, ha="center", va="top", fontsize=8)
        if i:
            arrow(ax, x - gap, 2.35, x, 2.35)
    x_shadow, x_main = 0.2 + (w + gap), 0.2 + 2 * (w + gap)
    ax.annotate("", xy=(x_main + w / 2, 2.8), xytext=(x_shadow + w / 2, 2.8),
                arrowprops={"arrowstyle": "-|>", "color": ORANGE, "connectionstyle": "arc3,rad=-0.4"})
    ax.text((x_shadow + x_main + w) / 2, 3.35, "the shadow map, sampled by the lit materials", ha="center",
            fontsize=8, color=ORANGE)
    save(fig, path)


def tbn(path: Path) -> None:
    """A surface point with its tangent frame, and a normal-map texel turned into a world-space normal."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(11.0, 4.2))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    u, v = np.meshgrid(np.linspace(-1, 1, 9), np.linspace(-1, 1, 9))
    z = 0.25 * np.sin(1.5 * u) * np.cos(1.2 * v)
    ax.plot_wireframe(u, v, z, color="#bbbbbb", lw=0.6)
    p = np.array([0.2, 0.1, 0.25 * np.sin(0.3) * np.cos(0.12)])
    dzdu, dzdv = 0.25 * 1.5 * np.cos(0.3) * np.cos(0.12), -0.25 * 1.2 * np.sin(0.3) * np.sin(0.12)
    t_vec = np.array([1.0, 0.0, dzdu])
    t_vec /= np.linalg.norm(t_vec)
    n_vec = np.cross(t_vec, np.array([0.0, 1.0, dzdv]))
    n_vec /= np.linalg.norm(n_vec)
    b_vec = np.cross(n_vec, t_vec)
    m = np.array([0.45, 0.25, 0.86])
    m /= np.linalg.norm(m)
    shading = m[0] * t_vec + m[1] * b_vec + m[2] * n_vec
    for vec, colour, label in ((t_vec, RED, "T (u)"), (b_vec, GREEN, "B (up the image)"), (n_vec, BLUE, "N"),
                               (shading, ORANGE, "n = TBN · m")):
        ax.quiver(*p, *(0.8 * vec), color=colour, lw=2, arrow_length_ratio=0.15)
        ax.text(*(p + 0.9 * vec), label, color=colour, fontsize=9)
    ax.set_title("world space: the tangent frame at a point", fontsize=9)
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_zlim(-0.6, 1.2)
    ax.set_box_aspect((1, 1, 0.9))
    ax.set_axis_off()
    ax.view_init(elev=25, azim=-60)
    ax2 = fig.add_subplot(1, 2, 2)
    ax2.add_patch(plt.Rectangle((-0.6, 0), 1.7, 1, color="#8080ff"))
    ax2.text(0.25, 0.5, "a normal-map texel\nrgb = (0.73, 0.62, 0.93)\nm = 2 rgb − 1\n= (0.45, 0.25, 0.86)",
             ha="center", va="center", fontsize=8)
    ax2.annotate("", xy=(1.6, 0.85), xytext=(1.1, 0.5), arrowprops={"arrowstyle": "-|>", "color": RED})
    ax2.annotate("", xy=(1.6, 0.5), xytext=(1.1, 0.5), arrowprops={"arrowstyle": "-|>", "color": GREEN})
    ax2.annotate("", xy=(1.6, 0.15), xytext=(1.1, 0.5), arrowprops={"arrowstyle": "-|>", "color": BLUE})
    ax2.text(1.65, 0.85, "m.x along T (+u of the texture)", va="center", fontsize=8.5, color=RED)
    ax2.text(1.65, 0.5, "m.y along B (up the image, −v)", va="center", fontsize=8.5, color=GREEN)
    ax2.text(1.65, 0.15, "m.z along N (out of the surface)", va="center", fontsize=8.5, color=BLUE)
    ax2.text(0.0, -0.25, "T follows the texture's +u, B points up the image, N out of the surface: "
             "[T B N] turns tangent space into world space.", fontsize=8.5, color="#444444")
    ax2.set_xlim(-0.65, 3.3)
    ax2.set_ylim(-0.4, 1.1)
    ax2.set_aspect("equal")
    ax2.axis("off")
    ax2.set_title("tangent space: what the texture stores", fontsize=9)
    save(fig, path)


def _ggx(n_dot_h: np.ndarray, roughness: float) -> np.ndarray:
    alpha2 = roughness ** 4
    return alpha2 / (np.pi * ((n_dot_h ** 2) * (alpha2 - 1) + 1) ** 2)


def microfacets(path: Path) -> None:
    """A rough surface as tiny mirrors: those whose normal is the half vector reflect l into v; GGX's D."""
    import matplotlib.pyplot as plt

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12.0, 3.8), gridspec_kw={"width_ratios": [1.5, 1]})
    rng = np.random.default_rng(7)
    xs = np.linspace(0, 10, 31)
    ys = np.concatenate([[0], np.cumsum(rng.normal(0, 0.3, len(xs) - 1))])
    ys -= np.linspace(ys[0], ys[-1], len(xs))
    light, view = np.array([-0.9, 0.44]), np.array([0.3, 0.95])
    light, view = light / np.linalg.norm(light), view / np.linalg.norm(view)
    half = (light + view) / np.linalg.norm(light + view)
    ax.plot(xs, ys, color=EDGE, lw=1.2)
    ax.plot([0, 10], [0, 0], color=GREY, ls=":", lw=0.8)
    for x0, x1, y0, y1 in zip(xs[:-1], xs[1:], ys[:-1], ys[1:]):
        normal = np.array([-(y1 - y0), x1 - x0])
        normal /= np.linalg.norm(normal)
        if normal @ half > 0.97:
            ax.plot([x0, x1], [y0, y1], color=ORANGE, lw=3)
            mid = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
            ax.annotate("", xy=mid + 0.9 * normal, xytext=mid, arrowprops={"arrowstyle": "-|>", "color": ORANGE})
    origin = np.array([5.0, 2.0])
    for vec, colour, label, side in ((light, RED, "l (to the light)", "right"), (view, BLUE, "v (to the eye)", "left"),
                                     (half, ORANGE, "h = normalize(l + v)", "right")):
        ax.annotate("", xy=origin + 1.6 * vec, xytext=origin, arrowprops={"arrowstyle": "-|>", "color": colour})
        ax.text(*(origin + 1.7 * vec), label, color=colour, fontsize=8.5, ha=side)
    ax.annotate("", xy=origin + np.array([0, 1.3]), xytext=origin, arrowprops={"arrowstyle": "-|>", "color": GREY})
    ax.text(origin[0] + 0.1, origin[1] + 1.0, "n", color=GREY, fontsize=9)
    ax.set_title("microfacets: only those facing h (orange) mirror the light into the eye", fontsize=9)
    ax.set_aspect("equal")
    ax.set_ylim(-1.2, 4.2)
    ax.axis("off")
    theta = np.linspace(0, np.pi / 2, 400)
    for r, colour in zip((0.2, 0.35, 0.5, 0.8), ("#08306b", "#2171b5", "#6baed6", "#bdd7e7")):
        ax2.plot(np.degrees(theta), _ggx(np.cos(theta), r) * np.cos(theta), color=colour,
                 label=f"roughness {r}")
    ax2.set_yscale("log")
    ax2.set_ylim(1e-3, 1e2)
    ax2.set_xlabel("angle between n and h (degrees)", fontsize=8.5)
    ax2.set_ylabel(r"$D(\mathbf{h})\,(\mathbf{n}\cdot\mathbf{h})$", fontsize=9)
    ax2.tick_params(labelsize=7)
    ax2.legend(fontsize=7.5, frameon=False)
    ax2.set_title(r"GGX: how many facets face h ($\alpha$ = roughness²)", fontsize=9)
    save(fig, path)


def shadow_pass(path: Path) -> None:
    """Pass 1 stores the depth seen from the light; pass 2 compares a point's depth in light space with it."""
    from matplotlib.patches import Rectangle

    fig, ax = canvas(12.0, 4.4, 12.0, 4.4)
    light = np.array([1.2, 4.0])
    ax.scatter(*light, s=160, color="#f1c232", edgecolor=EDGE, zorder=3)
    ax.text(light[0], light[1] + 0.25, "light", ha="center", fontsize=9)
    ax.plot([0.3, 11.7], [0.5, 0.5], color=EDGE, lw=2)
    ax.add_patch(Rectangle((4.0, 1.8), 1.2, 0.3, color="#999999"))
    ax.text(4.6, 1.5, "occluder", ha="center", fontsize=8.5)
    for x, colour, note in ((7.2, RED, "p: in shadow"), (10.2, GREEN, "q: lit")):
        target = np.array([x, 0.5])
        d = target - light
        hit = light + d * ((2.1 - light[1]) / d[1]) if x < 9 else None
        ax.plot(*zip(light, target), color=colour, lw=1.0, ls="--")
        if hit is not None:
            ax.scatter(*hit, color=colour, s=20, zorder=3)
            ax.text(hit[0] + 0.15, hit[1] + 0.05, "stored depth\n(nearest to the light)", fontsize=7.5,
                    color=colour)
        ax.scatter(*target, color=colour, s=30, zorder=3)
        ax.text(x, 0.15, note, ha="center", fontsize=8.5, color=colour)
    eye = np.array([11.3, 2.8])
    ax.scatter(*eye, s=60, marker="s", color=BLUE, zorder=3)
    ax.text(eye[0], eye[1] + 0.25, "camera", ha="center", fontsize=9, color=BLUE)
    for x in (7.2, 10.2):
        ax.plot([eye[0], x], [eye[1], 0.5], color=BLUE, lw=0.8)
    box(ax, 2.0, 3.85, 3.3, 0.5, "pass 1 (from the light): depth only\ninto the shadow map", PROGRAMMABLE, size=7)
    box(ax, 6.3, 3.3, 4.2, 0.75, "pass 2 (from the camera): p in light space;\nshadowed if depth(p) − bias > stored",
        PROGRAMMABLE, size=7)
    save(fig, path)


def tess_levels(path: Path) -> None:
    """A top view of the terrain's patches, each edge cut into clamp(scale · |b − a| / d, 1, 16) segments."""
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection

    n, size, scale, lo, hi = 8, 8.0, 16.0, 1, 16
    eye = np.array([1.3, -0.7])
    fig, ax = plt.subplots(figsize=(7.0, 6.6))

    def level(a: np.ndarray, b: np.ndarray) -> int:
        d = np.linalg.norm(eye - (a + b) / 2)
        return int(np.clip(np.ceil(scale * np.linalg.norm(b - a) / d), lo, hi))

    cell = size / n
    lines, dots, strips = [], [], []
    for i in range(n):
        for j in range(n):
            x0, y0 = i * cell, j * cell
            corners = np.array([[x0, y0], [x0 + cell, y0], [x0 + cell, y0 + cell], [x0, y0 + cell]])
            edges = list(zip(corners, np.roll(corners, -1, axis=0)))
            outer = [level(a, b) for a, b in edges]
            inner = max(outer)  # the inside is cut as finely as the finest edge
            # the inner level cuts the patch into strips (drawn in one direction only)
            strips += [[(x0 + k * cell / inner, y0), (x0 + k * cell / inner, y0 + cell)] for k in range(1, inner)]
            for (a, b), segments in zip(edges, outer):
                lines.append([tuple(a), tuple(b)])
                dots += list(a + np.outer(np.linspace(0, 1, segments + 1)[1:-1], b - a))
            ax.text(x0 + cell / 2, y0 + cell / 2, str(inner), ha="center", va="center", fontsize=7,
                    color=ORANGE)
    ax.add_collection(LineCollection(strips, colors="#c9daf8", linewidths=0.5, rasterized=True))
    ax.add_collection(LineCollection(lines, colors=EDGE, linewidths=0.8))
    ax.scatter(*np.array(dots).T, s=3, color=BLUE, rasterized=True)  # hundreds of dots: one picture
    ax.scatter(*eye, marker="^", s=90, color=RED)
    ax.text(eye[0] + 0.3, eye[1] - 0.1, "the eye (the terrain seen from above)", color=RED, fontsize=8.5)
    ax.set_aspect("equal")
    ax.set_xlim(-0.3, size + 0.3)
    ax.set_ylim(-1.1, size + 0.3)
    ax.axis("off")
    ax.set_title(f"edge level = clamp({scale:g} · edge length / distance, {lo}, {hi}) (an illustrative scale): "
                 "blue dots cut the edges;\n"
                 "the number is the patch's inner level. A shared edge gets one level from both patches: no cracks.",
                 fontsize=8.5)
    save(fig, path)


def workgroups(path: Path) -> None:
    """A dispatch of 16 x 16 work groups over an image, one invocation's ids; the tiled blur's shared-memory rows."""
    import matplotlib.pyplot as plt

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12.0, 4.6), gridspec_kw={"width_ratios": [1, 1.3]})
    groups, local = 4, 16
    side = groups * local
    for g in range(groups + 1):
        ax.plot([g * local, g * local], [0, side], color=EDGE, lw=1.2)
        ax.plot([0, side], [g * local, g * local], color=EDGE, lw=1.2)
    gx, gy = 1, 2
    ax.add_patch(plt.Rectangle((gx * local, gy * local), local, local, color=PROGRAMMABLE))
    for k in range(local + 1):
        ax.plot([gx * local + k] * 2, [gy * local, (gy + 1) * local], color="#6d9eeb", lw=0.4)
        ax.plot([gx * local, (gx + 1) * local], [gy * local + k] * 2, color="#6d9eeb", lw=0.4)
    ax.add_patch(plt.Rectangle((gx * local + 5, gy * local + 2), 1, 1, color=ORANGE))
    ax.text(side / 2, -3, f"a {side} x {side} image: dispatch({groups}, {groups}) work groups of {local} x {local} "
            "invocations,\none per pixel (blur_pass, sobel)", ha="center", va="top", fontsize=8.5)
    ax.text(side / 2, -11, "the orange one: global_invocation_id = workgroup_id · 16 + local_invocation_id\n"
            f"= ({gx}, {gy}) · 16 + (5, 2) = ({gx * local + 5}, {gy * local + 2})", fontsize=8, color=ORANGE,
            ha="center", va="top")
    ax.set_xlim(-1, side + 1)
    ax.set_ylim(-19, side + 1)
    ax.set_aspect("equal")
    ax.axis("off")
    tile, rows, radius = 64, 4, 8
    width = tile + 2 * radius
    ax2.add_patch(plt.Rectangle((0, 0), width, rows, color=DATA, ec=EDGE))
    ax2.add_patch(plt.Rectangle((radius, 0), tile, rows, color=PROGRAMMABLE, ec=EDGE))
    for k in range(width + 1):
        ax2.plot([k, k], [0, rows], color="#bbbbbb", lw=0.3)
    for k in range(rows + 1):
        ax2.plot([0, width], [k, k], color="#bbbbbb", lw=0.3)
    ax2.text(width / 2, rows + 4.0, "the tiled blur's work group: 64 x 4 invocations", ha="center", fontsize=9)
    ax2.text(radius / 2, rows + 0.5, f"apron r = {radius}", ha="center", va="bottom", fontsize=8, color=ORANGE)
    ax2.text(width - radius / 2, rows + 0.5, f"apron r = {radius}", ha="center", va="bottom", fontsize=8,
             color=ORANGE)
    ax2.text(width / 2, -1.2, "each row: 64 pixels (blue) plus r on each side (orange) loaded into workgroup\n"
             "memory once, clamped at the image's edge; a barrier; then every tap is read from there",
             ha="center", va="top", fontsize=8.5)
    ax2.set_xlim(-1, width + 1)
    ax2.set_ylim(-8, rows + 6)
    ax2.set_aspect("equal")
    ax2.axis("off")
    save(fig, path)


def path_bounce(path: Path) -> None:
    """One path: camera -> diffuse (random direction) -> mirror (reflected) -> glass (refracted) -> the sky."""
    import matplotlib.pyplot as plt

    fig, ax = canvas(12.0, 4.6, 12.0, 4.6)
    ax.add_patch(plt.Rectangle((0, 0), 12, 0.6, color="#d9d9d9"))
    ax.text(0.3, 0.25, "diffuse ground", fontsize=8)
    ax.add_patch(plt.Circle((6.0, 1.6), 1.0, color="#cccccc", ec=EDGE))
    ax.text(6.0, 1.6, "metal", ha="center", va="center", fontsize=8)
    ax.add_patch(plt.Circle((9.6, 2.6), 0.9, color="#cfe2f3", ec=EDGE, alpha=0.8))
    ax.text(9.6, 2.6, "glass", ha="center", va="center", fontsize=8)
    points = [(0.6, 3.8), (3.4, 0.6), (5.2, 2.2), (8.75, 2.85), (10.45, 2.35), (11.8, 4.4)]
    notes = ["camera: a ray per pixel,\njittered in the pixel",
             "Lambert: a random direction\naround n (cosine-weighted)",
             "metal: the mirror direction,\nfuzzed by roughness",
             "glass: refract (Snell) or reflect\n(Fresnel, by a random number)",
             "leaves the glass", "the sky: L = throughput × sky(d)"]
    colours = [BLUE, GREEN, GREY, "#3d85c6", "#3d85c6", ORANGE]
    for (a, b), colour in zip(zip(points[:-1], points[1:]), colours):
        ax.annotate("", xy=b, xytext=a, arrowprops={"arrowstyle": "-|>", "color": colour, "lw": 1.4})
    offsets = [(0.2, 0.1), (0.15, -0.5), (-2.6, 0.7), (-2.9, 0.9), (0.2, -0.8), (-3.4, -0.1)]
    for (x, y), note, (dx, dy), colour in zip(points, notes, offsets, colours):
        ax.scatter(x, y, s=18, color=colour, zorder=3)
        ax.text(x + dx, y + dy, note, fontsize=7.5, color=colour)
    ax.text(6.0, -0.3, "each bounce multiplies the throughput by the surface's colour; the pixel is the mean of "
            "many such paths", ha="center", fontsize=8.5, color="#444444")
    ax.set_ylim(-0.6, 4.6)
    save(fig, path)
