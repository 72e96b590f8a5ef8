#version 330 core
#include "common/frame.glsl"

layout(location = 0) in vec3 wsPosIn;
layout(location = 1) in vec3 wsNormalIn;
out vec3 wsPos;
out vec3 wsNormal;

void main() {
    wsPos = wsPosIn;
    wsNormal = wsNormalIn;
    gl_Position = frame.viewProjection * vec4(wsPosIn, 1.0);
}
