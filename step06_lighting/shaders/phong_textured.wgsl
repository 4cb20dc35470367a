// Blinn-Phong whose albedo is the material colour times its texture.
#include "frame.wgsl"
#include "instance.wgsl"
#include "lighting.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var albedo_texture: texture_2d<f32>;
@group(1) @binding(2) var albedo_sampler: sampler;

struct TexturedOut {
    @builtin(position) position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
};

@vertex
fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
           @location(2) uv: vec2<f32>, inst: Instance) -> TexturedOut {
    let world = instance_model(inst) * vec4<f32>(position, 1.0);
    var out: TexturedOut;
    out.position = frame.projection * frame.view * world;
    out.world = world.xyz;
    out.normal = instance_normal(inst, normal);
    out.uv = uv;
    return out;
}

@fragment
fn fs_main(in: TexturedOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let v = safe_normalize(frame.camera_position.xyz - in.world, n);
    let albedo = material.color.rgb * textureSample(albedo_texture, albedo_sampler, in.uv).rgb;
    return vec4<f32>(shade(in.world, n, v, albedo, material.specular, material.shininess), 1.0);
}
