"""What step 07 saves in USD scenes: declared once, read by the final step's USD layer (``step07_advanced.usd``).

``COMPONENTS`` maps a component class to the fields a file holds; ``SYSTEMS`` a system class to the constructor
settings it is rebuilt with (a scene may name only these); ``UNSAVEABLE`` a system whose state a file cannot hold,
and why (saving a scene that has one is refused with that sentence). Nothing here imports USD: the lessons stay free
of the persistence layer, and a file names classes, never code.
"""

from __future__ import annotations

from .explode.scene import ExplodeComponent, ExplodeSystem
from .gpu_motion.system import GpuSpinSystem
from .pathtracer.scene import PathTraceSystem
from .showcase.particles import ParticleComponent, ParticleSystem
from .terrain.scene import TessellationSystem

# The particle markers are saved; their system is refused, saying why.
COMPONENTS = {ParticleComponent: ("index",), ExplodeComponent: ("time", "speed")}
# The GPU spin is rebuilt from its components (the join times start again when the scene is loaded).
SYSTEMS = {GpuSpinSystem: ()}
UNSAVEABLE = {
    ParticleSystem: "the particles live in a GPU buffer that a compute kernel steps (chosen by the variant file for "
                    "its API); a file cannot hold it",
    TessellationSystem: "it drives the variant's tessellation backend (GPU tessellation stages in OpenGL, a compute "
                        "tessellator in WebGPU), which the variant file builds for its API",
    ExplodeSystem: "it drives the variant's explode route (an OpenGL geometry shader or a WebGPU compute pre-pass "
                   "with its GPU buffers), which the variant file builds for its API",
    PathTraceSystem: "its accumulation lives in GPU buffers that a compute kernel writes, built by the variant file "
                     "for its API",
}
