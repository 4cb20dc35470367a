// The material block of this program's stages
// (each includes it: GL needs the same block in every stage).
layout(std140) uniform Material {  // the material's values, the same bytes as WGSL's struct
    vec4 color;
    float explode_time;  // seconds on the explosion clock (set every frame by ExplodeSystem)
    float amount;        // how far a face moves at the peak (world units)
    float period;        // seconds from one whole mesh to the next
    float specular;
    float shininess;
} material;
