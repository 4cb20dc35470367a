// The engine's full-screen passes (the sky, the copy to the window): one triangle that covers the
// screen, drawn with draw(3) and no vertex buffer. A pass that includes this file writes
// fullscreen_vertex: where a corner goes and what it carries (interpolated across the screen).
struct FullscreenOut {
    @builtin(position) position: vec4<f32>,
    @location(0) value: vec4<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) index: u32) -> FullscreenOut {
    // Corners (0, 0), (2, 0), (0, 2) -> clip space (-1, -1), (3, -1), (-1, 3).
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return fullscreen_vertex(uv * 2.0 - 1.0);
}
