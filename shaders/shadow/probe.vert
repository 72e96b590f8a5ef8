#version 330 core
// A full-screen triangle for the shadow probe (engine: org.openworld.engine.shadow.ShadowProbe): every pixel of the
// picture is measured once; probe.frag finds its world point from the depth.
layout(location = 0) in vec2 csCorner;

void main() {
    gl_Position = vec4(csCorner, 0.0, 1.0);
}
