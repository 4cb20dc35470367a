"""Reference solution of the integrator exercise: the lesson's own implementations."""

from ..integrators import rk4_step, semi_implicit_euler_step

__all__ = ["rk4_step", "semi_implicit_euler_step"]
