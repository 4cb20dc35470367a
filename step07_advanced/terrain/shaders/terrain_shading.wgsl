// Colour by height and slope (grass, rock, snow), lit by the engine's
// lights, faded into the haze with distance. The same maths as
// terrain_shading.glsl: both APIs shade every fragment from its uv alone.
fn terrain_albedo(h: f32, n: vec3<f32>) -> vec3<f32> {
    let grass = vec3<f32>(0.060, 0.150, 0.030);
    let rock = vec3<f32>(0.180, 0.150, 0.120);
    let snow = vec3<f32>(0.780, 0.800, 0.850);
    let color = mix(rock, grass, smoothstep(0.80, 0.90, n.y));
    return mix(color, snow, smoothstep(0.64, 0.72, h) * smoothstep(0.55, 0.75, n.y));
}

fn shade_terrain(h: f32, n: vec3<f32>, world: vec3<f32>, haze: vec3<f32>) -> vec3<f32> {
    var light = lights.ambient.rgb;
    for (var i = 0; i < lights.count.x; i++) {
        let p = lights.position[i];
        let l = select(normalize(p.xyz - world), normalize(p.xyz), p.w == 0.0);
        light += lights.color[i].rgb * max(dot(n, l), 0.0);
    }
    let fog = 1.0 - exp(-0.02 * distance(world, frame.camera_position.xyz));
    return mix(terrain_albedo(h, n) * light, haze, fog);
}
