"""The particle fountain, backend-neutral: parameters, the numpy twin of the compute kernel, and the ECS side.

The GPU does the simulation (``particles.comp`` / ``particles.wgsl``, driven by ``compute_gl.py`` /
``compute_wgpu.py``); this module holds what both APIs share: the byte layout of the parameters and of the
particle buffer, a float32 numpy twin of the kernel (the reference the tests grade against), and the
:class:`ParticleSystem` that steps any kernel once per frame and moves one small cube per particle.

A particle is two vec4 (32 bytes, the same in std430 and WGSL): ``position.xyz`` with the remaining life in
``position.w``, and ``velocity.xyz``. The state array has shape (N, 2, 4), float32.
"""

from __future__ import annotations

import uuid
import warnings
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from gandalf_core import TransformComponent
from gandalf_core.ecs import Component, System

from .shaders import SIM_LAYOUT

#: Particles per work group (``local_size_x`` / ``@workgroup_size``): dispatch ceil(N / 64) groups.
WORKGROUP_SIZE = 64
PARTICLE_FLOATS = 8


@dataclass(frozen=True)
class SimParams:
    """One step's parameters; :meth:`pack` gives the bytes of the kernels' ``SimParams`` block."""

    dt: float = 1.0 / 60.0
    gravity: tuple[float, float, float] = (0.0, -9.81, 0.0)
    emitter: tuple[float, float, float] = (0.0, 0.1, 0.0)
    max_life: float = 2.4
    restitution: float = 0.55
    floor_y: float = 0.04
    seed: int = 0

    def pack(self) -> bytes:
        """The uniform bytes (:data:`.shaders.SIM_LAYOUT`): the emitter's w is the longest life."""
        return SIM_LAYOUT.pack({"gravity": (*self.gravity, 0.0), "emitter": (*self.emitter, self.max_life),
                                "dt": self.dt, "restitution": self.restitution, "floor_y": self.floor_y,
                                "seed": self.seed % 2**32})


def hash_u32(x: np.ndarray) -> np.ndarray:
    """lowbias32, the integer hash of the kernels, on uint32 arrays (wrapping multiplication)."""
    x = np.asarray(x, dtype=np.uint32).copy()
    x ^= x >> np.uint32(16)
    x *= np.uint32(0x7FEB352D)
    x ^= x >> np.uint32(15)
    x *= np.uint32(0x846CA68B)
    x ^= x >> np.uint32(16)
    return x


def random01(x: np.ndarray) -> np.ndarray:
    """Uniform float32 in [0, 1) from the hash's top 24 bits, as the kernels compute it."""
    return (hash_u32(x) >> np.uint32(8)).astype(np.float32) / np.float32(16777216.0)


def particle_step_np(state: np.ndarray, params: SimParams) -> np.ndarray:
    """The student's ``particle_step`` in float32: the exact constant-gravity step, a floor bounce, life -= dt."""
    f = np.float32
    dt = f(params.dt)
    gravity = np.asarray(params.gravity, dtype=np.float32)
    position = state[:, 0, :3] + state[:, 1, :3] * dt + f(0.5) * gravity * (dt * dt)
    velocity = state[:, 1, :3] + gravity * dt
    floor_y, e = f(params.floor_y), f(params.restitution)
    bounce = (position[:, 1] < floor_y) & (velocity[:, 1] < 0.0)
    position[bounce, 1] = floor_y + (floor_y - position[bounce, 1]) * e
    velocity[bounce, 1] = -velocity[bounce, 1] * e
    out = np.empty_like(state)
    out[:, 0, :3], out[:, 0, 3] = position, state[:, 0, 3] - dt
    out[:, 1, :3], out[:, 1, 3] = velocity, state[:, 1, 3]
    return out


def step_particles_np(state: np.ndarray, params: SimParams) -> np.ndarray:
    """The numpy twin of the whole compute kernel: ``particle_step`` then respawning the dead at the emitter."""
    out = particle_step_np(np.asarray(state, dtype=np.float32), params)
    dead = np.nonzero(out[:, 0, 3] <= 0.0)[0].astype(np.uint32)
    if dead.size:
        key = hash_u32(dead ^ hash_u32(np.uint32(params.seed % 2**32))) & np.uint32(0xFFFFFFF0)
        f = np.float32
        out[dead, 1, 0] = (random01(key) - f(0.5)) * f(2.4)
        out[dead, 1, 1] = f(5.0) + f(1.5) * random01(key + np.uint32(1))
        out[dead, 1, 2] = (random01(key + np.uint32(2)) - f(0.5)) * f(2.4)
        out[dead, 1, 3] = 0.0
        out[dead, 0, :3] = np.asarray(params.emitter, dtype=np.float32)
        out[dead, 0, 3] = f(params.max_life) * (f(0.5) + f(0.5) * random01(key + np.uint32(3)))
    return out


