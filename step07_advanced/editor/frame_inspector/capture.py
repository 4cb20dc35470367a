"""A frame capture: one frame's passes in order and, per draw, everything that went into it, in both APIs.

A renderer holds ``recorder = None``; only while a frame is captured does it hold a :class:`FrameRecorder`, which
its pass and draw loops call (one call where a render pass begins and ends, one ``with`` around each draw, one around
the overlays): capturing costs only the captured frame. :func:`capture_frame` captures the next frame of an
application and returns a :class:`FrameCapture`:

* passes in order: ``compute`` (dispatches of code that uses :func:`compute_recorded`), ``shadow`` (the shadow map),
  ``opaque``, ``sky``, ``transparent``, ``overlay`` (the editor's GUI), each with the target it draws into; a frame
  rendered twice (the editor's viewport, then the window) lists both;
* per draw: the entities of its instances, the mesh (vertex and index counts, the vertex layout), the material, the
  shader and its files, the pipeline state (blend, depth compare and writes, cull, front face, topology, patch size;
  in OpenGL read back from the context as it was when the draw ran, in WebGPU as the pipeline was created), the
  bound uniform blocks **decoded by field name** from their one declaration
  (:meth:`~gandalf_core.resources.layout.BlockLayout.unpack` of the bytes written: read back from the GL buffers,
  the bytes queued to the WebGPU ones), the bound textures and buffers;
* GPU milliseconds per pass and per draw when the device can time them (:mod:`.gpu_timer`), with
  :attr:`FrameCapture.timing` saying which timer ran or why none did.
"""

from __future__ import annotations

import uuid
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from gandalf_core.render.base import NOT_RECORDING
from gandalf_core.render.render_system import RenderSystem
from gandalf_core.resources.blocks import BLOCK_BINDINGS, FRAME_LAYOUT, LIGHTS_LAYOUT, WGSL_BINDINGS

from .frame_records import DrawRecord, FrameCapture, PassRecord
from .gpu_timer import GpuTimer
from .inspect_draw import describe_draw

__all__ = ["NOT_RECORDING", "DrawRecord", "FrameCapture", "FrameRecorder", "PassRecord", "capture_frame",
           "compute_recorded", "gpu_timer", "name_entities"]

