// Exercise hit_sphere (step07 path tracer), GLSL: the nearest intersection of a ray with a sphere.
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
float hit_sphere(vec3 origin, vec3 dir, vec3 center, float radius, float t_min, float t_max) {
    float a = dot(dir, dir);
    vec3 oc = origin - center;
    float half_b = dot(oc, dir);
    vec3 to_line = oc - (half_b / a) * dir;
    float discriminant = a * (radius * radius - dot(to_line, to_line));
    if (discriminant < 0.0) {
        return -1.0;
    }
    float len = length(oc);
    float c = (len - radius) * (len + radius);
    float q = -(half_b + (half_b >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant));
    float t0 = 0.0;
    float t1 = 0.0;
    if (q != 0.0) {
        t0 = min(c / q, q / a);
        t1 = max(c / q, q / a);
    }
    if (t0 > t_min && t0 < t_max) {
        return t0;
    }
    if (t1 > t_min && t1 < t_max) {
        return t1;
    }
    return -1.0;
}
