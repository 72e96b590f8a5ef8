// The water plane y = uLevel, per pixel: where the view ray meets it, and the depth to write there.
#include "common/frame.glsl"

uniform float uLevel; // metres

// Distance along the unit ray from the eye to the plane, or -1 where the ray never meets it.
float planeDistance(vec3 eye, vec3 dir) {
    float rise = uLevel - eye.y;
    if (abs(dir.y) < 1e-7 || rise * dir.y <= 0.0) {
        return -1.0;
    }
    return rise / dir.y;
}

// Window depth of a world point for gl_FragDepth. Water beyond the far plane (out to the horizon) is kept just
// inside it, in front of the sky, which lies on the far plane itself.
float windowDepth(vec3 wsPos) {
    vec4 clip = frame.viewProjection * vec4(wsPos, 1.0);
    return clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 0.999999);
}

// The world point behind a pixel of the scene from its window depth.
vec3 scenePoint(vec2 uv, float depth) {
    vec4 p = frame.invViewProjection * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    return p.xyz / p.w;
}
