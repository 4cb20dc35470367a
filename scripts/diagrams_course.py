"""The course's first diagrams: the pipeline (step 02), texture sampling (step 03), the coordinate spaces (step 04)
and one frame of the engine (architecture). Drawn by scripts/make_diagrams.py.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from diagram_kit import DATA, EDGE, FIXED, MISSING, PROGRAMMABLE, SYSTEM, arrow, box, canvas, save


def pipeline(path: Path) -> None:
    """The pipeline stages per API, WebGPU's missing ones drawn dashed."""
    stages = [
        ("vertex\nfetch", FIXED, True), ("vertex\nshader", PROGRAMMABLE, True),
        ("tessellation\ncontrol", PROGRAMMABLE, False), ("tessellator", FIXED, False),
        ("tessellation\nevaluation", PROGRAMMABLE, False), ("geometry\nshader", PROGRAMMABLE, False),
        ("rasteriser", FIXED, True), ("fragment\nshader", PROGRAMMABLE, True),
        ("depth test,\nblending", FIXED, True),
    ]
    w, h, gap = 1.3, 0.9, 0.25
    fig, ax = canvas(12.5, 5.0, len(stages) * (w + gap) + 0.6, 4.6)
    ax.set_ylim(-0.5, 4.6)
    rows = (("OpenGL 4.x", 3.2, True), ("WebGPU", 1.2, False))
    for label, y, has_all in rows:
        ax.text(0.1, y + h + 0.25, label, fontsize=11, weight="bold", va="bottom")
        for i, (name, color, in_webgpu) in enumerate(stages):
            x = 0.3 + i * (w + gap)
            present = has_all or in_webgpu
            box(ax, x, y, w, h, name if present else f"{name}\n(none)", color if present else MISSING,
                 dashed=not present, size=8, text_color="black" if present else "#888888")
            if i < len(stages) - 1:
                arrow(ax, x + w, y + h / 2, x + w + gap, y + h / 2, color=EDGE if has_all else "#555555")
    # WebGPU's route for the missing stages.
    x_tess = 0.3 + 2 * (w + gap)
    x_geom = 0.3 + 5 * (w + gap) + w
    ax.annotate("", xy=(x_tess, 0.55), xytext=(x_geom, 0.55),
                arrowprops={"arrowstyle": "<->", "color": "#b45f06", "lw": 1.0})
    ax.text((x_tess + x_geom) / 2, 0.1, "WebGPU's route: a compute pass writes the vertices into a storage buffer; the "
            "vertex shader reads them by index (vertex pulling)", ha="center", fontsize=8.5, color="#b45f06")
    ax.text((x_tess + x_geom) / 2, -0.3, "Compute shaders run beside the pipeline in both APIs (OpenGL 4.3 compute "
            "programs, WebGPU compute passes).", ha="center", fontsize=8.5, color="#444444")
    from matplotlib.patches import Patch

    ax.legend(handles=[Patch(facecolor=PROGRAMMABLE, edgecolor=EDGE, label="programmable (your shader)"),
                       Patch(facecolor=FIXED, edgecolor=EDGE, label="fixed function (settings only)"),
                       Patch(facecolor=MISSING, edgecolor="#999999", linestyle="--", label="not in WebGPU")],
              loc="upper right", fontsize=8, frameon=False, ncol=3, bbox_to_anchor=(1.0, 1.02))
    save(fig, path)


