"""The editor's frame inspector, capture side: what the frame panel (:mod:`step07_advanced.editor.frame_panel`)
shows, and what benchmarks and scripts read without an editor.

* :mod:`.capture`: :func:`~.capture.capture_frame` records one frame's passes and draws through the renderer's
  ``recorder`` hook (:attr:`gandalf_core.render.base.Renderer.recorder`), with the state, decoded uniform blocks
  and resources of each draw (:mod:`.inspect_draw`, records in :mod:`.frame_records`), and compute dispatches
  through :func:`~.capture.compute_recorded`;
* :mod:`.gpu_timer`: GPU milliseconds per pass and per draw (:func:`~.capture.gpu_timer` makes a renderer's);
* :mod:`.picking`: which draw, entity and material wrote a pixel;
* :mod:`.texture_readback`: any texture or target of a renderer (:mod:`.texture_sources`) read back as numpy.

What differs per API lives in ``*_gl.py`` / ``*_wgpu.py`` beside each (the timers, a pick's replay, texture
read-back), as everywhere in the course.

The engine knows none of them: a renderer offers the hook and the capture installs itself for one frame. Importing
this package loads no GUI or GPU library.
"""
