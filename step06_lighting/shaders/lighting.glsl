// All lights of the Lights block at one surface point: ambient + the sum
// of blinn_phong() over the lights. blinn_phong() comes from
// shading.glsl, which the variant file finds in exercises/ or solutions/.
#include "frame.glsl"
#include "shading.glsl"

// --8<-- [start:lights]
// Unit direction towards the light and its radiance
// (colour × intensity × distance falloff) at point p. A point light exactly
// at p lights it head-on (l = n) instead of normalising a zero vector.
void light_at(int i, vec3 p, vec3 n, out vec3 l, out vec3 radiance) {
    vec4 position = u_light_position[i];
    vec4 color = u_light_color[i];
    radiance = color.rgb;
    if (position.w < 0.5) {
        l = position.xyz;  // directional: already a unit vector towards the light
        return;
    }
    vec3 d = position.xyz - p;
    float distance = length(d);
    l = distance > 1e-6 ? d / distance : n;
    if (color.a > 0.0) {
        // Windowed inverse square (glTF's punctual lights): fades to exactly zero at the range.
        float x = distance / color.a;
        float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        radiance *= window * window / max(distance * distance, 1e-4);
    }
}

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
