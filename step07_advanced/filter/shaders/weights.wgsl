// The weight table on the GPU: one invocation per tap, each calls the student's gaussian_weight.
#include "blur_kernel.wgsl"

#include "filter_params.wgsl"
@group(0) @binding(2) var<storage, read_write> weights: array<f32>;

@compute @workgroup_size(64)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = i32(id.x);
    if (k > 2 * params.radius) {
        return;
    }
    weights[k] = gaussian_weight(k - params.radius, params.radius);
}
