// GPU-driven motion: each instance's rows turned by its spin, written where the draw reads its instance rows.
// base: the instance rows the CPU uploaded (3 vec4 an instance: the affine rows of the model matrix, translation
// in .w, camera-relative). motion: 2 vec4 an instance: (world axis, speed rad/s), (phase rad, 0, 0, 0).
// The turned model is R(axis, speed * time + phase) * M: the 3x3 part turns, the translation stays.
// params.time: seconds since the motion's epoch (under 1024 s: float32 keeps 1e-4 s); params.count: instances.
#include "motion_params.wgsl"
@group(0) @binding(1) var<storage, read> base: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> motion: array<vec4<f32>>;
@group(0) @binding(3) var<storage, read_write> moved: array<vec4<f32>>;

@compute @workgroup_size(64)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if (i >= params.count) { return; }
    let r0 = base[3u * i];
    let r1 = base[3u * i + 1u];
    let r2 = base[3u * i + 2u];
    let spin = motion[2u * i];
    let angle = spin.w * params.time + motion[2u * i + 1u].x;
    let a = spin.xyz;
    let c = cos(angle);
    let s = sin(angle);
    let k = 1.0 - c;
    // Rodrigues' rotation, row by row: R = c I + k a a^T + s [a]x
    let q0 = vec3<f32>(c + k * a.x * a.x, k * a.x * a.y - s * a.z, k * a.x * a.z + s * a.y);
    let q1 = vec3<f32>(k * a.y * a.x + s * a.z, c + k * a.y * a.y, k * a.y * a.z - s * a.x);
    let q2 = vec3<f32>(k * a.z * a.x - s * a.y, k * a.z * a.y + s * a.x, c + k * a.z * a.z);
    moved[3u * i] = vec4<f32>(q0.x * r0.xyz + q0.y * r1.xyz + q0.z * r2.xyz, r0.w);
    moved[3u * i + 1u] = vec4<f32>(q1.x * r0.xyz + q1.y * r1.xyz + q1.z * r2.xyz, r1.w);
    moved[3u * i + 2u] = vec4<f32>(q2.x * r0.xyz + q2.y * r1.xyz + q2.z * r2.xyz, r2.w);
}
