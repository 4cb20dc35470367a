// Exercise 3: one time step of a particle in GLSL, run by the compute shader particles.comp for
// every particle. Returns the particle unchanged until you write it.
// A wrong or black picture? `python -m step07_advanced.opengl --technique showcase --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").
//
// Particle: position.xyz, position.w = remaining life in seconds;
// velocity.xyz (velocity.w: keep as is). SimParams s: s.gravity.xyz
// (m/s²), s.dt (s), s.floor_y, s.restitution (0..1).
//   1. position += velocity * dt + 0.5 * gravity * dt * dt (the OLD velocity),
//      then velocity += gravity * dt: the exact update under constant
//      acceleration, so the path is the same at any dt
//   2. if position.y < floor_y while moving down (velocity.y < 0): bounce,
//        position.y = floor_y + (floor_y - position.y) * restitution;
//        velocity.y = -velocity.y * restitution
//   3. life (position.w) -= dt
Particle particle_step(Particle p, SimParams s) {
    return p;
}
