"""The base of every resource library (textures, shaders, meshes, materials) in both backends.

A library builds a GPU object once per name and hands out the cached one afterwards, as in the paper:
``lib.build(name, data)``. It belongs to one renderer, so a fresh renderer starts with empty libraries.
:meth:`ResourceLib.resolve` is how the renderers turn the names a scene's components use into GPU
objects on first use, from the scene's backend-neutral assets.

Objects built from a scene's assets follow them: when the data under a name changes (a texture replaced while
running), the next use builds it anew; when no scene has the name any more (:meth:`ResourceLib.collect`), its GPU
object is released. What the app's own code builds with :meth:`build` (shaders, storage buffers) stays until the
renderer goes. Whatever refers to a released object (a vertex array, a material's bind group) is dropped with it
through :attr:`ResourceLib.on_forget`, also when :meth:`ResourceLib.replace` puts a new object under its name (a
shader rebuilt from edited text: :mod:`.rebuild`).
"""

from __future__ import annotations

import warnings
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
        item = self._items.pop(name)  # gone before the callbacks run: a dependent built again cannot take it
        data = self._data.pop(name, None)
        from_assets = name in self._from_assets
        self._from_assets.discard(name)
        try:
            for callback in self.on_forget:
                callback(name)
        except BaseException:
            self._items[name], self._data[name] = item, data  # nothing was released: put it back as it was
            if from_assets:
                self._from_assets.add(name)
            raise
        self._release(item)

    def replace(self, name: str, item: T, data: Any) -> None:
        """Put a new object under ``name`` (built already, from ``data``) in place of the one there: what refers to
        the old one is dropped through :attr:`on_forget`, which runs with the new one in place (a dependent may build
        itself again at once), then the old one is released. Nothing of the old one is touched before the new one
        exists, so a build that fails leaves the last good object drawing."""
        if name not in self._items:
            raise KeyError(f"{self.kind} '{name}' has not been built")
        old = self._items[name]
        self._items[name], self._data[name] = item, data
        for callback in self.on_forget:
            callback(name)
        self._release(old)

    def renew_where(self, uses: Callable[[T], bool]) -> list[str]:
        """Release every object for which ``uses(object)`` holds (it refers to something that was replaced); those
        built from a scene's assets are built again on their next use, those the app's own code built are built
        again now from the same data (one that no longer builds is left out, with a warning naming its error).
        Returns their names."""
        renewed = [name for name, item in self._items.items() if uses(item)]
        for name in renewed:
            data, from_code = self._data.get(name), name not in self._from_assets
            self.forget(name)
            if from_code and data is not None:
                try:
                    self.build(name, data)
                except Exception as exc:  # noqa: BLE001 - the caller's rebuild went well; this one is reported
                    warnings.warn(f"{self.kind} '{name}' could not be built again: {exc}", stacklevel=2)
        return renewed

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

    def gpu_bytes(self) -> int:
        """Bytes of GPU memory this library's objects hold, as asked of the API (:mod:`.gpu_memory`)."""
        return sum(self._gpu_bytes(item, self._data.get(name)) for name, item in self._items.items())

    def _create(self, name: str, data: Any) -> T:
        raise NotImplementedError

    def _gpu_bytes(self, item: T, data: Any) -> int:
        """One object's bytes of GPU memory; 0 by default (a shader program is the driver's business)."""
        return 0

    def _release(self, item: T) -> None:
        """Free one object's GPU memory; nothing by default."""


__all__ = ["MissingResourceError", "ResourceLib"]
