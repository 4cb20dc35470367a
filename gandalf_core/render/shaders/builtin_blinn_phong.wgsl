// Built-in material gandalf.blinn_phong, colour only: the scene's lights on the material colour.
#include "lit_vertex.wgsl"
#include "builtin_lighting.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@fragment fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let lit = gandalf_builtin_lighting(in.world, in.normal, material.color.rgb, material.specular,
        material.shininess);
    return vec4<f32>(lit, material.color.a);
}
