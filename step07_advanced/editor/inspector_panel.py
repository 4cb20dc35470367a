"""The inspector: every component of the selected entity, its fields drawn from the component itself.

The widgets come from :func:`step07_advanced.editor.field_specs.field_specs` (numbers, flags, choices, names, colours,
vectors; a Mesh or Material component offers the scene's assets). Every change goes through the editor's undoable
actions; a drag is one undo step. Each component header has a remove button; "Add component" lists what the entity
does not have yet. A Material also shows the material's colour, textures (a texture dragged from the content
browser onto a slot replaces it) and the values of its shader's Material block, and opens the shader panel.
"""

from __future__ import annotations

import uuid
from typing import Any

import numpy as np
from imgui_bundle import imgui

from gandalf_core.components import MaterialComponent
from gandalf_core.ecs import Component, InfoComponent, LinkComponent

from .components import EditorPanelComponent
from .entities import display_name
from .field_specs import FieldSpec, addable_components, field_specs
from .panel_base import PanelSystem


def _edited(current: np.ndarray, widget: Any) -> np.ndarray:
    """The widget's values where the user changed them, the float64 values elsewhere (ImGui works in float32,
    so an untouched axis would otherwise come back rounded)."""
    widget = np.asarray(widget, dtype=np.float64)
    moved = current.astype(np.float32) != widget.astype(np.float32)
    return np.where(moved, widget, current)


