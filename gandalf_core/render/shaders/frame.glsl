// Per-frame uniforms (binding 0) and lights (binding 1): the same bytes as frame.wgsl
// (packed in gandalf_core/render/frame.py and gandalf_core/systems/light_system.py).
layout(std140) uniform Frame {
    mat4 u_view;
    mat4 u_projection;
    vec4 u_camera_position;
    vec4 u_time;               // x: seconds since start, wrapped every 1024 s;
                               // y: this frame's step; z: wraps
    mat4 u_clip_to_direction;  // clip-space point on the far plane -> world direction (skyboxes)
    vec4 u_depth;              // x: NDC depth of the near plane, y: of the far plane
    vec4 u_origin_high;        // xyz: the world position positions are relative
                               // to (the camera), float32 part
    vec4 u_origin_low;         // xyz: the rest of it (absolute position = relative + high + low)
};

#define MAX_LIGHTS 64
layout(std140) uniform Lights {
    ivec4 u_light_count;                // x: number of lights in use
    vec4 u_ambient;                     // rgb: ambient light (linear)
    vec4 u_light_position[MAX_LIGHTS];  // xyz: position (w = 1) or direction
                                        // towards the light (w = 0)
    vec4 u_light_color[MAX_LIGHTS];     // rgb: linear colour × intensity, a: range (0 = no falloff)
    mat4 u_light_view_projection;       // world -> clip space of the shadow-casting light
    vec4 u_shadow;                      // x: 1 = shadow map on, y: depth bias,
                                        // z: 1 / map size, w: light index
};

// A world position made relative to the camera, as every position the engine hands the GPU is
// (instance rows, lights): for shaders that build absolute world positions themselves
// (a terrain at the world's origin).
vec3 world_to_relative(vec3 p) { return p - u_origin_high.xyz - u_origin_low.xyz; }
