#version 330 core
in vec3 v_normal;
uniform vec4 u_color;
out vec4 f_color;
void main() {
    // Map each component from [-1, 1] to [0, 1].
    f_color = u_color * vec4(normalize(v_normal) * 0.5 + 0.5, 1.0);
}
