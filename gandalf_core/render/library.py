"""The base of every resource library (textures, shaders, meshes, materials) in both backends.

A library builds a GPU object once per name and hands out the cached one afterwards, as in the paper:
``lib.build(name, data)``. It belongs to one renderer, so a fresh renderer starts with empty libraries.
:meth:`ResourceLib.resolve` is how the renderers turn the names a scene's components use into GPU
objects on first use, from the scene's backend-neutral assets.

Objects built from a scene's assets follow them: when the data under a name changes (a texture replaced while
running), the next use builds it anew; when no scene has the name any more (:meth:`ResourceLib.collect`), its GPU
object is released. What the app's own code builds with :meth:`build` (shaders, storage buffers) stays until the
renderer goes. Whatever refers to a released object (a vertex array, a material's bind group) is dropped with it
through :attr:`ResourceLib.on_forget`.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterable, Mapping
from typing import Any, Generic, TypeVar

from .errors import MissingResourceError, missing

T = TypeVar("T")


class ResourceLib(Generic[T]):
    """Named GPU objects of one kind, built once; subclasses implement :meth:`_create` and :meth:`_release`."""

    kind = "resource"

    def __init__(self, stats: Counter[str]) -> None:
        self.stats = stats
        self._items: dict[str, T] = {}
        self._data: dict[str, Any] = {}
        self._from_assets: set[str] = set()  # names built by resolve() from a scene's assets
        #: Called with a name just before its object is released: dependents drop what refers to it.
        self.on_forget: list[Callable[[str], None]] = []

    def build(self, name: str, data: Any) -> T:
        """The GPU object for ``name``, created from ``data`` the first time and cached after that."""
        if name not in self._items:
            self._items[name] = self._create(name, data)
            self._data[name] = data
        return self._items[name]

    def resolve(self, name: str, table: Mapping[str, Any], referrer: str) -> T:
        """The object for ``name``, built from ``table[name]`` (a scene's assets) on first use.

        Two scenes that use one name for different data would silently share the first one's GPU
        object; that is an error here, naming the resource.
        """
        data = table.get(name)
        if name in self._items:
            if data is None or self._data.get(name) is data:
                return self._items[name]
            if name not in self._from_assets:
                raise ValueError(
                    f"{self.kind} '{name}' was built by the app's own code (build()), and a scene's assets hold "
                    f"other data under that name: give one of them another name"
                )
            self.forget(name)  # the scene's data under this name changed: build it anew
        if data is None:
            raise missing(self.kind, name, list(table), referrer)
        item = self.build(name, data)
        self._from_assets.add(name)
        return item

    def forget(self, name: str) -> None:
        """Release ``name``'s object (and, through :attr:`on_forget`, what refers to it); nothing if not built."""
        if name not in self._items:
            return
        for callback in self.on_forget:
            callback(name)
        item = self._items.pop(name)
        self._data.pop(name, None)
        self._from_assets.discard(name)
        self._release(item)

    def collect(self, live: Iterable[str]) -> list[str]:
        """Release the objects built from assets whose names are not in ``live`` (no scene has them any more);
        returns those names."""
        live = set(live)
        gone = [name for name in self._from_assets if name not in live]
        for name in gone:
            self.forget(name)
        return gone

    def adopt(self, name: str, data: Any) -> None:
        """Record that ``name``'s built object now stands for ``data``: for changes that need no rebuild
        (a material's colour set at run time and written back to the scene's assets)."""
        if name not in self._items:
            raise KeyError(f"{self.kind} '{name}' has not been built")
        self._data[name] = data

    def get(self, name: str, referrer: str = "the caller") -> T:
        try:
            return self._items[name]
        except KeyError:
            raise missing(self.kind, name, list(self._items), referrer) from None

    def data_of(self, name: str) -> Any:
        """The data ``name`` was built from (None when it was not built through :meth:`build`)."""
        return self._data.get(name)

    def names(self) -> list[str]:
        return list(self._items)

    def __contains__(self, name: object) -> bool:
        return name in self._items

    def __len__(self) -> int:
        return len(self._items)

    def release(self) -> None:
        """Free every object (the renderer calls this when it is released)."""
        for item in self._items.values():
            self._release(item)
        self._items.clear()
        self._data.clear()

    def _create(self, name: str, data: Any) -> T:
        raise NotImplementedError

    def _release(self, item: T) -> None:
        """Free one object's GPU memory; nothing by default."""


__all__ = ["MissingResourceError", "ResourceLib"]
