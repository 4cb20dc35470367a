// One blur pass, tiled: a work group loads TILE pixels + an apron of radius
// on each side, for ROWS lines, into workgroup memory once, then every
// invocation reads its 2r + 1 taps from there instead of from the texture.
// --8<-- [start:tiled]
#include "io.wgsl"

const TILE: i32 = 64;
const ROWS: i32 = 4;
const MAX_RADIUS: i32 = 32;

var<workgroup> tile: array<array<vec4<f32>, 128>, 4>;  // [ROWS][TILE + 2 * MAX_RADIUS]: 8 KiB

@compute @workgroup_size(64, 4)
fn cs_main(@builtin(local_invocation_id) lid: vec3<u32>, @builtin(workgroup_id) gid: vec3<u32>) {
    let along = params.direction;
    let across = params.direction.yx;  // the pass direction and the one across it
    let size = image_size();
    let n_along = size.x * along.x + size.y * along.y;
    let n_across = size.x * across.x + size.y * across.y;
    let r = params.radius;
    let l = i32(lid.x);
    let row = i32(lid.y);
    let base = i32(gid.x) * TILE;            // first pixel of the tile along the pass
    let line = i32(gid.y) * ROWS + row;      // this invocation's line across the pass
    let line_c = min(line, n_across - 1);
    for (var k = l; k < TILE + 2 * r; k += TILE) {  // the tile and its apron, clamp-to-edge
        let a = clamp(base + k - r, 0, n_along - 1);
        tile[row][k] = textureLoad(src, along * a + across * line_c, 0);
    }
    workgroupBarrier();  // every load of the group is done before anyone reads the tile
    let a = base + l;
    if (a >= n_along || line >= n_across) {
        return;
    }
    var sum = vec4<f32>(0.0);
    for (var i = -r; i <= r; i++) {
        sum += weights[i + r] * tile[row][l + r + i];
    }
    textureStore(dst, along * a + across * line, sum);
}
// --8<-- [end:tiled]
