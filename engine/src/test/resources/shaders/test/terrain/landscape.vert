#version 330 core
// A stand-in landscape mesh for the material tests (org.openworld.engine.terrain.material.MaterialRenderTest), or, with
// uSky = 1, a full-screen triangle (positions given in clip space) for the sky behind it.
#include "common/frame.glsl"

layout(location = 0) in vec3 wsPosIn;
layout(location = 1) in vec3 wsNormalIn;
uniform int uSky;
out vec3 wsPos;
out vec3 wsNormal;

void main() {
    wsPos = wsPosIn;
    wsNormal = wsNormalIn;
    gl_Position = uSky == 1 ? vec4(wsPosIn.xy, 1.0, 1.0) : frame.viewProjection * vec4(wsPosIn, 1.0);
}
