"""Errors of the render layer; each names the shader file and line, or the resource and what referred to it."""

from __future__ import annotations


class ShaderCompileError(ValueError):
    """A GLSL or WGSL shader failed to compile or link. The message starts with ``file:line:``."""


class MissingResourceError(KeyError):
    """A mesh, material, texture or shader name that no library or asset table knows."""

    def __str__(self) -> str:
        return str(self.args[0])


def missing(kind: str, name: str, known: list[str] | tuple[str, ...], referrer: str) -> MissingResourceError:
    """A MissingResourceError listing what is known, for ``referrer`` (e.g. "material 'M_Bricks'")."""
    have = ", ".join(sorted(known)) or "none"
    return MissingResourceError(f"{referrer} names {kind} '{name}', which is not registered (known: {have})")