def ecs_frame(path: Path) -> None:
    """One frame: Application.step -> the scene's systems in order -> the renderer -> the picture."""
    fig, ax = canvas(12.0, 5.6, 12.0, 5.6)
    # The scene's data on the left.
    box(ax, 0.2, 0.5, 2.6, 4.2, "", DATA)
    ax.text(1.5, 4.45, "Scene (data)", ha="center", fontsize=10, weight="bold")
    for i, text in enumerate(("entities: ids", "TransformComponent", "MeshComponent\nMaterialComponent",
                              "CameraComponent", "LightComponent", "your components", "assets: meshes,\n"
                              "textures, materials")):
        ax.text(1.5, 3.95 - i * 0.5, text, ha="center", va="center", fontsize=8)
    # Application.step on top.
    box(ax, 3.4, 4.7, 8.3, 0.7, "Application.step(): pending scene switch · input · resize · clock.tick() -> ts",
         FIXED, size=8)
    # Systems in order.
    systems = [("your systems\n(on_update_entity)", "move, spin, animate:\nwrite Transform"),
               ("TransformSystem", "local TRS ->\nworld matrices\n(parents first)"),
               ("LightSystem", "lights ->\nthe lights block"),
               ("RenderSystem", "camera, batches,\ninstance rows,\nframe uniforms")]
    for i, (name, job) in enumerate(systems):
        x = 3.4 + i * 2.15
        box(ax, x, 3.0, 1.85, 0.95, name, SYSTEM, size=7.0, weight="bold")
        ax.text(x + 0.92, 2.85, job, ha="center", va="top", fontsize=8.5)
        if i:
            arrow(ax, x - 0.3, 3.47, x, 3.47)
    arrow(ax, 4.32, 4.7, 4.32, 3.95)
    ax.text(4.45, 4.3, "scene.update(ts)", ha="left", va="center", fontsize=8)
    ax.text(8.6, 4.3, "the systems run in order, RenderSystem last", ha="center", va="center", fontsize=8,
            color="#444444")
    # Components read and written.
    arrow(ax, 2.8, 3.47, 3.4, 3.47, color="#7f6000", style="<|-|>")
    ax.text(3.1, 3.75, "read /\nwrite", ha="center", fontsize=7, color="#7f6000")
    # Renderer.
    x_r = 3.4 + 3 * 2.15
    arrow(ax, x_r + 0.92, 1.9, x_r + 0.92, 1.35)
    ax.text(x_r + 1.0, 1.6, "FrameData", ha="left", va="center", fontsize=8)
    box(ax, 6.0, 0.5, 5.7, 0.85, "Renderer: OpenGLRenderer (moderngl) or WebGPURenderer (wgpu)\nclear · upload "
         "once · instanced draws · sky · blended · overlays", PROGRAMMABLE, size=6.8)
    box(ax, 3.4, 0.5, 2.2, 0.85, "offscreen sRGB target\n-> window / capture()", FIXED, size=6.5)
    arrow(ax, 6.0, 0.93, 5.6, 0.93)
    save(fig, path)


