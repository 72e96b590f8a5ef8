#version 330 core
// A full-screen triangle for the temporal anti-aliasing pass (engine: org.openworld.engine.temporal): every pixel once.
layout(location = 0) in vec2 csCorner;

void main() {
    gl_Position = vec4(csCorner, 0.0, 1.0);
}
