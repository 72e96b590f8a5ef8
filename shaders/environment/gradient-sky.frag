#version 330 core
#include "common/frame.glsl"
#include "common/color.glsl"

in vec2 ndc;
out vec4 fragColor;

// A gradient sky: fog colour at the horizon, a deeper blue towards the zenith, a glow around the sun.
void main() {
    vec4 wsFar = frame.invViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 wsDir = normalize(wsFar.xyz / wsFar.w - cameraPos());
    float up = max(wsDir.y, 0.0);
    vec3 horizon = frame.fogColorDensity.rgb;
    vec3 zenith = vec3(0.10, 0.25, 0.60) * (frame.ambientColor.rgb / 0.30);
    vec3 sky = mix(horizon, zenith, pow(up, 0.5));
    float glow = pow(max(dot(wsDir, sunDir()), 0.0), 64.0);
    sky += frame.sunColor.rgb * glow * 0.6;
    fragColor = vec4(displayColor(sky), 1.0);
}
