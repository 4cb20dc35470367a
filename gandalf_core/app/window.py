"""A glfw window that feeds :class:`~gandalf_core.app.input.Input`; used only when a display exists."""

from __future__ import annotations

import atexit
import os

from .input import Input


def display_available() -> bool:
    """True when a window can be opened (an X11 or Wayland display is set)."""
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


#: OpenGL core versions a window asks for, newest first (the renderer needs 3.3; step 07 needs 4.x).
GL_VERSIONS = ((4, 6), (4, 5), (4, 3), (4, 1), (3, 3))


class Window:
    """A window with the newest GL core context the driver gives, 4.6 down to 3.3 (``api='opengl'``: some drivers
    give exactly the version asked for, and tessellation, compute and clip control need 4.x), or none
    (``api='webgpu'``: wgpu makes a surface)."""

    def __init__(self, width: int, height: int, title: str, api: str, input: Input) -> None:
        import glfw

        self._glfw = glfw
        if not _glfw_ready(glfw):
            raise RuntimeError("glfw could not initialise: is a display available?")
        self.handle = None
        for major, minor in (GL_VERSIONS if api == "opengl" else [(0, 0)]):
            glfw.default_window_hints()  # hints persist between windows: start from a clean slate
            if api == "opengl":
                glfw.window_hint(glfw.CONTEXT_VERSION_MAJOR, major)
                glfw.window_hint(glfw.CONTEXT_VERSION_MINOR, minor)
                glfw.window_hint(glfw.OPENGL_PROFILE, glfw.OPENGL_CORE_PROFILE)
                glfw.window_hint(glfw.OPENGL_FORWARD_COMPAT, True)
            else:
                glfw.window_hint(glfw.CLIENT_API, glfw.NO_API)
            reporting = glfw.ERROR_REPORTING
            glfw.ERROR_REPORTING = "ignore"  # a version the driver refuses is expected: the next one is tried
            try:
                self.handle = glfw.create_window(width, height, title, None, None)
            finally:
                glfw.ERROR_REPORTING = reporting
            if self.handle:
                break
        if not self.handle:
            raise RuntimeError(f"glfw could not open a {width}x{height} {api} window")
        if api == "opengl":
            glfw.make_context_current(self.handle)
            glfw.swap_interval(0)
        self.input = input
        glfw.set_key_callback(self.handle, self._on_key)
        glfw.set_cursor_pos_callback(self.handle, lambda _w, x, y: input.move_mouse(x, y))
        glfw.set_mouse_button_callback(self.handle, self._on_button)
        glfw.set_scroll_callback(self.handle, lambda _w, dx, dy: input.scroll(dx, dy))
        glfw.set_framebuffer_size_callback(self.handle, lambda _w, w, h: input.resize(w, h))

    def _on_key(self, _window: object, key: int, _scancode: int, action: int, _mods: int) -> None:
        glfw = self._glfw
        name = glfw.get_key_name(key, 0) or _special_key_name(glfw, key)
        if name:
            self.input.key(name, {glfw.PRESS: "press", glfw.RELEASE: "release"}.get(action, "repeat"))

    def _on_button(self, _window: object, button: int, action: int, _mods: int) -> None:
        self.input.button(button, "press" if action == self._glfw.PRESS else "release")

    @property
    def framebuffer_size(self) -> tuple[int, int]:
        return self._glfw.get_framebuffer_size(self.handle)

    def poll(self) -> None:
        self._glfw.poll_events()

    @property
    def should_close(self) -> bool:
        return bool(self._glfw.window_should_close(self.handle))

    def request_close(self) -> None:
        self._glfw.set_window_should_close(self.handle, True)

    def swap_buffers(self) -> None:
        self._glfw.swap_buffers(self.handle)

    def close(self) -> None:
        # glfw itself stays initialised (terminated at exit): re-initialising it for the next window
        # races with the X server resetting after its last client left.
        self._glfw.destroy_window(self.handle)


_initialised = False


def _glfw_ready(glfw: object) -> bool:
    global _initialised
    if not _initialised and glfw.init():
        atexit.register(glfw.terminate)
        _initialised = True
    return _initialised


_KEY_NAMES: dict[int, str] = {}


def _special_key_name(glfw: object, key: int) -> str | None:
    # glfw.get_key_name only names printable keys; the rest come from the KEY_* constants (KEY_LAST and
    # KEY_UNKNOWN are aliases, not keys).
    if not _KEY_NAMES:
        for attr in sorted(dir(glfw), reverse=True):
            if attr.startswith("KEY_") and attr not in ("KEY_LAST", "KEY_UNKNOWN"):
                _KEY_NAMES[getattr(glfw, attr)] = attr[4:]
    return _KEY_NAMES.get(key)