class FrameRecorder:
    """Receives a renderer's pass and draw hooks while one frame is captured (see :func:`capture_frame`)."""

    def __init__(self, renderer: Any, timing: bool = True, describe: bool = True) -> None:
        """``timing``: GPU times (:mod:`.gpu_timer`); ``describe``: each draw's state, blocks and resources (False:
        names, counts and times only, what a benchmark reading per-pass GPU times needs, at little cost)."""
        self.renderer = renderer
        self.describe = describe
        # Compute code reaches the capture through its context or device (see compute_recorded).
        _ACTIVE[id(renderer.ctx if renderer.backend == "opengl" else renderer.device)] = self
        self.timer: GpuTimer | None = gpu_timer(renderer) if timing else None
        self.timing = (self.timer.reason if self.timer is not None else "not asked for")
        self.passes: list[PassRecord] = []
        self._frames: list[str] = []  # the timer labels of each render() call
        self._target = ""
        self._pass: PassRecord | None = None
        self._pass_label = ""
        self._blocks: dict[str, dict[str, Any]] = {}
        self._draws = 0
        #: describe=False: each draw's rows array as drawn, made into a list in :meth:`finish`, right after the
        #: frame and before anything can change them (so that a million rows cost the timed spans nothing).
        self._rows: list[tuple[DrawRecord, Any]] = []
        #: The current render pass's begin and end timestamps (its first pass starts at the first, its last ends
        #: at the second), or None.
        self._target_stamps: list[int | None] | None = None
        self._pass_start: int | None = None
        self._drew_in_target = False
        self.reverse_z = False

    # --- hooks the renderers call ---------------------------------------------------------------------
    def begin_frame(self, frame: bytes, lights: bytes, where: Any = None) -> None:
        """A render() call begins; ``frame`` and ``lights`` are the engine blocks' bytes as written."""
        label = f"frame {len(self._frames)}"
        self._frames.append(label)
        self._span_begin(label, where)
        gl, wgsl = BLOCK_BINDINGS, WGSL_BINDINGS
        binding = (lambda n: f"binding {gl[n]}") if self.renderer.backend == "opengl" else \
            (lambda n: f"@group({wgsl[n][0]}) @binding({wgsl[n][1]})")
        self._blocks = {"Frame": {"binding": binding("Frame"), "values": FRAME_LAYOUT.unpack(frame)},
                        "Lights": {"binding": binding("Lights"), "values": LIGHTS_LAYOUT.unpack(lights)}}

    def end_frame(self, where: Any = None) -> None:
        """The render() call ends (WebGPU: before its encoder is finished, to resolve the timestamps)."""
        self._close_pass(where)
        self._span_end(where)
        if self.timer is not None and where is not None:
            self.timer.resolve(where)

    def begin_target(self, target: str, where: Any = None) -> dict[str, Any] | None:
        """A render pass into ``target`` begins: OpenGL calls it before the target is cleared; WebGPU before it
        begins the pass, with its encoder as ``where``, and passes the result as the pass's ``timestamp_writes`` (so
        that the pass's time includes its clear)."""
        self._close_pass(where)
        self._target = target
        self._drew_in_target = False
        if self.timer is None:
            return None
        if self.renderer.backend == "opengl":
            self._target_stamps = [self.timer.stamp(), None]
            return None
        reserved = self.timer.reserve(2)
        if reserved is None:
            return None
        self._target_stamps = list(reserved)
        return {"query_set": self.timer._set, "beginning_of_pass_write_index": reserved[0],
                "end_of_pass_write_index": reserved[1]}

    def end_target(self, where: Any = None) -> None:
        """The render pass ends (WebGPU: before ``where.end()``; its end is the pass's own end timestamp)."""
        stamps = self._target_stamps
        if stamps is not None and stamps[1] is None and self.timer is not None:
            stamps[1] = self.timer.stamp(where)
        if self._pass is None and self._target and not self._drew_in_target:  # nothing drawn: a clear alone
            self._open_pass("clear", where)
        self._close_pass(where, stamps[1] if stamps is not None else None)
        self._target_stamps = None
        self._target = ""

    @contextmanager
    def draw(self, pass_name: str, where: Any, shader: Any, batch: Any = None, material: Any = None,
             mesh: Any = None, reverse_z: bool = False, sky: str | None = None,
             pipeline: Any = None) -> Iterator[None]:
        """Around one draw call: records it (state, blocks, resources) and times it (``sky``: the sky pass's cube
        texture; ``pipeline``: WebGPU's pipeline, whose creation state the record shows)."""
        if self._pass is None or self._pass.name != pass_name:
            self._open_pass(pass_name, where)
        record = self._describe(pass_name, shader, batch, material, mesh, reverse_z, sky, pipeline)
        if pass_name != "shadow":
            self.reverse_z = reverse_z
        self._pass.draws.append(record)
        label = f"draw {record.index}"
        self._span_begin(label, where)
        yield
        self._span_end(where)

    @contextmanager
    def dispatch(self, label: str, workgroups: tuple[int, ...], shader: str, buffers: list[tuple[str, int]],
                 where: Any) -> Iterator[None]:
        """Around one compute dispatch (see :func:`compute_recorded`)."""
        if self._pass is None or self._pass.name != "compute":
            self._target = "compute"
            self._open_pass("compute", where)
        groups = tuple(int(g) for g in workgroups) + (1,) * (3 - len(workgroups))
        record = DrawRecord(index=self._draws, pass_name="compute", mesh=None, material=None, shader=label,
                            shader_files=[shader] if shader else [], instances=1, first_instance=0, rows=[],
                            vertex_count=0, index_count=0, layout=[], state={"workgroups": groups}, blocks={},
                            textures=[], buffers=[{"slot": f"storage {i}", "name": n, "bytes": b}
                                                  for i, (n, b) in enumerate(buffers)])
        self._draws += 1
        self._pass.draws.append(record)
        self._span_begin(f"draw {record.index}", where)
        yield
        self._span_end(where)
        # The dispatch's pass ends with it (a WebGPU compute pass does; on OpenGL, so that the span does not run on
        # through the CPU's work before the next pass): a dispatch after it is timed as a pass of its own.
        self._close_pass(where)

    @contextmanager
    def overlay(self, where: Any = None) -> Iterator[None]:
        """Around the overlays (the editor's GUI), drawn into the frame's target."""
        self._open_pass("overlay", where)
        yield
        self._close_pass(where)

    # --- the result ----------------------------------------------------------------------------------
    def abandon(self) -> None:
        """Give up a capture whose frame never ran (or failed): no read-back, the timer's queries freed."""
        self._unregister()
        if self.timer is not None:
            self.timer.release()
            self.timer = None

    def _unregister(self) -> None:
        for key in [k for k, recorder in _ACTIVE.items() if recorder is self]:
            del _ACTIVE[key]

    def finish(self) -> FrameCapture:
        """The capture, with the GPU times read back (waits for the GPU once) and the GPU memory the renderer holds."""
        frame_ms: list[float] = []
        self._unregister()
        for record, rows in self._rows:
            record.rows = rows.tolist()
        self._rows = []
        if self.timer is not None:
            ms = self.timer.results()
            for i, p in enumerate(self.passes):
                p.gpu_ms = ms.get(f"pass {i}")
                for d in p.draws:
                    d.gpu_ms = ms.get(f"draw {d.index}")
            frame_ms = [ms[label] for label in self._frames if label in ms]
            self.timer.release()
        return FrameCapture(self.renderer.backend, self.passes, self.timing, frame_ms, self.reverse_z,
                            self.renderer.gpu_memory())

    # --- inside -------------------------------------------------------------------------------------
    def _span_begin(self, label: str, where: Any) -> None:
        if self.timer is not None:
            self.timer.begin(label, where)

    def _span_end(self, where: Any) -> None:
        if self.timer is not None:
            self.timer.end(where)

    def _open_pass(self, name: str, where: Any) -> None:
        self._close_pass(where)
        self._pass = PassRecord(name, self._target)
        self.passes.append(self._pass)
        self._drew_in_target = True
        stamps = self._target_stamps
        if stamps is not None and stamps[0] is not None:  # the render pass's first: it starts where the pass does
            self._pass_start, stamps[0] = stamps[0], None
        elif self.timer is not None:
            self._pass_start = self.timer.stamp(where)

    def _close_pass(self, where: Any, end: int | None = None) -> None:
        if self._pass is not None:
            if self.timer is not None:
                end = end if end is not None else self.timer.stamp(where)
                self.timer.span(f"pass {self.passes.index(self._pass)}", self._pass_start, end)
            self._pass = None

    def _describe(self, pass_name: str, shader: Any, batch: Any, material: Any, mesh: Any,
                  reverse_z: bool, sky: str | None, pipeline: Any = None) -> DrawRecord:
        index = self._draws
        self._draws += 1
        if not self.describe:
            record = DrawRecord(index, pass_name, mesh.name if mesh is not None else None,
                                material.name if material is not None else None, shader.name, [],
                                batch.count if batch is not None else 1,
                                batch.first_instance if batch is not None else 0, [], 0, 0, [], {}, {}, [], [],
                                bool(batch is not None and batch.mirrored), sky)
            if batch is not None:
                self._rows.append((record, batch.rows))
            return record
        return describe_draw(self.renderer, index, pass_name, shader, batch, material, mesh, reverse_z,
                             self._blocks, sky, pipeline)


