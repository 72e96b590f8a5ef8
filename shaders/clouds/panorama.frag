#version 330 core
// The volumetric clouds in every direction from the viewer's eye (engine: org.openworld.engine.sky.clouds.
// CloudPanoramaMarch), in the sky panorama's layout (sky/panorama.glsl: the upper hemisphere on the left, the lower on
// the right), for the water's reflection (reflection.frag) and the sky's environment map (sky/sky.frag). The same
// march as the picture's, cut at the ground's sphere below the eye instead of the scene's depth. Drawn a band of rows
// per frame, or whole, in the first pass the clouds draw in.
#include "clouds/march.glsl"
#include "sky/panorama.glsl"

out vec4 cloudLight; // rgb: light towards the eye after the air in front, display units; a: transmittance

uniform vec2 uSize;  // the panorama's size, texels (2N x N)

void main() {
    vec3 dir = panoramaDirection(gl_FragCoord.xy, uSize);
    vec3 eye = viewerPos();
    // a ray down from under the clouds ends on the ground (sea level around the eye): no cloud lies beyond it
    vec2 ground = sphereHits(eye, dir, EARTH_RADIUS);
    float limit = ground.x > 0.0 ? ground.x : MAX_DISTANCE;
    float distance;
    cloudLight = marchClouds(eye, dir, limit, jitter(gl_FragCoord.xy), distance);
}
