#version 330 core
// The cloud layer of sky/clouds.glsl over a plain gradient sky, seen by a pinhole camera (engine test:
// org.openworld.engine.sky.CloudLayerTest). Colour: the composite, display-encoded; alpha: the cloud's opacity.
#include "sky/clouds.glsl"
#include "common/color.glsl"

in vec2 ndc;
out vec4 fragColor;

uniform vec4 camera;      // x: yaw, y: pitch (rad, docs/design.md conventions); z: tan(vertical fov / 2); w: width / height
uniform vec3 uSunDir;
uniform vec3 sunColor;
uniform vec3 ambientColor;
uniform vec3 horizonColor;
uniform vec3 zenithColor;
uniform float cloudsOn;   // 1 draws the layer, 0 the bare sky (the reference)

const vec3 GROUND = vec3(0.05, 0.06, 0.04); // dark green-grey below the horizon

void main() {
    float cy = cos(camera.x), sy = sin(camera.x), cp = cos(camera.y), sp = sin(camera.y);
    vec3 forward = vec3(sy * cp, sp, -cy * cp); // yaw clockwise from north (-Z)
    vec3 right = vec3(cy, 0.0, sy);
    vec3 up = cross(right, forward);
    vec3 wsDir = normalize(forward + ndc.x * camera.z * camera.w * right + ndc.y * camera.z * up);

    vec3 sky = wsDir.y > 0.0 ? mix(horizonColor, zenithColor, sqrt(wsDir.y)) : GROUND;
    Cloud cloud = cloudAlong(wsDir, uSunDir, sunColor, ambientColor, horizonColor);
    float alpha = cloudsOn * cloudOpacity(cloud.excess, cloud.transmittance);
    // tone curve and sRGB without the engine's exposure: this fixture runs without an engine's frame block
    fragColor = vec4(linearToSrgb(toneMapAces(mix(sky, cloud.color, alpha))), alpha);
}
