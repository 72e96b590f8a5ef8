#version 330 core
// A full-screen triangle; the fragment shader rebuilds the view ray from the inverse view-projection.
layout(location = 0) in vec2 csCorner;
out vec2 ndc;

void main() {
    ndc = csCorner;
    gl_Position = vec4(csCorner, 1.0, 1.0);
}
