// Step 07 path tracer, GLSL: closest hit over the spheres
// (the student's hit_sphere) and the triangles (a BVH with a short stack),
// and the path loop with the three materials. trace.wgsl is the same in WGSL.
const float T_MIN = 1e-4;
const float T_FAR = 1e30;
const float RAY_OFFSET = 5e-4;
const uint LAMBERT = 0u;
const uint METAL = 1u;
const uint GLASS = 2u;
const int STACK_SIZE = 32;

struct Hit {
    float t;
    vec3 normal;    // unit, outward: (p - centre) / radius, or the
                    // triangle's normal on its counter-clockwise side
    uint material;
};

bool is_finite(float x) {
    return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;
}

// Slab test: does the ray meet the box between T_MIN and t_max?
bool hit_box(vec3 origin, vec3 inv_dir, vec3 bmin, vec3 bmax, float t_max) {
    vec3 t0 = (bmin - origin) * inv_dir;
    vec3 t1 = (bmax - origin) * inv_dir;
    vec3 lo = min(t0, t1);
    vec3 hi = max(t0, t1);
    float enter = max(max(lo.x, lo.y), max(lo.z, T_MIN));
    float leave = min(min(hi.x, hi.y), min(hi.z, t_max));
    return enter <= leave;
}

// Möller–Trumbore: (t, u, v) with t = -1 for a miss; the hit point is (1 - u - v) p0 + u p1 + v p2.
vec3 hit_triangle(vec3 origin, vec3 dir, vec3 p0, vec3 p1, vec3 p2, float t_max) {
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    vec3 pv = cross(dir, e2);
    float det = dot(e1, pv);
    if (abs(det) < 1e-12) {
        return vec3(-1.0);
    }
    float inv_det = 1.0 / det;
    vec3 tv = origin - p0;
    float u = dot(tv, pv) * inv_det;
    if (u < 0.0 || u > 1.0) {
        return vec3(-1.0);
    }
    vec3 qv = cross(tv, e1);
    float v = dot(dir, qv) * inv_det;
    if (v < 0.0 || u + v > 1.0) {
        return vec3(-1.0);
    }
    float t = dot(e2, qv) * inv_det;
    if (!(t > T_MIN && t < t_max)) {
        return vec3(-1.0);
    }
    return vec3(t, u, v);
}

// --8<-- [start:trace]
bool trace(vec3 origin, vec3 dir, out Hit hit) {
    hit.t = T_FAR;
    hit.normal = vec3(0.0, 1.0, 0.0);
    hit.material = 0u;
    for (uint i = 0u; i < u_counts.x; i++) {
        vec4 s = spheres[2u * i];
        float t = hit_sphere(origin, dir, s.xyz, s.w, T_MIN, hit.t);  // the student's function
        if (t > T_MIN && t < hit.t) {
            hit.t = t;
            hit.normal = (origin + t * dir - s.xyz) / s.w;
            hit.material = uint(spheres[2u * i + 1u].x);
        }
    }
    if (u_counts.z == 0u) {
        return hit.t < T_FAR;
    }
    // No division by zero: a zero direction component becomes a tiny one of the same sign.
    vec3 sign_dir = vec3(greaterThanEqual(dir, vec3(0.0))) * 2.0 - 1.0;
    vec3 inv_dir = 1.0 / mix(dir, sign_dir * 1e-12, lessThan(abs(dir), vec3(1e-12)));
    uint stack[STACK_SIZE];
    int top = 0;
    stack[top++] = 0u;
    while (top > 0) {
        uint node = stack[--top];
        vec4 lo = nodes[2u * node];
        vec4 hi = nodes[2u * node + 1u];
        if (!hit_box(origin, inv_dir, lo.xyz, hi.xyz, hit.t)) {
            continue;
        }
        uint count = uint(hi.w);
        uint index = uint(lo.w);
        if (count == 0u) {  // inner node: its left child follows it, lo.w is the right child
            if (top <= STACK_SIZE - 2) {
                stack[top++] = index;
                stack[top++] = node + 1u;
            }
            continue;
        }
        for (uint k = index; k < index + count; k++) {
            vec4 p0 = triangles[6u * k];
            vec3 tuv = hit_triangle(origin, dir, p0.xyz, triangles[6u * k + 1u].xyz,
                                    triangles[6u * k + 2u].xyz, hit.t);
            if (tuv.x > 0.0) {
                float w = 1.0 - tuv.y - tuv.z;
                vec3 n = w * triangles[6u * k + 3u].xyz + tuv.y * triangles[6u * k + 4u].xyz
                       + tuv.z * triangles[6u * k + 5u].xyz;
                hit.t = tuv.x;
                hit.normal = normalize(n);
                hit.material = uint(p0.w);
            }
        }
    }
    return hit.t < T_FAR;
}
// --8<-- [end:trace]

// --8<-- [start:path]
vec3 path_radiance(vec3 origin, vec3 dir, inout uint rng) {
    vec3 throughput = vec3(1.0);
    vec3 radiance = vec3(0.0);
    for (uint bounce = 0u; bounce <= u_counts.w; bounce++) {
        Hit hit;
        if (!trace(origin, dir, hit)) {
            radiance = throughput * sky_radiance(dir);  // the only light: the sky
            break;
        }
        if (bounce == u_counts.w) {
            break;  // too many bounces: the path carries no light
        }
        vec4 m0 = materials[2u * hit.material];
        vec4 m1 = materials[2u * hit.material + 1u];
        uint kind = uint(m0.w);
        vec3 facing = dot(dir, hit.normal) < 0.0 ? hit.normal : -hit.normal;
        vec3 next;
        if (kind == LAMBERT) {
            next = facing + random_unit_vector(rng);  // cosine-weighted around the normal
            if (dot(next, next) < 1e-12) {
                next = facing;
            }
        } else if (kind == METAL) {
            next = reflect(dir, facing) + m1.x * random_in_unit_sphere(rng);  // m1.x: fuzz
            if (dot(next, facing) <= 0.0) {
                next = vec3(0.0);  // fuzzed below the surface: absorbed
            }
        } else {
            // the student's function
            next = scatter_dielectric(dir, hit.normal, m1.y, rng_next(rng));
        }
        float len2 = dot(next, next);
        if (!(len2 > 1e-12) || !is_finite(len2)) {
            break;  // absorbed (a zero or broken direction)
        }
        throughput *= m0.rgb;
        // Start the next ray a little off the surface, on the side it leaves
        // to: float32 knows a point on a sphere 1000 units from its centre
        // only to ~1e-4, and a ray must not hit the surface it starts on.
        vec3 p = origin + hit.t * dir;
        dir = next / sqrt(len2);
        origin = p + (dot(dir, facing) > 0.0 ? facing : -facing) * RAY_OFFSET;
    }
    bool finite = is_finite(radiance.r) && is_finite(radiance.g) && is_finite(radiance.b);
    return finite ? radiance : vec3(0.0);
}
// --8<-- [end:path]
