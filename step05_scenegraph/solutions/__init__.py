"""Step 05 reference solutions (same API as ``exercises``)."""


from .house import (
    ORANGE,
    HouseRotationSystem,
    brick_texture_data,
    house_camera,
    house_material_data,
    house_meshes,
)
from .integrators import rk4_step, semi_implicit_euler_step

__all__ = [
    "ORANGE",
    "HouseRotationSystem",
    "brick_texture_data",
    "house_camera",
    "house_material_data",
    "house_meshes",
    "rk4_step",
    "semi_implicit_euler_step",
]

