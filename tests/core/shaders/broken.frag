#version 330 core
// A fragment shader with a syntax error on line 6.
out vec4 f_color;
void main() {
    f_color = vec4(1.0);
    f_color = vec4(0.0) +;
}
