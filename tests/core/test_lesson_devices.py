"""The plain-wgpu lesson files ask their device for WebGPU's default limits, not for all the adapter has.

wgpu's ``request_device_sync()`` without limits requests every limit at the adapter's maximum (lavapipe offers
textures of 16384², the defaults 8192²): a lesson that silently used more would run here and fail on a student's
laptop or in a browser. Each lesson runs for real here, and the limits of the device it made are read back; a need
beyond what the adapter has is refused before the device, naming the lesson and the gap.
"""

from __future__ import annotations

import importlib

import pytest
import wgpu

from gandalf_core.render.capabilities import WEBGPU_DEFAULT_LIMITS, CapabilityError, Needs
from gandalf_tools import lesson

LESSONS = ["step01_window.clear_wgpu", "step02_triangle.vertex_buffer_wgpu", "step03_textures.texture_wgpu",
           "step04_camera.uniforms_wgpu", "step06_lighting.lights.lights_wgpu"]


@pytest.fixture
def devices(monkeypatch):
    """The (adapter limits, device limits) of every device requested while the test runs."""
    made = []
    adapter_class = type(wgpu.gpu.request_adapter_sync(power_preference="high-performance"))
    request = adapter_class.request_device_sync

    def recording(self, *args, **kwargs):
        device = request(self, *args, **kwargs)
        made.append((dict(self.limits), dict(device.limits)))
        return device

    monkeypatch.setattr(adapter_class, "request_device_sync", recording)
    return made


@pytest.mark.parametrize("name", LESSONS)
def test_the_lesson_device_has_the_default_limits(name, devices):
    importlib.import_module(name).render(16, 16)
    assert len(devices) == 1, f"{name} requested {len(devices)} devices"
    offered, got = devices[0]
    for limit, default in WEBGPU_DEFAULT_LIMITS.items():
        expected = max(default, offered[limit]) if limit.startswith("min-") else min(default, offered[limit])
        assert got[limit] == expected, f"{name}: {limit} is {got[limit]} (WebGPU's default {default}, " \
                                       f"this adapter {offered[limit]})"


def test_a_lesson_that_needs_more_than_the_adapter_has_says_so():
    adapter = wgpu.gpu.request_adapter_sync(power_preference="high-performance")
    huge = int(adapter.limits["max-texture-dimension-2d"]) * 2
    needs = Needs(limits={"max-texture-dimension-2d": huge}, webgpu_for="a huge texture")
    with pytest.raises(CapabilityError, match=rf"step99\.lesson needs WebGPU's max-texture-dimension-2d of {huge}"):
        lesson.webgpu_limits(adapter, "step99.lesson", needs)
