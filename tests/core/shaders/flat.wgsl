// Test shader: the material colour.
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@vertex fn vs_main(@location(0) position: vec3<f32>,
    inst: Instance) -> @builtin(position) vec4<f32> {
    return frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return material.color; }
