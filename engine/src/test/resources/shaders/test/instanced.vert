#version 330 core
// A 2D mesh in clip space, moved by a per-instance offset (engine test: org.openworld.engine.gl.MeshInstancingTest).
layout(location = 0) in vec2 csCorner; // per vertex
layout(location = 1) in vec2 csOffset; // per instance

void main() {
    gl_Position = vec4(csCorner + csOffset, 0.0, 1.0);
}