def initial_particles(count: int, params: SimParams = SimParams(), warmup: float = 2.5) -> np.ndarray:
    """``count`` particles, all dead at the emitter, then simulated for ``warmup`` seconds by the numpy twin.

    Their first lives end at staggered times, so after the warm-up the fountain flows evenly.
    """
    if not isinstance(count, int) or count < 1:
        raise ValueError(f"count must be a positive int, got {count!r}")
    state = np.zeros((count, 2, 4), dtype=np.float32)
    state[:, 0, :3] = params.emitter
    state[:, 0, 3] = -np.arange(count, dtype=np.float32) / count  # all respawn on the first step
    for k in range(round(warmup / params.dt)):
        state = step_particles_np(state, SimParams(**{**params.__dict__, "seed": 1_000_000 + k}))
        if k == 0:  # stagger the births over one longest life
            state[:, 0, 3] *= np.linspace(1.0 / count, 1.0, count, dtype=np.float32)
    return state


class ParticleKernel(Protocol):
    """What :class:`ParticleSystem` needs from a kernel (numpy, OpenGL or WebGPU)."""

    def step(self, params: SimParams) -> None: ...

    def read(self) -> np.ndarray: ...

    def release(self) -> None: ...


class NumpyParticleKernel:
    """The numpy twin as a kernel: the backend-neutral fallback, and a model for the GPU ones."""

    def __init__(self, state: np.ndarray) -> None:
        self.state = np.array(state, dtype=np.float32)

    def step(self, params: SimParams) -> None:
        self.state = step_particles_np(self.state, params)

    def read(self) -> np.ndarray:
        return self.state.copy()

    def release(self) -> None:
        """Nothing to free: the state is a numpy array."""


class ParticleComponent(Component):
    """Marks an entity as the picture of particle ``index``: its translation follows that particle."""

    def __init__(self, index: int) -> None:
        self.index = int(index)


class ParticleSystem(System):
    """Steps the kernel with a fixed time step (``params.dt``) as often as the frame's time asks, then moves every
    particle's cube: the fountain runs at the same speed at 30, 60 or 144 frames a second.

    The steps owed carry over between frames. After a long hitch at most :attr:`max_steps` steps run in one frame
    (so a stall cannot snowball); the simulated time left out is added to :attr:`dropped_time` and reported once
    with a warning, never dropped silently. The seed changes every step.
    """

    #: The most kernel steps one frame may run (catching up after a slow frame).
    max_steps = 8

    def __init__(self, kernel: ParticleKernel, params: SimParams = SimParams()) -> None:
        super().__init__((ParticleComponent, TransformComponent))
        self.kernel, self.params, self.steps = kernel, params, 0
        self.owed = 0.0  # simulated seconds not stepped yet (less than one step, unless a frame hit max_steps)
        self.dropped_time = 0.0
        self._positions: np.ndarray | None = None

    def on_update_system(self, ts: float) -> None:
        dt = self.params.dt
        self.owed += ts
        steps = int(self.owed / dt + 1e-6)  # the tolerance keeps 60 steps of 1/60 s from rounding down to 59
        if steps > self.max_steps:
            dropped = (steps - self.max_steps) * dt
            if self.dropped_time == 0.0:
                warnings.warn(f"particles: a frame of {ts:.3f} s needs {steps} steps of {dt:.4f} s; running "
                              f"{self.max_steps} and dropping {dropped:.3f} s of simulated time "
                              "(ParticleSystem.dropped_time adds it up)", stacklevel=2)
            self.dropped_time += dropped
            self.owed -= dropped
            steps = self.max_steps
        for _ in range(steps):
            self.kernel.step(SimParams(**{**self.params.__dict__, "seed": self.steps}))
            self.steps += 1
        self.owed = max(0.0, self.owed - steps * dt)
        if steps or self._positions is None:
            self._positions = self.kernel.read()[:, 0, :3].astype(np.float64)
        super().on_update_system(ts)  # then on_update_entity for every particle's cube

    def on_destroy_system(self) -> None:
        self.kernel.release()

    def on_update_entity(self, ts: float, entity: uuid.UUID, components: tuple[Any, ...]) -> None:
        particle, transform = components
        transform.translation = self._positions[particle.index]
