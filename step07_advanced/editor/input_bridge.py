"""Feeds ImGui from the app's :class:`~gandalf_core.app.input.Input`: this frame's mouse, wheel, key and text events.

Keys arrive by glfw's names ("A", "SPACE", "LEFT_SHIFT", "." ...). Text is derived from printable key
presses (letters follow Shift; other characters are taken as named), since Input carries no
character events.
"""

from __future__ import annotations

from typing import Any

from imgui_bundle import imgui

from gandalf_core.app.input import Input, KeyEvent, MouseButtonEvent, MouseMoveEvent, ScrollEvent

_K = imgui.Key
_NAMED = {
    "SPACE": _K.space, "ENTER": _K.enter, "KP_ENTER": _K.keypad_enter, "TAB": _K.tab,
    "BACKSPACE": _K.backspace, "DELETE": _K.delete, "INSERT": _K.insert, "ESCAPE": _K.escape,
    "LEFT": _K.left_arrow, "RIGHT": _K.right_arrow, "UP": _K.up_arrow, "DOWN": _K.down_arrow,
    "HOME": _K.home, "END": _K.end, "PAGE_UP": _K.page_up, "PAGE_DOWN": _K.page_down,
    "LEFT_SHIFT": _K.left_shift, "RIGHT_SHIFT": _K.right_shift, "LEFT_CONTROL": _K.left_ctrl,
    "RIGHT_CONTROL": _K.right_ctrl, "LEFT_ALT": _K.left_alt, "RIGHT_ALT": _K.right_alt,
    "LEFT_SUPER": _K.left_super, "RIGHT_SUPER": _K.right_super,
    ".": _K.period, ",": _K.comma, "-": _K.minus, "=": _K.equal, "/": _K.slash, "\\": _K.backslash,
    ";": _K.semicolon, "'": _K.apostrophe, "[": _K.left_bracket, "]": _K.right_bracket, "`": _K.grave_accent,
    **{f"F{i}": getattr(_K, f"f{i}") for i in range(1, 13)},
    **{chr(c): getattr(_K, chr(c).lower()) for c in range(ord("A"), ord("Z") + 1)},
    **{str(d): getattr(_K, f"_{d}") for d in range(10)},
}
_MODIFIERS = {
    "LEFT_SHIFT": _K.mod_shift, "RIGHT_SHIFT": _K.mod_shift, "LEFT_CONTROL": _K.mod_ctrl,
    "RIGHT_CONTROL": _K.mod_ctrl, "LEFT_ALT": _K.mod_alt, "RIGHT_ALT": _K.mod_alt,
    "LEFT_SUPER": _K.mod_super, "RIGHT_SUPER": _K.mod_super,
}


def key_text(key: str, shift: bool) -> str:
    """The text a printable key types ("" for other keys)."""
    if key == "SPACE":
        return " "
    if len(key) != 1:
        return ""
    return key if (shift or not key.isalpha()) else key.lower()


def feed(io: Any, source: Input) -> None:
    """Queue this frame's input events on ImGui's ``io`` (ImGui spreads a press and release over frames)."""
    shift = source.is_down("LEFT_SHIFT") or source.is_down("RIGHT_SHIFT")
    for event in source.events:
        if isinstance(event, MouseMoveEvent):
            io.add_mouse_pos_event(event.x, event.y)
        elif isinstance(event, MouseButtonEvent):
            if 0 <= event.button < 5:
                io.add_mouse_button_event(event.button, event.action == "press")
        elif isinstance(event, ScrollEvent):
            io.add_mouse_wheel_event(event.dx, event.dy)
        elif isinstance(event, KeyEvent):
            down = event.action != "release"
            if event.key in _MODIFIERS:
                io.add_key_event(_MODIFIERS[event.key], down)
            named = _NAMED.get(event.key)
            if named is not None:
                io.add_key_event(named, down)
            if down:
                text = key_text(event.key, shift)
                if text:
                    io.add_input_characters_utf8(text)
