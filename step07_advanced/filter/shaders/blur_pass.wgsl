// One pass of the separable blur: every invocation writes one pixel with the student's blur_pass.
// --8<-- [start:kernel]
#include "io.wgsl"
#include "convolve.wgsl"

@compute @workgroup_size(16, 16)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let p = vec2<i32>(id.xy);
    if (any(p >= image_size())) {
        return;  // the last groups hang over the image's edge
    }
    textureStore(dst, p, blur_pass(p, params.direction, params.radius));
}
// --8<-- [end:kernel]
