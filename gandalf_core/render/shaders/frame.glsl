// Per-frame uniforms, the same bytes as frame.wgsl (see gandalf_core/render/frame.py).
layout(std140) uniform Frame {
    mat4 u_view;
    mat4 u_projection;
    vec4 u_camera_position;
    vec4 u_time;  // x: seconds since start, y: this frame's time step
};
