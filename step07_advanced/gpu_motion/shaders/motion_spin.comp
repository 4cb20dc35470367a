#version 430
// GPU-driven motion: each instance's rows turned by its spin, written where the draw reads its instance rows.
// base: the instance rows the CPU uploaded (3 vec4 an instance: the affine rows of the model matrix, translation
// in .w, camera-relative). motion: 2 vec4 an instance: (world axis, speed rad/s), (phase rad, 0, 0, 0).
// The turned model is R(axis, speed * time + phase) * M: the 3x3 part turns, the translation stays.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Base { vec4 base[]; };
layout(std430, binding = 1) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = 2) writeonly buffer Moved { vec4 moved[]; };
// u_time: seconds since the motion's epoch (under 1024 s: float32 keeps 1e-4 s); u_count: instances.
#include "motion_params.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_count) { return; }
    vec4 r0 = base[3u * i], r1 = base[3u * i + 1u], r2 = base[3u * i + 2u];
    vec4 spin = motion[2u * i];
    float angle = spin.w * u_time + motion[2u * i + 1u].x;
    vec3 a = spin.xyz;
    float c = cos(angle), s = sin(angle), k = 1.0 - c;
    // Rodrigues' rotation, row by row: R = c I + k a a^T + s [a]x
    vec3 q0 = vec3(c + k * a.x * a.x, k * a.x * a.y - s * a.z, k * a.x * a.z + s * a.y);
    vec3 q1 = vec3(k * a.y * a.x + s * a.z, c + k * a.y * a.y, k * a.y * a.z - s * a.x);
    vec3 q2 = vec3(k * a.z * a.x - s * a.y, k * a.z * a.y + s * a.x, c + k * a.z * a.z);
    moved[3u * i] = vec4(q0.x * r0.xyz + q0.y * r1.xyz + q0.z * r2.xyz, r0.w);
    moved[3u * i + 1u] = vec4(q1.x * r0.xyz + q1.y * r1.xyz + q1.z * r2.xyz, r1.w);
    moved[3u * i + 2u] = vec4(q2.x * r0.xyz + q2.y * r1.xyz + q2.z * r2.xyz, r2.w);
}
