// One light of the lights block seen from a surface point: the unit vector towards it and the radiance that
// arrives. A point light (position.w = 1) falls off with the inverse square, windowed to reach exactly zero at
// its range (colour.a; 0 = no range, no falloff); a directional light (w = 0) holds a unit vector towards the
// light and does not fall off. Used by the built-in lit material and by the lit shaders of steps 06 and 07.
#include "frame.wgsl"

// Length and direction that neither underflow nor overflow: the vector is first divided by its largest
// component (no squares of 1e-20 or 1e20), so a scene at any scale shades alike. safe_normalize returns
// `fallback` for a zero, infinite or NaN vector (interpolated normals can cancel out).
fn safe_length(v: vec3<f32>) -> f32 {
    let a = abs(v);
    let s = max(max(a.x, a.y), a.z);
    let finite = s > 0.0 && s <= 3.4028235e38;
    return select(s, s * length(v / select(1.0, s, finite)), finite);
}
fn safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len = safe_length(v);
    let usable = len > 0.0 && len <= 3.4028235e38;
    return select(fallback, v / select(1.0, len, usable), usable);
}

// --8<-- [start:light_at]
struct LightSample {
    l: vec3<f32>,         // unit direction towards the light
    radiance: vec3<f32>,  // colour × intensity × distance falloff
};

// A point light exactly at p lights it head-on (l = n) instead of normalising a zero vector.
fn light_at(i: i32, p: vec3<f32>, n: vec3<f32>) -> LightSample {
    let position = lights.position[i];
    let color = lights.color[i];
    if (position.w < 0.5) {
        return LightSample(position.xyz, color.rgb);  // directional: already a unit
                                                      // vector towards the light
    }
    let d = position.xyz - p;
    let distance = safe_length(d);
    let l = safe_normalize(d, n);
    var radiance = color.rgb;
    if (color.a > 0.0) {
        // Windowed inverse square (glTF's punctual lights): fades to exactly zero at the range.
        let x = distance / color.a;
        let window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        radiance *= window * window / max(distance * distance, 1e-4);
    }
    return LightSample(l, radiance);
}
// --8<-- [end:light_at]
