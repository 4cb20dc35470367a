// The vertex stage of the step's surface shaders
// (pbr, bumpy, normal_view): world position, normal, UV, tangent.
#include "frame.wgsl"
#include "instance.wgsl"

struct SurfaceOut {
    @builtin(position) position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @location(3) tangent: vec4<f32>,
};

@vertex
fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
           @location(2) uv: vec2<f32>, @location(3) tangent: vec4<f32>,
           inst: Instance) -> SurfaceOut {
    let model = instance_model(inst);
    let world = model * vec4<f32>(position, 1.0);
    var out: SurfaceOut;
    out.position = frame.projection * frame.view * world;
    out.world = world.xyz;
    out.normal = instance_normal(inst, normal);
    out.uv = uv;
    // A tangent lies in the surface, so it follows the model matrix itself
    // (normals need the cofactor).
    out.tangent = vec4<f32>((model * vec4<f32>(tangent.xyz, 0.0)).xyz, tangent.w);
    return out;
}
