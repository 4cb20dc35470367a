"""Screenshots of the editor's frame inspector, in both APIs, headless: ``docs/images/editor-frame-opengl.png`` and
``docs/images/editor-frame-webgpu.png``.

The scene is the editor page's (``editor_screenshots.build_scene``) with a shadow-casting sun; the frame inspector
shows a captured frame with a draw selected (its state and decoded Material block), the result of a pick on the
viewport (the sphere), and the texture viewer showing the shadow map.

    python scripts/frame_inspector_screenshots.py            # both APIs, 1280x720, into docs/images
    python scripts/frame_inspector_screenshots.py --out /tmp/shots --backends webgpu
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "scripts"))


def shoot(backend: str, width: int, height: int, out: Path) -> Path:
    import numpy as np
    from editor_screenshots import build_scene

    from gandalf_core import Application, InfoComponent
    from gandalf_core.components import LightComponent
    from step07_advanced.editor import enable_editor

    os.environ["GANDALF_GPU_TIMING"] = "1"  # WebGPU's timestamps (OpenGL's need no request)
    with Application(backend, width, height, headless=True, fixed_dt=1 / 60) as app:
        scene = build_scene()
        for _entity, (info, light) in scene.view(InfoComponent, LightComponent):
            if info.name == "sun":
                light.cast_shadows, light.shadow_extent = True, 8.0
        app.add_scene(scene)
        editor = enable_editor(app)
        editor.show_panel("frame")
        for kind in ("hierarchy", "content", "inspector", "systems", "stats", "file"):
            editor.show_panel(kind, False)
        top = 20.0
        editor.panel("viewport").position, editor.panel("viewport").size = (0.0, top), (0.55 * width, 0.62 * height)
        editor.panel("console").position = (0.0, top + 0.62 * height)
        editor.panel("console").size = (0.55 * width, height - top - 0.62 * height)
        editor.panel("frame").position, editor.panel("frame").size = (0.55 * width, top), (0.45 * width, height - top)
        app.run(frames=3)
        system = editor.panel_system("frame")
        system.request_capture()
        app.run(frames=3)
        sphere = next(e for e, (info,) in app.scene.view(InfoComponent) if info.name == "sphere")
        system.selected_draw = next(d.index for d in system.capture.draws
                                    if d.pass_name == "opaque" and sphere in d.entities)
        target = editor.viewport.target
        with target.drawing():  # the sphere's middle in the viewport's picture
            from gandalf_core.render import RenderSystem

            render = next(s for s in app.scene.systems if isinstance(s, RenderSystem))
            view, projection, _eye, _rz = render.camera()
            clip = projection @ view @ np.array([0.8, 0.6, 1.6, 1.0])
            x, y = (clip[0] / clip[3] + 1) / 2 * target.size[0], (1 - clip[1] / clip[3]) / 2 * target.size[1]
        system.request_pick(int(x), int(y))
        system.view_texture("shadow map")
        app.run(frames=4)
        path = out / f"editor-frame-{backend}.png"
        app.save_png(path)
        if backend == "opengl":  # the texture viewer on its own: a mip level of a texture, with a texel read out
            system.selected_draw = None
            system.view_texture("tiles", 0, 3)
            app.run(frames=3)
            x0, y0, x1, y1 = editor.item_rects["frame/texture/image"]
            app.input.move_mouse(x0 + 0.3 * (x1 - x0), y0 + 0.6 * (y1 - y0))
            app.run(frames=3)
            from PIL import Image

            (x, y), (w, h) = editor.panel("frame").position, editor.panel("frame").size
            app.save_png(out / "editor-frame-texture.png")
            Image.open(out / "editor-frame-texture.png").crop((int(x), int(y), int(x + w), int(y + h))).save(
                out / "editor-frame-texture.png")
        editor.disable()
    return path


if __name__ == "__main__":
    from editor_screenshots import main  # the editor pictures' options, written once

    raise SystemExit(main(shoot=shoot, doc=__doc__))
