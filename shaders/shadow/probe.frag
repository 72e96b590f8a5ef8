#version 330 core
// The shadow probe (engine: org.openworld.engine.shadow.ShadowProbe, which reads this back and hands it to
// ShadowStatistics): per pixel of the finished picture, the sun's visibility at the world point it shows, as every
// lit shader sees it, and that point.
//   out (sunVisibility(wsPos, wsNormal), wsPos)   where the pixel shows a surface
//   out (-1, 0, 0, 0)                             where it shows the sky (depth 1: nothing was drawn nearer)
// The point comes from the copied scene depth through frame.invViewProjection; the normal is the surface's own,
// from the point's screen-space derivatives, turned to face up (the winding of a derivative cross product depends
// on the view, the ground's normal does not).
#include "common/shadow.glsl"

uniform sampler2D sceneDepth; // the scene's depth, copied (window depth 0 near .. 1 far)

out vec4 probe;

void main() {
    float depth = texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r;
    vec2 ndc = gl_FragCoord.xy * frame.viewport.zw * 2.0 - 1.0;
    vec4 wsHomogeneous = frame.invViewProjection * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    vec3 wsPos = wsHomogeneous.xyz / wsHomogeneous.w;
    // derivatives before any branch: they need the whole 2x2 pixel quad
    vec3 across = cross(dFdx(wsPos), dFdy(wsPos));
    vec3 wsNormal = dot(across, across) > 0.0 ? normalize(across) : vec3(0.0, 1.0, 0.0);
    wsNormal = wsNormal.y < 0.0 ? -wsNormal : wsNormal;
    probe = depth == 1.0 ? vec4(-1.0, 0.0, 0.0, 0.0) : vec4(sunVisibility(wsPos, wsNormal), wsPos);
}
