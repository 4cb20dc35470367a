// Test shader: vertex pulling. Each vertex reads its position from a
// storage buffer by vertex_index.
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var<storage, read> positions: array<vec4<f32>>;
@vertex fn vs_main(@builtin(vertex_index) index: u32,
    inst: Instance) -> @builtin(position) vec4<f32> {
    return frame.projection * frame.view * instance_model(inst) * vec4<f32>(positions[index].xyz,
        1.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> { return material.color; }
