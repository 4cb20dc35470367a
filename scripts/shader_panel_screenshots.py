"""Screenshots of the editor's shader panel, in both APIs, headless: ``docs/images/editor-shader-opengl.png`` and
``docs/images/editor-shader-webgpu.png``.

The scene of ``editor_screenshots.py``, with its sphere drawn by a small cel-shading shader written into a temporary
folder (``toon.vert``/``toon.frag`` or ``toon.wgsl``, and the include ``toon_bands.glsl``/``.wgsl`` they share). The
sphere is selected, the shader panel is open on the include, and a typo saved there (``stpes`` for ``steps``) shows
its error at its line, in the panel and over the viewport, while the last good program keeps drawing.

    python scripts/shader_panel_screenshots.py                 # both APIs, 1280x720, into docs/images
    python scripts/shader_panel_screenshots.py --out /tmp/shots --backends webgpu
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from editor_screenshots import build_scene, main  # noqa: E402 - the editor pictures' scene and options, written once

TOON_MATERIAL = [("color", "vec4"), ("steps", "float")]
FILES = {
    "opengl": {
        "toon.vert": """#version 330 core
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_normal;
void main() {
    v_normal = instance_normal(a_normal);
    gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0);
}
""",
        "toon.frag": """#version 330 core
#include "material.glsl"
#include "toon_bands.glsl"
in vec3 v_normal;
out vec4 f_color;
void main() {
    float light = max(dot(normalize(v_normal), normalize(vec3(0.4, 0.8, 0.5))), 0.0);
    f_color = vec4(material.color.rgb * (0.2 + 0.8 * bands(light, material.steps)), 1.0);
}
""",
        "toon_bands.glsl": """// Cel shading: the light's strength in a few flat steps.
float bands(float light, float steps) {
    return floor(light * steps + 0.5) / steps;
}
""",
    },
    "webgpu": {
        "toon.wgsl": """#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"
#include "toon_bands.wgsl"
struct VOut { @builtin(position) position: vec4<f32>, @location(0) normal: vec3<f32> };
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>, inst: Instance) -> VOut {
    var out: VOut;
    out.position = frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
    out.normal = instance_normal(inst, normal);
    return out;
}
@fragment fn fs_main(in: VOut) -> @location(0) vec4<f32> {
    let light = max(dot(normalize(in.normal), normalize(vec3<f32>(0.4, 0.8, 0.5))), 0.0);
    return vec4<f32>(material.color.rgb * (0.2 + 0.8 * bands(light, material.steps)), 1.0);
}
""",
        "toon_bands.wgsl": """// Cel shading: the light's strength in a few flat steps.
fn bands(light: f32, steps: f32) -> f32 {
    return floor(light * steps + 0.5) / steps;
}
""",
    },
}


def shoot(backend: str, width: int, height: int, out: Path) -> Path:
    from gandalf_core import Application, InfoComponent
    from gandalf_core.components import MaterialComponent
    from gandalf_core.resources import MaterialData
    from step07_advanced.editor import enable_editor

    with tempfile.TemporaryDirectory() as folder, Application(backend, width, height, headless=True,
                                                              fixed_dt=1 / 60) as app:
        paths = {name: Path(folder) / name for name in FILES[backend]}
        for name, text in FILES[backend].items():
            paths[name].write_text(text)
        stages = [path for path in paths.values() if "bands" not in path.name]
        app.renderer.shaders.build("toon", *stages, material=TOON_MATERIAL)
        scene = build_scene()
        scene.assets.material("toon", MaterialData("toon", color=(0.25, 0.6, 1.0), params={"steps": 3.0}))
        sphere = next(e for e, (info,) in scene.view(InfoComponent) if info.name == "sphere")
        scene.add_component(sphere, MaterialComponent("toon"))
        app.add_scene(scene)
        editor = enable_editor(app)
        editor.selected = sphere
        app.run(frames=2)
        editor.show_panel("shader")
        app.run(frames=2)
        panel = editor.panel_system("shader")
        include = next(path for path in paths.values() if "bands" in path.name)
        panel.active = include.resolve()
        panel._jump = (include.resolve(), 3)  # bring the include's tab to the front, at the line of the typo
        text = include.read_text().replace("/ steps;", "/ stpes;")
        panel.text_editor(include).set_text(text)
        panel.save(include.resolve())
        app.run(frames=4)
        path = out / f"editor-shader-{backend}.png"
        app.save_png(path)
        editor.disable()
    return path


if __name__ == "__main__":
    raise SystemExit(main(shoot=shoot, doc=__doc__))
