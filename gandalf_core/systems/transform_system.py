"""The transform system: world matrices for every entity, parents before children, once per frame.

Only rows that changed are recomputed: the transform store reports the rows written since the last frame
(``ColumnStore.take_changes``), and those rows and their descendants get new matrices (a static scene costs
nothing per frame). On a full pass (the first frame, a new hierarchy, a whole column handed out for writing),
all local matrices are built in one vectorised pass (``TRSBatch``); the hierarchy is then resolved
level by level (every entity at depth *d* in one batched matrix product), so a child is always
recomputed after any ancestor moved and 100k entities cost a few numpy calls. A deep hierarchy (more than
:data:`DEEP` levels: a 1,000-link chain) would cost one call per level; it is resolved by pointer jumping
instead: each round composes every entity with its current ancestor's product and jumps to that ancestor's
ancestor, so ``ceil(log2(depth))`` batched rounds give every world matrix.
"""

from __future__ import annotations

import uuid

import numpy as np

from ..components import LinkComponent, TransformComponent
from ..ecs import ColumnStore, Scene, System
from ..math import TRSBatch, decompose_trs, invert_affine, quat_normalize, trs

# Quaternions shorter than this carry no usable rotation and count as the identity.
_MIN_QUAT_NORM = 1e-12
#: Hierarchies deeper than this are resolved by pointer jumping (log2(depth) rounds) rather than level by level.
DEEP = 12


class TransformSystem(System):
    """Writes ``TransformComponent.world`` for every entity that has a Transform.

    Only what changed is paid for: the rows the store reports as changed (:meth:`ColumnStore.take_changes`) and
    their descendants are recomputed; a frame in which nothing moved costs one call. After each update
    :attr:`changed` holds the rows whose world matrix was written (None: all of them) and :attr:`generation`
    counts the updates, so a reader that saw every generation needs to look at those rows only.
    """

    def __init__(self) -> None:
        super().__init__([TransformComponent])
        self._plan_key: tuple[int, int, int] | None = None
        self._levels: list[tuple[np.ndarray, np.ndarray]] = []
        self._jumps: tuple[np.ndarray, np.ndarray] | None = None  # (rows with a parent, their parent rows)
        self._trs = TRSBatch()
        self._trs_changed = TRSBatch()  # its own scratch: the changed rows are fewer, and their number varies
        self._local: np.ndarray | None = None
        self._moved: np.ndarray | None = None  # per row: changed itself or below a changed ancestor
        #: Rows whose world matrix the last update wrote (sorted), or None when it wrote every row.
        self.changed: np.ndarray | None = None
        #: Bumped by every update (a reader compares it with the generation it saw last).
        self.generation = 0
        #: True when every scale written so far is positive: then no world matrix mirrors (det(T R S) = sx sy sz
        #: for a proper rotation, and a product of positive determinants down a hierarchy). False says "may".
        self.positive_scales = False

    def on_update_system(self, ts: float) -> None:
        scene = self.scene
        assert scene is not None
        store = scene.store(TransformComponent)
        self.generation += 1
        changes = store.take_changes()
        n = store.count
        if n == 0:
            self.changed = changes if changes is not None else np.zeros(0, np.intp)
            return
        key = (scene.hierarchy_version, self.version, store.layout_version)
        if key != self._plan_key:
            self._levels = self._plan(scene)
            self._jumps = None
            if len(self._levels) > DEEP:
                self._jumps = (np.concatenate([rows for rows, _ in self._levels]),
                               np.concatenate([parents for _, parents in self._levels]))
            self._plan_key = key
            changes = None
        if changes is not None and (self._jumps is None or not len(changes)):
            self.changed = self._update_rows(store, changes)
            return
        self.changed = None
        self.positive_scales = bool(store.columns["scale"][:n].min() > 0.0)
        q = _usable_quaternions(store.columns["quaternion"][:n])
        world = store.columns["world"][:n]
        if not self._levels:  # a flat scene: local is world, written in place
            self._build(store, q, world)
            return
        if self._local is None or len(self._local) != n:
            self._local = np.empty((n, 4, 4))
        local = self._build(store, q, self._local)
        world[:] = local
        if self._jumps is not None:
            self._resolve_by_jumping(world, n, *self._jumps)
            return
        for rows, parent_rows in self._levels:
            world[rows] = world[parent_rows] @ local[rows]

    # --8<-- [start:update_rows]
    def _update_rows(self, store: ColumnStore, rows: np.ndarray) -> np.ndarray:
        """Recompute the world matrices of ``rows`` and of everything below them; return the rows written."""
        if not len(rows):
            return rows
        n = store.count
        columns = store.columns
        self.positive_scales = self.positive_scales and bool(columns["scale"][rows].min() > 0.0)
        local = self._build(store, _usable_quaternions(columns["quaternion"][rows]), None, rows)
        world = columns["world"]
        if not self._levels:
            world[rows] = local
            return rows
        self._local[rows] = local
        if self._moved is None or len(self._moved) != n:
            self._moved = np.zeros(n, dtype=bool)
        moved = self._moved
        moved[:] = False
        moved[rows] = True
        for child_rows, parent_rows in self._levels:  # a child moves when its parent did
            moved[child_rows] |= moved[parent_rows]
        written = np.flatnonzero(moved)
        world[written] = self._local[written]
        for child_rows, parent_rows in self._levels:
            picked = moved[child_rows]
            if picked.any():
                children = child_rows[picked]
                world[children] = world[parent_rows[picked]] @ self._local[children]
        return written
    # --8<-- [end:update_rows]

    @staticmethod
    def _resolve_by_jumping(world: np.ndarray, n: int, rows: np.ndarray, parents: np.ndarray) -> None:
        """``world`` holds the local matrices; afterwards the world ones. Round k makes each entity's matrix the
        product of its 2^k nearest ancestors' and its own, so the number of rounds grows with log2(depth)."""
        ancestor = np.full(n, -1, dtype=np.intp)
        ancestor[rows] = parents
        active = rows
        while len(active):
            up = ancestor[active]
            world[active] = world[up] @ world[active]  # right side read before the write: one simultaneous step
            ancestor[active] = ancestor[up]
            active = active[ancestor[active] >= 0]

    def _build(self, store: ColumnStore, q: np.ndarray, out: np.ndarray | None,
               rows: np.ndarray | None = None) -> np.ndarray:
        """The local matrices (of ``rows``, or of every row); TRSBatch checks the columns are finite, and a failure
        is told per entity here (NaN can come in through a field's live view), so the check costs nothing extra."""
        n = store.count
        columns = store.columns
        try:
            if rows is None:
                return self._trs(columns["translation"][:n], q, columns["scale"][:n], out=out)
            return self._trs_changed(columns["translation"][rows], q, columns["scale"][rows], out=out)
        except ValueError:
            for field in ("translation", "quaternion", "scale"):
                column = store.read(field)
                bad = ~np.isfinite(column.reshape(len(column), -1)).all(axis=1)
                if bad.any():
                    row = int(np.flatnonzero(bad)[0])
                    entity = next(e for e, (t,) in zip(self.entities, self.components) if t._row == row)
                    raise ValueError(f"{self.scene.describe(entity)}: TransformComponent.{field} is not finite: "
                                     f"{column[row].tolist()}") from None
            raise

    def _plan(self, scene: Scene) -> list[tuple[np.ndarray, np.ndarray]]:
        """Group transform rows by hierarchy depth (depth ≥ 1 only; roots need no product)."""
        row_of: dict[uuid.UUID, int] = {}
        for entity, (transform,) in zip(self.entities, self.components):
            row_of[entity] = transform._row
        depth_cache: dict[uuid.UUID, int] = {}

        def transformed_parent(entity: uuid.UUID) -> uuid.UUID | None:
            # The nearest ancestor that has a Transform; ancestors without one count as identity.
            parent = scene.parent_of(entity)
            while parent is not None and parent not in row_of:
                parent = scene.parent_of(parent)
            return parent

        def depth(entity: uuid.UUID) -> int:
            chain: list[uuid.UUID] = []
            node: uuid.UUID | None = entity
            while node is not None and node not in depth_cache:
                chain.append(node)
                node = transformed_parent(node)
            d = -1 if node is None else depth_cache[node]
            for item in reversed(chain):  # iterative: a 1000-deep chain must not hit the recursion limit
                d += 1
                depth_cache[item] = d
            return depth_cache[entity]

        by_level: dict[int, tuple[list[int], list[int]]] = {}
        for entity, row in row_of.items():
            d = depth(entity)
            if d == 0:
                continue
            parent = transformed_parent(entity)
            rows, parents = by_level.setdefault(d, ([], []))
            rows.append(row)
            parents.append(row_of[parent])  # type: ignore[index]
        return [
            (np.array(rows, dtype=np.intp), np.array(parents, dtype=np.intp))
            for _, (rows, parents) in sorted(by_level.items())
        ]


