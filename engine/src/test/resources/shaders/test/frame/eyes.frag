#version 330 core
#include "common/frame.glsl"
// The two eyes of the frame block as colours, metres / 1000 (engine test: org.openworld.engine.gl.FrameUniformsTest):
// the left half of the target the viewer's, the right half the pass camera's.
out vec4 fragColor;

void main() {
    bool left = gl_FragCoord.x < 0.5 * frame.viewport.x;
    fragColor = vec4((left ? viewerPos() : cameraPos()) / 1000.0, 1.0);
}
