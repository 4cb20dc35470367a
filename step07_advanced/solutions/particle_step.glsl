// Reference solution: one exact time step of a particle under constant gravity (compute exercise) in GLSL.

Particle particle_step(Particle p, SimParams s) {
    // Constant acceleration integrates exactly: x += v dt + g dt^2 / 2, v += g dt (the same path at any dt).
    vec3 position = p.position.xyz + p.velocity.xyz * s.dt + 0.5 * s.gravity.xyz * (s.dt * s.dt);
    vec3 velocity = p.velocity.xyz + s.gravity.xyz * s.dt;
    if (position.y < s.floor_y && velocity.y < 0.0) {
        // Mirror the overshoot above the floor and reverse the vertical
        // speed, both scaled by the restitution.
        position.y = s.floor_y + (s.floor_y - position.y) * s.restitution;
        velocity.y = -velocity.y * s.restitution;
    }
    return Particle(vec4(position, p.position.w - s.dt), vec4(velocity, p.velocity.w));
}
