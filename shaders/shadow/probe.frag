#version 330 core
// The shadow probe (engine: org.openworld.engine.shadow.ShadowProbe, which reads this back and hands it to
// ShadowStatistics): per pixel of the finished picture, the sun's visibility at the world point it shows, as every
// lit shader sees it, and that point.
//   out (sunVisibility(wsPos, wsNormal), wsPos)   where the pixel shows a surface
//   out (-1, 0, 0, 0)                             where it shows the sky (depth 1: nothing was drawn nearer)
// The point comes from the copied scene depth through frame.invViewProjection; the normal is the surface's own,
// from the point's screen-space derivatives, turned to face up (the winding of a derivative cross product depends
// on the view, the ground's normal does not).
// With `revisit` on, the points are not this frame's but the previous frame's (its probe output): this frame's
// maps are then asked about the very points the last frame's maps were, so any change of their visibility is the
// maps' own flicker, none of it the camera's motion.
#include "common/shadow.glsl"

uniform sampler2D sceneDepth; // the scene's depth, copied (window depth 0 near .. 1 far)
uniform sampler2D points;     // with revisit: the previous frame's probe output
uniform int revisit;          // 1: the points of `points`; 0: this frame's, from the depth

out vec4 probe;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 wsPos;
    bool sky;
    if (revisit == 1) {
        vec4 last = texelFetch(points, pixel, 0);
        wsPos = last.yzw;
        sky = last.x < 0.0;
    } else {
        float depth = texelFetch(sceneDepth, pixel, 0).r;
        vec2 ndc = gl_FragCoord.xy * frame.viewport.zw * 2.0 - 1.0;
        vec4 wsHomogeneous = frame.invViewProjection * vec4(ndc, depth * 2.0 - 1.0, 1.0);
        wsPos = wsHomogeneous.xyz / wsHomogeneous.w;
        sky = depth == 1.0;
    }
    // derivatives before any branch on the result: they need the whole 2x2 pixel quad
    vec3 across = cross(dFdx(wsPos), dFdy(wsPos));
    vec3 wsNormal = dot(across, across) > 0.0 ? normalize(across) : vec3(0.0, 1.0, 0.0);
    wsNormal = wsNormal.y < 0.0 ? -wsNormal : wsNormal;
    probe = sky ? vec4(-1.0, 0.0, 0.0, 0.0) : vec4(sunVisibility(wsPos, wsNormal), wsPos);
}
