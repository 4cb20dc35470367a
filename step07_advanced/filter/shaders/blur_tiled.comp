#version 430
// One blur pass, tiled: a work group loads TILE pixels + an apron of u_radius on each side, for
// ROWS lines, into shared memory once, then every invocation reads its 2r + 1 taps from there
// instead of from the texture.
// --8<-- [start:tiled]
#define TILE 64
#define ROWS 4
#define MAX_RADIUS 32
layout(local_size_x = TILE, local_size_y = ROWS) in;
#include "io.glsl"
layout(OUT_FORMAT, binding = 0) writeonly uniform image2D u_dst;

shared vec4 tile[ROWS][TILE + 2 * MAX_RADIUS];  // (64 + 64) * 4 * 16 B = 8 KiB

void main() {
    ivec2 along = u_direction, across = u_direction.yx;  // the pass direction and the one across it
    ivec2 size = image_size();
    int n_along = size.x * along.x + size.y * along.y,
        n_across = size.x * across.x + size.y * across.y;
    int l = int(gl_LocalInvocationID.x), row = int(gl_LocalInvocationID.y);
    int base = int(gl_WorkGroupID.x) * TILE;                 // first pixel of the tile
                                                             // along the pass
    int line = int(gl_WorkGroupID.y) * ROWS + row;           // this invocation's line
                                                             // across the pass
    int line_c = min(line, n_across - 1);
    for (int k = l; k < TILE + 2 * u_radius; k += TILE) {  // the tile and its apron, clamp-to-edge
        int a = clamp(base + k - u_radius, 0, n_along - 1);
        tile[row][k] = texelFetch(u_src, along * a + across * line_c, 0);
    }
    barrier();  // every load of the group is done (and visible) before anyone reads the tile
    int a = base + l;
    if (a >= n_along || line >= n_across) return;
    vec4 sum = vec4(0.0);
    for (int i = -u_radius; i <= u_radius; ++i)
        sum += weights[i + u_radius] * tile[row][l + u_radius + i];
    imageStore(u_dst, along * a + across * line, sum);
}
// --8<-- [end:tiled]
