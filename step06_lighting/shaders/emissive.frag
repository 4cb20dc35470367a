#version 330 core
// A light's marker: its flat colour, unlit.
in vec3 v_world;
in vec3 v_normal;
uniform vec4 u_color;
out vec4 f_color;
void main() {
    f_color = vec4(u_color.rgb, 1.0);
}
