#version 330 core
// A full-screen triangle (or any 2D mesh) given in clip space; used by the engine's GL tests.
layout(location = 0) in vec2 csCorner;

void main() {
    gl_Position = vec4(csCorner, 0.0, 1.0);
}
