#version 330 core
// A conifer, one instance per tree (engine: org.openworld.engine.trees.TreeSystem). The shape is 1 unit tall on the
// origin; each tree's record scales it to its height, turns it about the vertical, widens or narrows it a little,
// and stands it on its foot. Shared by the lit program (MAIN, REFLECTION) and the depth-only one (SHADOW).
//
// Trees shrink into the ground over the last fifth of the view distance, measured from the VIEWER (viewerPos(), the
// same in every pass): measured from cameraPos(), which in the shadow pass is the sun's camera hundreds of metres
// away, most trees would be gone from the shadow maps while still standing in the picture.
#include "common/frame.glsl"

layout(location = 0) in vec3 msPos;      // the shape, units of the tree's height: per vertex
layout(location = 1) in vec3 msNormal;
layout(location = 2) in float part;      // 0 trunk, 1 needles
layout(location = 3) in vec4 footHeight; // xyz: the foot, from uPlaced (m); w: height (m): per instance
layout(location = 4) in vec2 turnTint;   // x: turn about the vertical (radians); y: tint 0..1

uniform vec2 uPlaced; // where the feet's x and z are measured from: the placement's centre from the render origin (m)
uniform vec2 uFade; // x: distance from the viewer where trees start to shrink (m); y: where they are gone (m)

out vec3 wsPos;
out vec3 wsNormal;
flat out float vPart;
flat out float vTint;

const float WIDTH_LOW = 0.85;   // the narrowest tree's width, times the shape's: its lowest cone 0.43 heights across
const float WIDTH_SPREAD = 0.3; // ... to the widest, 1.15 times: 0.58 heights across

void main() {
    vec3 foot = footHeight.xyz + vec3(uPlaced.x, 0.0, uPlaced.y);
    float shrink = 1.0 - smoothstep(uFade.x, uFade.y, distance(foot, viewerPos()));
    float c = cos(turnTint.x);
    float s = sin(turnTint.x);
    mat2 turn = mat2(c, s, -s, c);
    float width = WIDTH_LOW + WIDTH_SPREAD * turnTint.y;
    vec3 p = vec3(turn * msPos.xz * width, msPos.y).xzy;
    // widening by w across squeezes the normal's horizontal part by 1 / w (the inverse transpose)
    vec3 n = vec3(turn * msNormal.xz / width, msNormal.y).xzy;
    wsPos = foot + p * footHeight.w * shrink;
    wsNormal = normalize(n);
    vPart = part;
    vTint = turnTint.y;
    gl_Position = frame.viewProjection * vec4(wsPos, 1.0);
}
