// Benchmark shader: world-space normal per vertex, Lambert shading in the fragment stage
// (one fixed directional light plus ambient, tinted by the material colour, in linear light).
#include "lit_vertex.wgsl"  // the engine's lit vertex stage
#include "material.wgsl"  // the Material block, declared in Python with the shader
@fragment fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let diffuse = max(dot(normalize(in.normal), normalize(vec3<f32>(0.3, 0.5, 1.0))), 0.0);
    return vec4<f32>(material.color.rgb * (0.15 + 0.85 * diffuse), material.color.a);
}
