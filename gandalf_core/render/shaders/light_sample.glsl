// One light of the lights block seen from a surface point: the unit vector towards it and the radiance that
// arrives. A point light (position.w = 1) falls off with the inverse square, windowed to reach exactly zero at
// its range (colour.a; 0 = no range, no falloff); a directional light (w = 0) holds a unit vector towards the
// light and does not fall off. Used by the built-in lit material and by the lit shaders of steps 06 and 07.
#include "frame.glsl"

// Length and direction that neither underflow nor overflow: the vector is first divided by its largest
// component (no squares of 1e-20 or 1e20), so a scene at any scale shades alike. safe_normalize returns
// `fallback` for a zero, infinite or NaN vector (interpolated normals can cancel out).
float safe_length(vec3 v) {
    vec3 a = abs(v);
    float s = max(max(a.x, a.y), a.z);
    return s > 0.0 && s <= 3.4028235e38 ? s * length(v / s) : s;
}
vec3 safe_normalize(vec3 v, vec3 fallback) {
    float len = safe_length(v);
    return len > 0.0 && len <= 3.4028235e38 ? v / len : fallback;
}

// --8<-- [start:light_at]
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
    float distance = safe_length(d);
    l = safe_normalize(d, n);
    if (color.a > 0.0) {
        // Windowed inverse square (glTF's punctual lights): fades to exactly zero at the range.
        float x = distance / color.a;
        float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        radiance *= window * window / max(distance * distance, 1e-4);
    }
}
// --8<-- [end:light_at]
