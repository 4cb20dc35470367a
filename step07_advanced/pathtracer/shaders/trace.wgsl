// Step 07 path tracer, WGSL: closest hit over the spheres
// (the student's hit_sphere) and the triangles (a BVH with a short stack),
// and the path loop with the three materials. trace.glsl is the same in GLSL.
const T_MIN: f32 = 1e-4;
const T_FAR: f32 = 1e30;
const RAY_OFFSET: f32 = 5e-4;
const LAMBERT: u32 = 0u;
const METAL: u32 = 1u;
const GLASS: u32 = 2u;
const STACK_SIZE: i32 = 32;

struct Hit {
    t: f32,
    normal: vec3<f32>,  // unit, outward: (p - centre) / radius, or the
                        // triangle's normal on its counter-clockwise side
    material: u32,
};

fn is_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7f800000u) != 0x7f800000u;
}

// Slab test: does the ray meet the box between T_MIN and t_max?
fn hit_box(origin: vec3<f32>, inv_dir: vec3<f32>, bmin: vec3<f32>, bmax: vec3<f32>,
    t_max: f32) -> bool {
    let t0 = (bmin - origin) * inv_dir;
    let t1 = (bmax - origin) * inv_dir;
    let lo = min(t0, t1);
    let hi = max(t0, t1);
    let enter = max(max(lo.x, lo.y), max(lo.z, T_MIN));
    let leave = min(min(hi.x, hi.y), min(hi.z, t_max));
    return enter <= leave;
}

// Möller–Trumbore: (t, u, v) with t = -1 for a miss; the hit point is (1 - u - v) p0 + u p1 + v p2.
fn hit_triangle(origin: vec3<f32>, dir: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
                t_max: f32) -> vec3<f32> {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let pv = cross(dir, e2);
    let det = dot(e1, pv);
    if (abs(det) < 1e-12) {
        return vec3<f32>(-1.0);
    }
    let inv_det = 1.0 / det;
    let tv = origin - p0;
    let u = dot(tv, pv) * inv_det;
    if (u < 0.0 || u > 1.0) {
        return vec3<f32>(-1.0);
    }
    let qv = cross(tv, e1);
    let v = dot(dir, qv) * inv_det;
    if (v < 0.0 || u + v > 1.0) {
        return vec3<f32>(-1.0);
    }
    let t = dot(e2, qv) * inv_det;
    if (!(t > T_MIN && t < t_max)) {
        return vec3<f32>(-1.0);
    }
    return vec3<f32>(t, u, v);
}

// --8<-- [start:trace]
fn trace(origin: vec3<f32>, dir: vec3<f32>, hit: ptr<function, Hit>) -> bool {
    (*hit).t = T_FAR;
    (*hit).normal = vec3<f32>(0.0, 1.0, 0.0);
    (*hit).material = 0u;
    for (var i = 0u; i < params.counts.x; i++) {
        let s = spheres[2u * i];
        let t = hit_sphere(origin, dir, s.xyz, s.w, T_MIN, (*hit).t);  // the student's function
        if (t > T_MIN && t < (*hit).t) {
            (*hit).t = t;
            (*hit).normal = (origin + t * dir - s.xyz) / s.w;
            (*hit).material = u32(spheres[2u * i + 1u].x);
        }
    }
    if (params.counts.z == 0u) {
        return (*hit).t < T_FAR;
    }
    // No division by zero: a zero direction component becomes a tiny one of the same sign.
    let sign_dir = select(vec3<f32>(-1.0), vec3<f32>(1.0), dir >= vec3<f32>(0.0));
    let inv_dir = 1.0 / select(dir, sign_dir * 1e-12, abs(dir) < vec3<f32>(1e-12));
    var stack: array<u32, STACK_SIZE>;
    var top = 0;
    stack[top] = 0u;
    top++;
    while (top > 0) {
        top--;
        let node = stack[top];
        let lo = nodes[2u * node];
        let hi = nodes[2u * node + 1u];
        if (!hit_box(origin, inv_dir, lo.xyz, hi.xyz, (*hit).t)) {
            continue;
        }
        let count = u32(hi.w);
        let index = u32(lo.w);
        if (count == 0u) {  // inner node: its left child follows it, lo.w is the right child
            if (top <= STACK_SIZE - 2) {
                stack[top] = index;
                stack[top + 1] = node + 1u;
                top += 2;
            }
            continue;
        }
        for (var k = index; k < index + count; k++) {
            let p0 = triangles[6u * k];
            let tuv = hit_triangle(origin, dir, p0.xyz, triangles[6u * k + 1u].xyz,
                                   triangles[6u * k + 2u].xyz, (*hit).t);
            if (tuv.x > 0.0) {
                let w = 1.0 - tuv.y - tuv.z;
                let n = w * triangles[6u * k + 3u].xyz + tuv.y * triangles[6u * k + 4u].xyz
                      + tuv.z * triangles[6u * k + 5u].xyz;
                (*hit).t = tuv.x;
                (*hit).normal = normalize(n);
                (*hit).material = u32(p0.w);
            }
        }
    }
    return (*hit).t < T_FAR;
}
// --8<-- [end:trace]

// --8<-- [start:path]
fn path_radiance(origin_in: vec3<f32>, dir_in: vec3<f32>, rng: ptr<function, u32>) -> vec3<f32> {
    var origin = origin_in;
    var dir = dir_in;
    var throughput = vec3<f32>(1.0);
    var radiance = vec3<f32>(0.0);
    for (var bounce = 0u; bounce <= params.counts.w; bounce++) {
        var hit: Hit;
        if (!trace(origin, dir, &hit)) {
            radiance = throughput * sky_radiance(dir);  // the only light: the sky
            break;
        }
        if (bounce == params.counts.w) {
            break;  // too many bounces: the path carries no light
        }
        let m0 = materials[2u * hit.material];
        let m1 = materials[2u * hit.material + 1u];
        let kind = u32(m0.w);
        let facing = select(-hit.normal, hit.normal, dot(dir, hit.normal) < 0.0);
        var next: vec3<f32>;
        if (kind == LAMBERT) {
            next = facing + random_unit_vector(rng);  // cosine-weighted around the normal
            if (dot(next, next) < 1e-12) {
                next = facing;
            }
        } else if (kind == METAL) {
            next = reflect(dir, facing) + m1.x * random_in_unit_sphere(rng);  // m1.x: fuzz
            if (dot(next, facing) <= 0.0) {
                next = vec3<f32>(0.0);  // fuzzed below the surface: absorbed
            }
        } else {
            // the student's function
            next = scatter_dielectric(dir, hit.normal, m1.y, rng_next(rng));
        }
        let len2 = dot(next, next);
        if (!(len2 > 1e-12) || !is_finite(len2)) {
            break;  // absorbed (a zero or broken direction)
        }
        throughput *= m0.rgb;
        // Start the next ray a little off the surface, on the side it leaves
        // to: float32 knows a point on a sphere 1000 units from its centre
        // only to ~1e-4, and a ray must not hit the surface it starts on.
        let p = origin + hit.t * dir;
        dir = next / sqrt(len2);
        origin = p + select(-facing, facing, dot(dir, facing) > 0.0) * RAY_OFFSET;
    }
    let finite = is_finite(radiance.r) && is_finite(radiance.g) && is_finite(radiance.b);
    return select(vec3<f32>(0.0), radiance, finite);
}
// --8<-- [end:path]
