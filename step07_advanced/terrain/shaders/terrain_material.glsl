// The material block of this program's stages
// (each includes it: GL needs the same block in every stage).
layout(std140) uniform Material {  // the material's values, the same bytes as WGSL's struct
    vec4 color;          // the haze (the sky's colour), linear
    float size;
    float height_scale;
    vec4 lod;            // scale, min level, max level
} material;
