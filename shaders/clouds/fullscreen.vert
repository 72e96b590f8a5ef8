#version 330 core
// A full-screen triangle for the clouds' passes (engine: org.openworld.engine.clouds): every pixel of the target once;
// the fragment shaders build their rays from gl_FragCoord. On the far plane (z = w), so the composite can pick the
// sky's pixels (depth test LEQUAL) or the surfaces' (GREATER) by the depth test; the grid passes have no depth.
layout(location = 0) in vec2 csCorner;

void main() {
    gl_Position = vec4(csCorner, 1.0, 1.0);
}
