#version 330 core
in vec3 v_direction;
uniform samplerCube u_sky;
out vec4 f_color;
void main() {
    f_color = vec4(texture(u_sky, normalize(v_direction)).rgb, 1.0);
}
