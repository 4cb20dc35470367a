#version 330 core
// Step 02: positions and colours come from the vertex buffer; the instance rows place the shape.
#include "frame.glsl"
#include "instance.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 4) in vec4 a_color;  // sRGB, like every colour in gandalf

out vec4 v_color;  // linear light: interpolated across the triangle

// The exact sRGB decoding (IEC 61966-2-1): a straight line near black, a 2.4 power above.
vec3 srgb_to_linear(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

void main() {
    v_color = vec4(srgb_to_linear(a_color.rgb), a_color.a);
    // No camera in this step: view and projection are identity, so this is the clip-space position.
    gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0);
}
