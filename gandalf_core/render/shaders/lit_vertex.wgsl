// The lit vertex stage for meshes drawn without a texture (positions and normals only): LitOut with uv = 0.
// A textured shader includes lit_varyings.wgsl instead and passes its mesh's uv to lit_vertex().
#include "lit_varyings.wgsl"
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>, inst: Instance) -> LitOut {
    return lit_vertex(inst, position, normal, vec2<f32>(0.0));
}