def gpu_timer(renderer: Any) -> GpuTimer:
    """A timer for ``renderer``'s context or device (check :attr:`GpuTimer.available`)."""
    if renderer.backend == "opengl":
        from .gpu_timer_gl import GLTimer

        return GLTimer(renderer.ctx)
    from .gpu_timer_wgpu import WGPUTimer

    return WGPUTimer(renderer.device, getattr(renderer, "adapter", None))


#: The recorder capturing a frame of each context or device (by id), while it captures.
_ACTIVE: dict[int, FrameRecorder] = {}


def compute_recorded(context: Any, label: str, workgroups: tuple[int, ...], *, shader: str = "",
                     buffers: list[tuple[str, int]] = (), where: Any = None) -> Any:
    """The capture's ``with`` around a compute dispatch on ``context`` (a moderngl context, or a wgpu device with
    the compute pass encoder as ``where``): it lists the dispatch, its workgroups and buffers in a ``compute`` pass
    of the captured frame and times it. Nothing happens unless a frame of that context is being captured::

        with compute_recorded(ctx, "particles", (groups,), buffers=[("particles", buf.size)]):
            program.run(group_x=groups)
    """
    recorder = _ACTIVE.get(id(context))
    if recorder is None:
        return NOT_RECORDING
    return recorder.dispatch(label, workgroups, shader, list(buffers), where)


def capture_frame(app: Any, timing: bool = True, dt: float | None = None, describe: bool = True,
                  name: bool = True) -> FrameCapture:
    """Run one frame of ``app`` with its renderer recording, and return the capture (entities named, unless
    ``name`` is False).

    A benchmark that wants GPU milliseconds per pass: ``capture_frame(app, describe=False, name=False)``, then
    ``{p.name: p.gpu_ms for p in capture.passes}`` and ``capture.frame_gpu_ms``."""
    renderer = app.renderer
    recorder = FrameRecorder(renderer, timing, describe)
    renderer.recorder = recorder
    try:
        app.step(dt)
    except BaseException:
        recorder.abandon()
        raise
    finally:
        renderer.recorder = None
    capture = recorder.finish()
    if name:
        name_entities(capture, app.scene)
    return capture


def name_entities(capture: FrameCapture, scene: Any) -> None:
    """Fill each draw's ``entities`` from its rows, through the scene's render system (rows -> entities)."""
    by_row: dict[int, uuid.UUID] = {}
    for system in scene.systems:
        if isinstance(system, RenderSystem):
            for entity, (transform, _mesh, _material) in zip(system.entities, system.components):
                by_row[transform._row] = entity
    for draw in capture.draws:
        draw.entities = [by_row[r] for r in draw.rows if r in by_row]
