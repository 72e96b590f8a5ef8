#version 330 core
// A full-screen triangle: the water is found per pixel by intersecting the view ray with its plane, so it reaches
// the horizon in every direction with no mesh to run out (engine: org.openworld.engine.water.WaterSystem).
layout(location = 0) in vec2 csCorner;
out vec2 ndc;

void main() {
    ndc = csCorner;
    gl_Position = vec4(csCorner, 0.0, 1.0);
}
