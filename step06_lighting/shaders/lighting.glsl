// All lights of the Lights block at one surface point: ambient + the sum
// of blinn_phong() over the lights. blinn_phong() comes from
// shading.glsl, which the variant file finds in exercises/ or solutions/.
#include "light_sample.glsl"  // light_at(): the engine's, one light seen from p
#include "shading.glsl"

// --8<-- [start:lights]
vec3 shade(vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess) {
    vec3 color = u_ambient.rgb * albedo;
    int count = min(u_light_count.x, MAX_LIGHTS);
    for (int i = 0; i < count; ++i) {
        vec3 l, radiance;
        light_at(i, p, n, l, radiance);
        color += blinn_phong(n, l, v, radiance, albedo, specular, shininess);
    }
    return color;
}
// --8<-- [end:lights]

// A unit vector from a possibly unnormalised (or zero) one: interpolated normals can cancel out.
vec3 safe_normalize(vec3 v, vec3 fallback) {
    float len = length(v);
    return len > 1e-12 ? v / len : fallback;
}
