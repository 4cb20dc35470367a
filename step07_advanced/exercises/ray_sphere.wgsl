// Exercise hit_sphere (step07 path tracer), WGSL: the nearest intersection of a ray with a sphere.
// A wrong or black picture? `python -m step07_advanced.webgpu --technique pathtracer --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").
//
// hit_sphere(origin, dir, center, radius, t_min, t_max) -> t
//   The ray is origin + t * dir. dir is any non-zero vector (NOT necessarily unit length): t is in
//   units of dir. Return the smallest root t of |origin + t*dir - center|^2 = radius^2 with
//   t_min < t < t_max (both bounds strict), or exactly -1.0 when there is none
//   (no real root, or both roots outside the range). So a ray that starts inside the sphere returns
//   its far root (the near one is behind it), a sphere behind the ray returns -1.0, and a tangent
//   ray (discriminant exactly 0) hits at its single root. Numerically stable in float32: graded on
//   spheres 10 000 units away and of radius up to 1e5, a hit within
//   2e-5 * (|oc| + radius) / |dir| + 1e-5 * |t| of the exact root. The textbook discriminant
//   half_b^2 - a*c fails there (two numbers near 1e8 subtracted); this way passes:
//     a = dot(dir, dir), oc = origin - center, half_b = dot(oc, dir)     (the half-b form)
//     discriminant = a * (radius^2 - |oc - (half_b / a) * dir|^2)
//                    (= half_b^2 - a*c, but without subtracting two huge numbers:
//                    |oc - (half_b/a) dir| is the distance from the centre to the line)
//     c = (|oc| - radius) * (|oc| + radius)
//     q = -(half_b + sign(half_b) * sqrt(discriminant)), the roots are c / q and q / a
//     (take sign(0) = +1; when q == 0 both roots are 0).
//   Never NaN or inf for a finite ray and sphere.
// The stub misses every sphere (returns -1.0) until you write it.
fn hit_sphere(origin: vec3<f32>, dir: vec3<f32>, center: vec3<f32>, radius: f32, t_min: f32,
    t_max: f32) -> f32 {
    return -1.0;
}
