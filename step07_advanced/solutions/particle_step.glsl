// Reference solution: one explicit time step of a particle (compute exercise) in GLSL.

Particle particle_step(Particle p, SimParams s) {
    // Semi-implicit Euler: the new velocity moves the particle.
    vec3 velocity = p.velocity.xyz + s.gravity.xyz * s.dt;
    vec3 position = p.position.xyz + velocity * s.dt;
    if (position.y < s.floor_y && velocity.y < 0.0) {
        // Mirror the overshoot above the floor and reverse the vertical
        // speed, both scaled by the restitution.
        position.y = s.floor_y + (s.floor_y - position.y) * s.restitution;
        velocity.y = -velocity.y * s.restitution;
    }
    return Particle(vec4(position, p.position.w - s.dt), vec4(velocity, p.velocity.w));
}
