#version 330 core
// One flat colour; the engine's GL tests tell their systems apart by it.
uniform vec4 uColor;
out vec4 fragColor;

void main() {
    fragColor = uColor;
}
