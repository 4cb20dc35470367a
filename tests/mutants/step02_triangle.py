"""Mutants of step 02: ``interleave``, ``ngon_mesh`` and ``NGonSystem``."""

from __future__ import annotations

import math

import numpy as np

from gandalf_core.resources import MeshData, VertexAttribute, VertexLayout
from gandalf_tools.grading.mutants import Mutant, mutant, patch

STEP = "step02_triangle"
MUTANTS: list[Mutant] = []


# --- interleave ------------------------------------------------------------------------------------


def _layout(pkg, *, position=(0, 3, 0), color=(4, 4, 12), stride=28):
    return VertexLayout(
        attributes=(VertexAttribute("position", *position), VertexAttribute("color", *color)), stride=stride
    )


def _with_layout(pkg, **kwargs):
    original = pkg.vertex_data.interleave

    def interleave(positions, colors):
        data, _ = original(positions, colors)
        return data, _layout(pkg, **kwargs)

    patch(pkg, "vertex_data.interleave", interleave)


for _name, _text, _slips in [
    ("stride-in-floats", "stride counted in floats (7) instead of bytes (28)", {"stride": 7}),
    ("offset-in-floats", "the colour's offset in floats (3) instead of bytes (12)", {"color": (4, 4, 3)}),
    ("location-1", "the colour at shader location 1 instead of the engine's 4", {"color": (1, 4, 12)}),
]:
    mutant(MUTANTS, STEP, "interleave", _name, _text)(lambda pkg, _s=_slips: _with_layout(pkg, **_s))


@mutant(MUTANTS, STEP, "interleave", "float64", "returns float64 data (the GPU reads 4-byte floats)")
def _(pkg):
    original = pkg.vertex_data.interleave

    def interleave(positions, colors):
        data, layout = original(positions, colors)
        return data.astype(np.float64), layout

    patch(pkg, "vertex_data.interleave", interleave)


@mutant(MUTANTS, STEP, "interleave", "colour-first", "writes the colour before the position in each row")
def _(pkg):
    original = pkg.vertex_data.interleave

    def interleave(positions, colors):
        data, layout = original(positions, colors)
        return np.ascontiguousarray(np.hstack([data[:, 3:], data[:, :3]])), layout

    patch(pkg, "vertex_data.interleave", interleave)


@mutant(MUTANTS, STEP, "interleave", "truncates-rows", "no row-count check: keeps the shorter of the two")
def _(pkg):
    original = pkg.vertex_data.interleave

    def interleave(positions, colors):
        p, c = np.asarray(positions, dtype=np.float64), np.asarray(colors, dtype=np.float64)
        if p.ndim == 2 and c.ndim == 2 and len(p) != len(c):
            n = min(len(p), len(c))
            p, c = p[:n], c[:n]
        return original(p, c)

    patch(pkg, "vertex_data.interleave", interleave)


# --- ngon_mesh -------------------------------------------------------------------------------------


def _fan(n, radius, *, angle=lambda k, n: 2.0 * np.pi * k / n, order=(0, 1, 2), close=True, alpha=1.0):
    k = np.arange(n)
    a = angle(k, n)
    corners = radius * np.column_stack([np.cos(a), np.sin(a), np.zeros(n)])
    positions = np.vstack([np.zeros((1, 3)), corners])
    colors = np.ones((n + 1, 4))
    colors[:, 3] = alpha
    tri = np.column_stack([np.zeros(n, dtype=np.int64), k + 1, (k + 1) % n + 1])
    if not close:
        tri = tri[:-1]
    return MeshData(positions=positions, colors=colors, indices=tri[:, list(order)], name=f"ngon{n}")


def _checked(pkg, build):
    original = pkg.ngon.ngon_mesh

    def ngon_mesh(sides, radius):
        original(sides, radius)  # the solution's argument checks
        return build(int(sides), float(radius))

    patch(pkg, "ngon.ngon_mesh", ngon_mesh)


@mutant(MUTANTS, STEP, "ngon_mesh", "clockwise", "winds every triangle clockwise (centre, k + 1, k)")
def _(pkg):
    _checked(pkg, lambda n, r: _fan(n, r, order=(0, 2, 1)))


