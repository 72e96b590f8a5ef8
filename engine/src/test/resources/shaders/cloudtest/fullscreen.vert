#version 330 core
// A full-screen triangle (GlTestSupport.fullScreenTriangle) passing its normalised device coordinates on.
layout(location = 0) in vec2 csCorner;
out vec2 ndc;

void main() {
    ndc = csCorner;
    gl_Position = vec4(csCorner, 0.0, 1.0);
}
