// Per-frame uniforms (binding 0) and lights (binding 1): the same bytes as frame.glsl
// (packed in gandalf_core/render/frame.py and gandalf_core/systems/light_system.py).
struct Frame {
    view: mat4x4<f32>,
    projection: mat4x4<f32>,
    camera_position: vec4<f32>,
    time: vec4<f32>,               // x: seconds since start, wrapped every 1024
                                   // s; y: this frame's step; z: wraps
    clip_to_direction: mat4x4<f32>, // clip-space point on the far plane -> world
                                    // direction (skyboxes)
    depth: vec4<f32>,              // x: NDC depth of the near plane, y: of the far plane
    origin_high: vec4<f32>,        // xyz: the world position positions are relative to
                                   // (the camera), float32 part
    origin_low: vec4<f32>,         // xyz: the rest of it
                                   // (absolute position = relative + high + low)
};
@group(0) @binding(0) var<uniform> frame: Frame;

// A world position made relative to the camera, as every position the engine hands the GPU is
// (instance rows, lights): for shaders that build absolute world positions themselves
// (a terrain at the world's origin).
fn world_to_relative(p: vec3<f32>) -> vec3<f32> {
    return p - frame.origin_high.xyz - frame.origin_low.xyz;
}

const MAX_LIGHTS: u32 = 64u;
struct Lights {
    count: vec4<i32>,                          // x: number of lights in use
    ambient: vec4<f32>,                        // rgb: ambient light (linear)
    position: array<vec4<f32>, MAX_LIGHTS>,    // xyz: position (w = 1) or direction
                                               // towards the light (w = 0)
    color: array<vec4<f32>, MAX_LIGHTS>,       // rgb: linear colour × intensity,
                                               // a: range (0 = no falloff)
    light_view_projection: mat4x4<f32>,        // world -> clip space of the shadow-casting light
    shadow: vec4<f32>,                         // x: 1 = shadow map on, y: depth bias,
                                               // z: 1 / map size, w: light index
};
@group(0) @binding(1) var<uniform> lights: Lights;