def spaces(path: Path) -> None:
    """The coordinate spaces with their matrices, and window depth against distance in both depth ranges."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(12.0, 4.4))
    ax = fig.add_axes((0.0, 0.55, 1.0, 0.45))
    ax.set_xlim(0, 12.0)
    ax.set_ylim(0, 1.6)
    ax.axis("off")
    chain = [("object\n(model) space", "mesh positions"), ("world space", "the scene"),
             ("camera (view)\nspace", "camera at 0,\nlooking down -z"), ("clip space", "x, y, z, w"),
             ("normalised device\ncoordinates", "x, y in [-1, 1]\nz: see right"), ("window", "pixels and depth")]
    steps = ["M (model)\nTransform.world", "V (view)\ninverse camera world", "P (projection)\nCameraComponent",
             "divide by w\n(the GPU)", "viewport\n(the GPU)"]
    for i, (name, note) in enumerate(chain):
        x = 0.15 + i * 2.0
        box(ax, x, 0.6, 1.5, 0.75, name, SYSTEM if i < 3 else PROGRAMMABLE if i < 5 else FIXED, size=8.5)
        ax.text(x + 0.75, 0.5, note, ha="center", va="top", fontsize=7.5)
        if i < len(steps):
            arrow(ax, x + 1.5, 0.97, x + 2.0, 0.97)
            ax.text(x + 1.75, 1.38, steps[i], ha="center", va="bottom", fontsize=7, color="#444444")
    # Depth against distance for one camera, near 0.5, far 20.
    near, far = 0.5, 20.0
    d = np.linspace(near, far, 400)
    z_gl = ((far + near) / (near - far) * (-d) + 2 * far * near / (near - far)) / d
    z_wgpu = (far / (near - far) * (-d) + far * near / (near - far)) / d
    ax1 = fig.add_axes((0.07, 0.1, 0.38, 0.36))
    ax1.plot(d, z_gl, color="#1155cc", label="OpenGL: $z_{ndc} \\in [-1, 1]$")
    ax1.plot(d, z_wgpu, color="#cc4125", label="WebGPU: $z_{ndc} \\in [0, 1]$")
    ax1.axhline(0, color="#999999", lw=0.6)
    ax1.set_xlabel("distance from the camera (near = 0.5, far = 20)", fontsize=8)
    ax1.set_ylabel("$z_{ndc}$", fontsize=9)
    ax1.tick_params(labelsize=7)
    ax1.legend(fontsize=7.5, frameon=False, loc="lower right")
    ax1.set_title("the same camera, the two depth ranges", fontsize=9)
    ax2 = fig.add_axes((0.56, 0.1, 0.4, 0.36))
    ax2.plot(d, (z_gl + 1) / 2, color="#1155cc", label="OpenGL window depth (z + 1) / 2")
    ax2.plot(d, 1 - z_wgpu, color="#cc4125", ls="--", label="WebGPU reverse-Z: 1 - z (near -> 1)")
    ax2.set_xlabel("distance from the camera", fontsize=8)
    ax2.set_ylabel("stored depth", fontsize=9)
    ax2.tick_params(labelsize=7)
    ax2.legend(fontsize=7.5, frameon=False, loc="center right")
    ax2.set_title("stored depth: standard (most of [0, 1] near the camera) and reverse-Z", fontsize=9)
    save(fig, path)


def _bilinear(texture: np.ndarray, size: int) -> np.ndarray:
    """Sample ``texture`` (h, w) at the centres of a size x size grid with linear filtering (clamp)."""
    h, w = texture.shape
    uv = (np.arange(size) + 0.5) / size
    x = np.clip(uv * w - 0.5, 0, w - 1)
    y = np.clip(uv * h - 0.5, 0, h - 1)
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    x1, y1 = np.minimum(x0 + 1, w - 1), np.minimum(y0 + 1, h - 1)
    fx, fy = (x - x0)[None, :], (y - y0)[:, None]
    top = texture[np.ix_(y0, x0)] * (1 - fx) + texture[np.ix_(y0, x1)] * fx
    bottom = texture[np.ix_(y1, x0)] * (1 - fx) + texture[np.ix_(y1, x1)] * fx
    return top * (1 - fy) + bottom * fy


def _nearest(texture: np.ndarray, size: int) -> np.ndarray:
    h, w = texture.shape
    uv = (np.arange(size) + 0.5) / size
    return texture[np.ix_((uv * h).astype(int), (uv * w).astype(int))]


def sampling(path: Path) -> None:
    """Nearest against linear magnification; a minified checkerboard without and with a mip level."""
    import matplotlib.pyplot as plt

    small = np.array([[0.1, 0.9, 0.3, 0.7], [0.9, 0.2, 0.8, 0.4], [0.5, 0.8, 0.1, 0.9], [0.7, 0.3, 0.9, 0.2]])
    n, squares, shown = 256, 53, 24  # a fine checkerboard seen through 24 x 24 pixels: ~10 texels per pixel
    cells = np.arange(n) * squares // n
    checker = ((cells[:, None] + cells[None, :]) % 2).astype(float)
    level = checker
    while level.shape[0] > shown * 2:  # the mip chain: 2 x 2 averages down to the level the pixel size matches
        level = level.reshape(level.shape[0] // 2, 2, level.shape[1] // 2, 2).mean(axis=(1, 3))
    panels = [
        (small, "the texture: 4 x 4 texels"),
        (_nearest(small, 96), "magnified, nearest:\nthe closest texel"),
        (_bilinear(small, 96), "magnified, linear:\nfour texels blended"),
        (checker, f"a {squares}-square checkerboard,\n{n} x {n} texels"),
        (_nearest(checker, shown), f"minified to {shown} x {shown}, no mipmaps:\none texel per pixel (aliasing)"),
        (_bilinear(level, shown), f"with mipmaps: a {level.shape[0]} x {level.shape[0]}\nlevel of 2 x 2 averages "
         "(grey)"),
    ]
    fig, axes = plt.subplots(1, len(panels), figsize=(12.0, 2.9))
    for ax, (image, title) in zip(axes, panels):
        ax.imshow(image, cmap="gray", vmin=0.0, vmax=1.0, interpolation="nearest")
        ax.set_title(title, fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.subplots_adjust(left=0.01, right=0.99, top=0.8, bottom=0.02, wspace=0.12)
    save(fig, path)
