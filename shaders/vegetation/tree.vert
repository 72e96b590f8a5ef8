#version 330 core
// A plant, one instance per record (engine: org.openworld.engine.vegetation.TreeDraw). The shape is 1 unit tall on
// the origin; each plant's record scales it to its height, turns it about the vertical, widens or narrows it a
// little, sways it in the wind and stands it on its foot. Shared by the lit program (MAIN, REFLECTION) and the
// depth-only one (SHADOW).
//
// Plants shrink into the ground over the last fifth of the view distance, and switch from the full shape to the
// simplified one at the LOD distance and from that to the impostors (impostor.vert) at theirs, all measured from the VIEWER (viewerPos(), the same in every pass): measured
// from cameraPos(), which in the shadow pass is the sun's camera hundreds of metres away, most plants would be gone
// from the shadow maps while still standing in the picture.
#include "common/frame.glsl"
#include "vegetation/sway.glsl"

layout(location = 0) in vec3 msPos;      // the shape, units of the plant's height: per vertex
layout(location = 1) in vec3 msNormal;
layout(location = 2) in float part;      // 0 trunk, 1 foliage
layout(location = 3) in vec4 footHeight; // xyz: the foot, x and z from uPlaced (m); w: height (m): per instance
layout(location = 4) in vec2 turnTint;   // x: turn about the vertical (radians); y: tint 0..1

uniform vec2 uFade; // x: distance from the viewer where plants start to shrink (m); y: where they are gone (m)
uniform vec3 uLod;  // x, y: the cross-fade from the full shape to the simplified one (m); z: 0 full shape, 1 simplified
uniform vec2 uImpostor; // the cross-fade from the simplified shape to the impostors (m); equal ends: a hard switch
uniform vec2 uPlaced; // where the feet's x and z are measured from: the layout's centre from the render origin (m)

out vec3 wsPos;
out vec3 wsNormal;
out vec3 msShape;         // the shape's point, for the leaves' and the bark's patterns
flat out float vPart;
flat out float vTint;
flat out float vFar;      // the simplified shape's share at this plant, 0..1 (the cross-fade)
flat out float vImpostor; // the impostor's share at this plant, 0..1

const float WIDTH_LOW = 0.85;   // the narrowest plant's width, times the shape's
const float WIDTH_SPREAD = 0.3; // ... to the widest, 1.15 times

void main() {
    vec3 foot = footHeight.xyz + vec3(uPlaced.x, 0.0, uPlaced.y);
    float d = distance(foot, viewerPos());
    float shrink = 1.0 - smoothstep(uFade.x, uFade.y, d);
    // the simplified shape's share: 0 before the band, 1 after it; a zero-width band is a hard switch
    vFar = clamp((d - uLod.x) / max(uLod.y - uLod.x, 1e-3), 0.0, 1.0);
    vImpostor = clamp((d - uImpostor.x) / max(uImpostor.y - uImpostor.x, 1e-3), 0.0, 1.0);
    bool other = uLod.z < 0.5 ? vFar >= 1.0 : vFar <= 0.0 || vImpostor >= 1.0;
    float c = cos(turnTint.x);
    float s = sin(turnTint.x);
    mat2 turn = mat2(c, s, -s, c);
    float width = WIDTH_LOW + WIDTH_SPREAD * turnTint.y;
    vec3 p = vec3(turn * msPos.xz * width, msPos.y).xzy;
    // widening by w across squeezes the normal's horizontal part by 1 / w (the inverse transpose)
    vec3 n = vec3(turn * msNormal.xz / width, msNormal.y).xzy;
    vec2 lean = plantLean(footHeight.xz); // vegetation/sway.glsl
    p.xz += lean * max(msPos.y, 0.0) * max(msPos.y, 0.0);
    wsPos = foot + p * footHeight.w * shrink;
    wsNormal = normalize(n);
    msShape = msPos * footHeight.w;
    vPart = part;
    vTint = turnTint.y;
    // a plant wholly on the other shape's side of the band: folded away before the rasteriser
    gl_Position = other ? vec4(0.0, 0.0, 2.0, 1.0) : frame.viewProjection * vec4(wsPos, 1.0);
}
