// Colour by height and slope (grass, rock, snow), lit by the engine's
// lights, faded into the haze with distance. The same maths as
// terrain_shading.wgsl: both APIs shade every fragment from its uv alone.
vec3 terrain_albedo(float h, vec3 n) {
    vec3 grass = vec3(0.060, 0.150, 0.030);
    vec3 rock = vec3(0.180, 0.150, 0.120);
    vec3 snow = vec3(0.780, 0.800, 0.850);
    vec3 color = mix(rock, grass, smoothstep(0.80, 0.90, n.y));
    return mix(color, snow, smoothstep(0.64, 0.72, h) * smoothstep(0.55, 0.75, n.y));
}

vec3 shade_terrain(float h, vec3 n, vec3 world, vec3 haze) {
    vec3 light = u_ambient.rgb;
    for (int i = 0; i < u_light_count.x; ++i) {
        vec4 p = u_light_position[i];
        vec3 l = p.w == 0.0 ? normalize(p.xyz) : normalize(p.xyz - world);
        light += u_light_color[i].rgb * max(dot(n, l), 0.0);
    }
    float fog = 1.0 - exp(-0.02 * distance(world, u_camera_position.xyz));
    return mix(terrain_albedo(h, n) * light, haze, fog);
}
