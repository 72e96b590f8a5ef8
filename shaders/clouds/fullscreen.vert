#version 330 core
// A full-screen triangle for the clouds' passes (engine: org.openworld.engine.clouds): every pixel of the target once;
// the fragment shaders build their rays from gl_FragCoord.
layout(location = 0) in vec2 csCorner;

void main() {
    gl_Position = vec4(csCorner, 0.0, 1.0);
}
