// Per-frame uniforms, the same bytes as frame.glsl (see gandalf_core/render/frame.py).
struct Frame {
    view: mat4x4<f32>,
    projection: mat4x4<f32>,
    camera_position: vec4<f32>,
    time: vec4<f32>,  // x: seconds since start, y: this frame's time step
};
@group(0) @binding(0) var<uniform> frame: Frame;