def _usable_quaternions(q: np.ndarray) -> np.ndarray:
    """``q`` with (near-)zero quaternions, never valid, replaced by the identity ("no rotation"). TRSBatch builds
    the exact rotation for any other length, so no renormalising pass."""
    degenerate = np.einsum("ij,ij->i", q, q) < _MIN_QUAT_NORM**2
    if degenerate.any():
        q = q.copy()
        q[degenerate] = (1.0, 0.0, 0.0, 0.0)
    return q


def world_matrix(scene: Scene, entity: uuid.UUID) -> np.ndarray:
    """The entity's world matrix computed now from its ancestors' local transforms (no frame needed)."""
    matrix = np.eye(4)
    node: uuid.UUID | None = entity
    while node is not None:
        transform = scene.try_component(node, TransformComponent)
        if transform is not None:
            q = transform.quaternion
            # Same rule as the system's batch path: a (near-)zero quaternion is the identity rotation.
            q = quat_normalize(q) if np.linalg.norm(q) > _MIN_QUAT_NORM else np.array([1.0, 0.0, 0.0, 0.0])
            matrix = trs(transform.translation, q, transform.scale) @ matrix
        node = scene.parent_of(node)
    return matrix


def set_parent_keep_world(scene: Scene, entity: uuid.UUID, parent: uuid.UUID | None) -> None:
    """Re-parent ``entity`` so that its world pose stays where it is (local TRS recomputed).

    Exact when the new parent's world matrix has no shear (uniform scale, or non-uniform scale without
    rotation above it); a local TRS cannot express a sheared pose, so then the closest TRS is kept.
    """
    world = world_matrix(scene, entity)
    if scene.try_component(entity, LinkComponent) is None:
        scene.add_component(entity, LinkComponent(None))
    scene.set_parent(entity, parent)
    parent_world = world_matrix(scene, parent) if parent is not None else np.eye(4)
    t, q, s = decompose_trs(invert_affine(parent_world) @ world)
    transform = scene.get_component(entity, TransformComponent)
    transform.translation, transform.quaternion, transform.scale = t, q, s