class InspectorPanelSystem(PanelSystem):
    """Edits the selected entity's components, generated from their fields; add and remove components."""

    kind = "inspector"

    def draw(self, panel: EditorPanelComponent) -> None:
        editor = self.editor
        scene, entity = self.scene, editor.selected
        if entity is None or entity not in scene:
            imgui.text_disabled("nothing selected")
            return
        if imgui.small_button("+ Component"):
            imgui.open_popup("add component")
        self.remember("inspector/add")
        if imgui.begin_popup("add component"):
            for name, make in addable_components(scene, entity):
                if imgui.menu_item_simple(name):
                    self.act(lambda m=make: editor.add_component(entity, m()))
                self.remember(f"inspector/add/{name}")
            imgui.end_popup()
        imgui.same_line()
        imgui.text(display_name(scene, entity))
        imgui.same_line()
        imgui.text_disabled(str(entity)[:8])
        for component in scene.components_of(entity):
            if isinstance(component, LinkComponent):
                continue
            self._component(entity, component)

    def _component(self, entity: uuid.UUID, component: Component) -> None:
        ctype = type(component)
        name = ctype.__name__
        right = imgui.get_cursor_pos_x() + imgui.get_content_region_avail().x
        is_open = imgui.collapsing_header(f"{name.removesuffix('Component')}##{name}",
                                          imgui.TreeNodeFlags_.default_open | imgui.TreeNodeFlags_.allow_overlap)
        imgui.same_line(right - 18)
        if imgui.small_button(f"x##remove{name}"):
            self.act(self.editor.remove_component, entity, ctype)
            return
        self.remember(f"inspector/remove/{name}")
        if not is_open:
            return
        # --8<-- [start:fields]
        imgui.push_id(name)
        for spec in field_specs(component):
            self._field(entity, component, spec)
        if isinstance(component, MaterialComponent):
            self._material(component.material)
        imgui.pop_id()
        # --8<-- [end:fields]

    def _field(self, entity: uuid.UUID, component: Component, spec: FieldSpec) -> None:
        ctype = type(component)
        try:
            value = getattr(component, spec.name)
        except AttributeError:
            return
        kind, label = spec.kind, spec.name
        changed, new = False, value
        if kind == "vector":
            current = np.array(value, dtype=np.float64)
            speed = 0.5 if spec.name == "rotation" else 0.01
            width = imgui.calc_item_width()
            draw = {2: imgui.drag_float2, 3: imgui.drag_float3, 4: imgui.drag_float4}[spec.size]
            changed, widget = draw(label, current.tolist(), speed)
            self.remember(f"inspector/{spec.name}", width)
            new = _edited(current, widget) if changed else value
        # --8<-- [start:number]
        elif kind == "number":
            if value is None:
                imgui.text_disabled(f"{label}: auto")
                return
            speed = max(abs(float(value)) * 0.005, 0.001)
            changed, new = imgui.drag_float(label, float(value), speed)
            self.remember(f"inspector/{spec.name}")
            if changed:
                lo = spec.low if spec.low is not None else -np.inf
                hi = spec.high if spec.high is not None else np.inf
                new = float(np.clip(new, np.nextafter(lo, np.inf) if lo > -np.inf else lo,
                                    np.nextafter(hi, -np.inf) if hi < np.inf else hi))
        # --8<-- [end:number]
        elif kind == "int":
            changed, new = imgui.drag_int(label, int(value))
        elif kind == "flag":
            changed, new = imgui.checkbox(label, bool(value))
        elif kind == "text":
            changed, new = imgui.input_text(label, str(value))
            self.remember(f"inspector/{spec.name}")
        elif kind == "choice":
            choices = list(spec.choices)
            index = choices.index(value) if value in choices else 0
            changed, index = imgui.combo(label, index, choices)
            new = choices[index]
        elif kind == "color":
            rgba = [float(c) for c in value]
            changed, widget = (imgui.color_edit3 if spec.size == 3 else imgui.color_edit4)(label, rgba)
            self.remember(f"inspector/{spec.name}")
            new = np.asarray(widget, dtype=np.float64)
        elif kind == "resource":
            self._resource(entity, component, spec)
            return
        else:
            imgui.text_disabled(f"{label}: {value!r}")
            return
        # --8<-- [start:apply]
        if changed:
            merge = kind in ("vector", "number", "int", "color", "text")  # a drag or typing: one undo step
            if isinstance(component, InfoComponent) and spec.name == "name":
                self.act(self.editor.rename_entity, entity, new, merge=True)
            else:
                self.act(self.editor.set_field, entity, ctype, spec.name, new, merge=merge)
        # --8<-- [end:apply]

    def _resource(self, entity: uuid.UUID, component: Component, spec: FieldSpec) -> None:
        """A Mesh or Material component: pick another of the scene's assets (the component is replaced)."""
        kind = spec.choices[0]
        names = sorted(getattr(self.scene.assets, kind))
        current = getattr(component, spec.name)
        if current not in names:
            names.insert(0, current)
        changed, index = imgui.combo(spec.name, names.index(current), names)
        if changed and names[index] != current:
            self.act(self.editor.add_component, entity, type(component)(names[index]))

    def _material(self, name: str) -> None:
        editor = self.editor
        color = editor.material_color(name)
        if color is None:
            imgui.text_disabled("(not built yet)")
        else:
            changed, value = imgui.color_edit3("material color", list(color))
            self.remember("inspector/material_color")
            if changed:
                self.act(editor.set_material_color, name, value, merge=True)
        data = self.scene.assets.materials.get(name)
        for slot, texture in enumerate(data.textures if data is not None else ()):
            imgui.selectable(f"texture {slot}: {texture}##tex{slot}", False)
            self.remember(f"inspector/texture/{slot}")
            self.texture_drop_target(name, slot)
        if data is not None and color is not None:
            self._params(name, data)
        if imgui.small_button("edit shader"):
            editor.show_panel("shader")
        self.remember("inspector/edit_shader")

    def _params(self, name: str, data: Any) -> None:
        """The material's values of its shader's Material block (the colour above), by field: a field the shader
        gained shows up here at once."""
        block = self.editor.app.renderer.materials.get(name).shader.material_block
        for f in block.fields if block is not None else ():
            if f.name == "color" or f.name not in data.params:
                continue
            value = np.atleast_1d(np.asarray(data.params[f.name], dtype=np.float64))
            if value.size > 4:
                imgui.text_disabled(f"{f.name}: {value.size} values")
                continue
            draw = {1: imgui.drag_float, 2: imgui.drag_float2, 3: imgui.drag_float3, 4: imgui.drag_float4}
            args = float(value[0]) if value.size == 1 else value.tolist()
            changed, widget = draw[value.size](f.name, args, 0.01)
            self.remember(f"inspector/param/{f.name}")
            if changed:
                new = _edited(value, np.atleast_1d(widget))
                self.act(self.editor.set_material_param, name, f.name, float(new[0]) if value.size == 1 else new,
                         merge=True)