@mutant(MUTANTS, STEP, "ngon_mesh", "open-fan", "forgets the last triangle that closes back to corner 0")
def _(pkg):
    _checked(pkg, lambda n, r: _fan(n, r, close=False))


@mutant(MUTANTS, STEP, "ngon_mesh", "degrees", "corner angles 360 k / n fed to cos/sin (degrees for radians)")
def _(pkg):
    _checked(pkg, lambda n, r: _fan(n, r, angle=lambda k, n: 360.0 * k / n))


@mutant(MUTANTS, STEP, "ngon_mesh", "diameter", "treats radius as the diameter")
def _(pkg):
    _checked(pkg, lambda n, r: _fan(n, r / 2.0))


@mutant(MUTANTS, STEP, "ngon_mesh", "alpha-0", "corner colours with alpha 0")
def _(pkg):
    _checked(pkg, lambda n, r: _fan(n, r, alpha=0.0))


@mutant(MUTANTS, STEP, "ngon_mesh", "int-sides", "accepts any sides that int() takes (4.5, '6')")
def _(pkg):
    original = pkg.ngon.ngon_mesh

    def ngon_mesh(sides, radius):
        return original(int(sides), radius)

    patch(pkg, "ngon.ngon_mesh", ngon_mesh)


@mutant(MUTANTS, STEP, "ngon_mesh", "nan-radius", "only rejects radius <= 0 (NaN and infinity get through)")
def _(pkg):
    original = pkg.ngon.ngon_mesh

    def ngon_mesh(sides, radius):
        if isinstance(radius, float) and not math.isfinite(radius) and not radius < 0:
            mesh = original(sides, 1.0)
            return MeshData(mesh.positions * radius, colors=mesh.colors, indices=mesh.indices)
        return original(sides, radius)

    patch(pkg, "ngon.ngon_mesh", ngon_mesh)


@mutant(MUTANTS, STEP, "ngon_mesh", "no-indices", "a plain triangle list without an index buffer")
def _(pkg):
    original = pkg.ngon.ngon_mesh

    def ngon_mesh(sides, radius):
        mesh = original(sides, radius)
        tri = mesh.triangles().astype(int).ravel()
        return MeshData(mesh.positions[tri], colors=mesh.colors[tri])

    patch(pkg, "ngon.ngon_mesh", ngon_mesh)


# --- NGonSystem ------------------------------------------------------------------------------------


def _system(pkg, create):
    base = pkg.ngon.NGonSystem
    module = pkg.ngon

    class NGonSystem(base):
        def on_create_entity(self, entity, components):
            ngon, mesh = components
            create(self, entity, ngon, mesh, module.ngon_mesh)  # looked up now: a test may replace it

    patch(pkg, "ngon.NGonSystem", NGonSystem)


@mutant(MUTANTS, STEP, "NGonSystem", "wrong-name", "registers the mesh under a name of its own, not the component's")
def _(pkg):
    _system(
        pkg,
        lambda self, e, ngon, mesh, build: self.scene.assets.mesh(f"ngon{ngon.sides}", build(ngon.sides, ngon.radius)),
    )


@mutant(MUTANTS, STEP, "NGonSystem", "default-hexagon", "ignores the component: always a hexagon of radius 0.5")
def _(pkg):
    _system(pkg, lambda self, e, ngon, mesh, build: self.scene.assets.mesh(mesh.mesh, build(6, 0.5)))


@mutant(MUTANTS, STEP, "NGonSystem", "unit-radius", "ignores the component's radius")
def _(pkg):
    _system(pkg, lambda self, e, ngon, mesh, build: self.scene.assets.mesh(mesh.mesh, build(ngon.sides, 1.0)))


@mutant(MUTANTS, STEP, "NGonSystem", "one-shared-mesh", "builds the first entity's mesh and reuses it for all")
def _(pkg):
    cache = {}

    def create(self, e, ngon, mesh, build):
        if "first" not in cache:
            cache["first"] = build(ngon.sides, ngon.radius)
        self.scene.assets.mesh(mesh.mesh, cache["first"])

    _system(pkg, create)


@mutant(MUTANTS, STEP, "NGonSystem", "nothing-registered", "stores the mesh on the component instead of the assets")
def _(pkg):
    def create(self, e, ngon, mesh, build):
        mesh.data = build(ngon.sides, ngon.radius)

    _system(pkg, create)
