#version 330 core
// A star's pixel (engine: org.openworld.engine.sky.StarField): the sky there, as the sky pass draws it, with the
// star's light behind the clouds.
#include "common/frame.glsl"
#include "common/color.glsl"
#include "sky/night.glsl"

in vec3 wsRay;
flat in float starRadiance;
out vec4 fragColor;

void main() {
    vec3 wsDir = normalize(wsRay);
    float alpha;
    vec3 radiance = skyBehind(wsDir, alpha) + (1.0 - alpha) * (moonDisc(wsDir) + vec3(starRadiance));
    fragColor = vec4(displayColor(radiance), 1.0);
}
