// One light of the lights block seen from a surface point: the unit vector towards it and the radiance that
// arrives. A point light (position.w = 1) falls off with the inverse square, windowed to reach exactly zero at
// its range (colour.a; 0 = no range, no falloff); a directional light (w = 0) holds a unit vector towards the
// light and does not fall off. Used by the built-in lit material and by the lit shaders of steps 06 and 07.
#include "frame.wgsl"

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
    let distance = length(d);
    let l = select(n, d / max(distance, 1e-6), distance > 1e-6);
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
