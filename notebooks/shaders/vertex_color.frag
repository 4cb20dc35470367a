#version 330 core
// Step 02: write the interpolated colour; the sRGB framebuffer encodes it again.
in vec4 v_color;
out vec4 f_color;

void main() {
    f_color = v_color;
}
