"""Screenshots of the editor with every panel, in both APIs, headless: ``docs/images/editor-opengl.png`` and
``docs/images/editor-webgpu.png`` (and crops of the viewport and of the console, ``editor-viewport.png`` and
``editor-console.png``, from the OpenGL run).

The scene: a textured, lit floor and cubes (two of them under a parent), a sphere, an unnamed light and a camera;
a cube is selected (the inspector shows its components, the viewport its translate gizmo), a warning and a
shader compile error (with its file:line) are in the console, one edit is in the undo history.

    python scripts/editor_screenshots.py                 # both APIs, 1280x720, into docs/images
    python scripts/editor_screenshots.py --out /tmp/shots --size 1600x900 --backends opengl
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def build_scene():  # noqa: ANN201 - a Scene
    from gandalf_core import InfoComponent, LinkComponent, Scene, TransformComponent
    from gandalf_core.components import (
        CameraComponent,
        ClearColorComponent,
        LightComponent,
        MaterialComponent,
        MeshComponent,
    )
    from gandalf_core.math import look_at_rotation
    from gandalf_core.resources import MaterialData, checkerboard, cube, plane, uv_sphere

    scene = Scene("editor demo")
    assets = scene.assets
    assets.mesh("cube", cube())
    assets.mesh("floor", plane(8.0))
    assets.mesh("sphere", uv_sphere(0.6))
    assets.texture("checker", checkerboard(64, 8, (0.9, 0.9, 0.9), (0.35, 0.35, 0.4)))
    assets.texture("tiles", checkerboard(64, 4, (0.8, 0.45, 0.2), (0.95, 0.8, 0.55)))
    assets.material("bricks", MaterialData("gandalf.blinn_phong", ["tiles"], color=(1.0, 1.0, 1.0)))
    assets.material("floor", MaterialData("gandalf.blinn_phong", ["checker"], color=(0.8, 0.8, 0.8)))
    assets.material("plastic", MaterialData("gandalf.blinn_phong", color=(0.2, 0.5, 1.0)))
    scene.create_entity(InfoComponent("background"), ClearColorComponent((0.18, 0.22, 0.3)))
    scene.create_entity(InfoComponent("floor"), TransformComponent(), MeshComponent("floor"),
                        MaterialComponent("floor"))
    group = scene.create_entity(InfoComponent("cubes"), TransformComponent((0.0, 0.5, 0.0)))
    for i, x in enumerate((-1.6, 0.0, 1.6)):
        scene.create_entity(InfoComponent(f"cube{i}"), LinkComponent(group),
                            TransformComponent((x, 0.0, 0.0), (0.0, 25.0 * i, 0.0), 0.9),
                            MeshComponent("cube"), MaterialComponent("bricks"))
    scene.create_entity(InfoComponent("sphere"), TransformComponent((0.8, 0.6, 1.6)), MeshComponent("sphere"),
                        MaterialComponent("plastic"))
    scene.create_entity(TransformComponent((3.0, 4.0, 3.0)), LightComponent("point", intensity=3.0))
    scene.create_entity(InfoComponent("sun"), TransformComponent(rotation=(-50.0, 30.0, 0.0)),
                        LightComponent("directional", intensity=0.6))
    eye = (3.5, 3.2, 6.0)
    scene.create_entity(InfoComponent("camera"), TransformComponent(eye, quaternion=look_at_rotation(eye, (0, 0.5, 0))),
                        CameraComponent(45.0, 0.1, 100.0))
    return scene


def shoot(backend: str, width: int, height: int, out: Path) -> Path:
    from gandalf_core import Application, InfoComponent
    from step07_advanced.editor import enable_editor

    with Application(backend, width, height, headless=True, fixed_dt=1 / 60) as app:
        app.add_scene(build_scene())
        editor = enable_editor(app)
        app.run(frames=2)
        cube = next(e for e, (info,) in app.scene.view(InfoComponent) if info.name == "cube1")
        editor.selected = cube
        editor.set_material_color("plastic", (0.25, 0.6, 1.0))
        with warnings.catch_warnings():
            warnings.simplefilter("always")
            warnings.warn("texture 'tiles' has no mipmaps: minified it will shimmer", UserWarning, stacklevel=1)
        with tempfile.TemporaryDirectory() as folder:
            if backend == "opengl":
                bad = Path(folder) / "glow.frag"
                bad.write_text("#version 330\nout vec4 color;\nvoid main() {\n    color = vec4(glow, 1.0);\n}\n")
                vert = Path(folder) / "glow.vert"
                vert.write_text("#version 330\nin vec3 position;\nvoid main() { gl_Position = vec4(position, 1.0); }\n")
                editor.build_shader("glow", vert, bad)
            else:
                bad = Path(folder) / "glow.wgsl"
                bad.write_text("@fragment\nfn fs_main() -> @location(0) vec4<f32> {\n"
                               "    return vec4<f32>(glow, 1.0);\n}\n")
                editor.build_shader("glow", bad)
        editor.status = ""
        app.run(frames=4)
        path = out / f"editor-{backend}.png"
        app.save_png(path)
        if backend == "opengl":
            from PIL import Image

            image = Image.open(path)
            for kind in ("viewport", "console"):
                panel = editor.panel(kind)
                (x, y), (w, h) = panel.position, panel.size
                image.crop((int(x), int(y), int(x + w), int(y + h))).save(out / f"editor-{kind}.png")
        editor.disable()
    return path


def main(argv: list[str] | None = None, shoot=shoot, doc: str = __doc__) -> int:  # noqa: ANN001 - shoot(...)
    """Parse the options of ``doc``'s script and call ``shoot(backend, width, height, out)`` for each backend (the
    shader panel's script shares it)."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=doc)
    parser.add_argument("--out", type=Path, default=ROOT / "docs" / "images", help="folder for the PNG files")
    parser.add_argument("--size", default="1280x720", help="WIDTHxHEIGHT of the editor frame")
    parser.add_argument("--backends", default="opengl,webgpu")
    args = parser.parse_args(argv)
    width, height = (int(v) for v in args.size.lower().split("x"))
    args.out.mkdir(parents=True, exist_ok=True)
    for backend in args.backends.split(","):
        print(shoot(backend.strip(), width, height, args.out))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
