#version 330 core
// A full-screen triangle at the far plane (z = w, so depth 1: drawn only where nothing nearer is); the fragment
// shader rebuilds the view ray from the inverse view-projection.
layout(location = 0) in vec2 csCorner;
out vec2 ndc;

void main() {
    ndc = csCorner;
    gl_Position = vec4(csCorner, 1.0, 1.0);
}
