// Exercise 2: decoding a tangent-space normal map in GLSL
// (included by the step's normal-mapped shaders). Returns magenta
// until you write it. Keep it free of NaN for any input.
// A wrong or black picture? `python -m step07_advanced.opengl --technique parallax --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").

// The shading normal (unit, world space) for the unit interpolated normal n, the world-space
// tangent (xyz: along +u, w: ±1 handedness) and a normal-map texel map_rgb in [0, 1]³
// (green = up, glTF style):
//   m = map_rgb * 2 - 1;  T = tangent.xyz made orthogonal to n and normalised;
//   B = cross(n, T) * sign(w)
//   result = normalize(T m.x + B m.y + n m.z)
// When T has no usable length take any unit vector perpendicular to
// n; when the result has none, return n.
vec3 perturb_normal(vec3 n, vec4 tangent, vec3 map_rgb) {
    return vec3(1.0, 0.0, 1.0);
}
