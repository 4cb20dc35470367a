#version 330 core
// The shadow pass writes depth only: the rasteriser stores it, this stage adds nothing.
void main() {
}
