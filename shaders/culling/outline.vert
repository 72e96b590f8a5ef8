#version 330 core
// The frozen frustum's edges as screen-space ribbons of constant width (core-profile GL has no wide lines):
// each edge is a quad whose four vertices know both ends; the ends are projected with the current camera,
// clipped to lie in front of its eye, and pushed sideways by half the width in pixels.
#include "common/frame.glsl"

layout(location = 0) in vec2 cornerIndices; // the edge's two ends, indices into wsCorners
layout(location = 1) in vec2 ribbon;        // x: which end (0 or 1); y: which side (-1 or +1)

uniform vec3 wsCorners[8];  // the frozen frustum's corners, world space (m)
uniform float halfWidthPx;  // half the ribbon's width (px)

// Smallest clip w an end may have, in clip units (metres in front of the eye for a perspective camera): an end
// behind the eye is moved along the edge to here, so the projected ribbon does not fold through infinity.
const float MIN_CLIP_W = 1e-3;

void main() {
    vec4 csA = frame.viewProjection * vec4(wsCorners[int(cornerIndices.x)], 1.0);
    vec4 csB = frame.viewProjection * vec4(wsCorners[int(cornerIndices.y)], 1.0);
    if (csA.w < MIN_CLIP_W && csB.w < MIN_CLIP_W) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0); // wholly behind the eye: beyond the far plane, clipped away
        return;
    }
    if (csA.w < MIN_CLIP_W) {
        csA = mix(csA, csB, (MIN_CLIP_W - csA.w) / (csB.w - csA.w));
    } else if (csB.w < MIN_CLIP_W) {
        csB = mix(csB, csA, (MIN_CLIP_W - csB.w) / (csA.w - csB.w));
    }
    vec2 pxA = csA.xy / csA.w * 0.5 * frame.viewport.xy;
    vec2 pxB = csB.xy / csB.w * 0.5 * frame.viewport.xy;
    vec2 along = pxB - pxA;
    vec2 across = dot(along, along) > 0.0 ? normalize(vec2(-along.y, along.x)) : vec2(0.0);
    vec4 csEnd = ribbon.x < 0.5 ? csA : csB;
    // a pixel offset is 2 / viewport in NDC, times w in clip space
    csEnd.xy += across * ribbon.y * halfWidthPx * 2.0 * frame.viewport.zw * csEnd.w;
    gl_Position = csEnd;
}
