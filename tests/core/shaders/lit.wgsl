// Test shader: Lambert lighting from the lights block.
#include "lit_vertex.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@fragment fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    var c = lights.ambient.rgb * material.color.rgb;
    for (var i = 0; i < lights.count.x; i++) {
        c += material.color.rgb * lights.color[i].rgb
            * max(dot(n, normalize(lights.position[i].xyz)), 0.0);
    }
    return vec4<f32>(c, 1.0);
}
