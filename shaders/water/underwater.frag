#version 330 core
// The water seen from below (engine: org.openworld.engine.water.WaterSystem; from above: fresnel.frag). Every pixel
// is seen through exp(-extinction * path) of water glowing with its in-water colour; where the view meets the
// surface first, the world above shows through Snell's window and the water beyond it is mirrored. The whole
// screen is under water, so this runs on a full-screen triangle and writes the surface's depth itself.
#include "water/optics.glsl"

in vec2 ndc;
out vec4 fragColor;

uniform vec3 uInside;            // the water's glow seen from within, per unit of light entering it, rgb

vec3 underWater(vec3 eye, vec3 dir, float t, vec2 uv, float sceneDepth) {
    float depth = uLevel - eye.y;
    vec3 body = toneMapped(lightAtDepth(depth, sunVisibility(vec3(eye.x, uLevel, eye.z), vec3(0.0, 1.0, 0.0)))
                           * uInside);
    float sceneDistance = sceneDepth >= 1.0 ? 1e9 : distance(eye, scenePoint(uv, sceneDepth));
    vec3 seen;
    float path;
    if (t > 0.0 && t < sceneDistance) {
        // the surface from below: the world above through Snell's window, the water mirrored beyond it
        vec3 n = -rippleNormal((eye + t * dir).xz);
        float f = fresnel(dot(n, -dir), true);
        seen = (1.0 - f) * picture(refraction, uv) + f * body;
        path = t;
    } else {
        seen = picture(refraction, uv);
        path = sceneDistance;
    }
    vec3 transmittance = exp(-uExtinction * path);
    return transmittance * seen + (1.0 - transmittance) * body;
}

void main() {
    vec3 eye = cameraPos();
    vec3 dir = normalize(viewRay(ndc));
    vec2 uv = gl_FragCoord.xy * frame.viewport.zw;
    float sceneDepth = texture(depthCopy, uv).r;
    float t = planeDistance(eye, dir);
    vec3 color = underWater(eye, dir, t, uv, sceneDepth);
    gl_FragDepth = t > 0.0 ? min(windowDepth(eye + t * dir), sceneDepth) : sceneDepth;
    fragColor = vec4(linearToSrgb(clamp(color, 0.0, 1.0)), 1.0);
}
