#version 330 core
// The sky evaluated directly for every pixel, the way sky/panorama.frag does for every texel, composited and
// displayed the way sky/sky.frag does (without the sun's disc, which the test keeps out of view): the reference the
// panorama's lookup is compared with (engine test: org.openworld.engine.sky.SkyPanoramaTest).
#include "common/frame.glsl"
#include "common/color.glsl"
#include "sky/atmosphere.glsl"
#include "sky/clouds.glsl"

out vec4 fragColor;

uniform sampler2D skyView;

void main() {
    vec2 ndc = gl_FragCoord.xy * frame.viewport.zw * 2.0 - 1.0;
    vec3 wsDir = normalize(viewRay(ndc));
    vec3 sky = texture(skyView, skyViewUv(wsDir, sunDir())).rgb;
    vec3 level = normalize(vec3(wsDir.x, 0.0, wsDir.z) + vec3(1e-6, 0.0, 0.0));
    vec3 horizon = texture(skyView, skyViewUv(level, sunDir())).rgb;
    Cloud cloud = cloudAlong(wsDir, sunDir(), frame.sunColor.rgb, frame.ambientColor.rgb, horizon);
    fragColor = vec4(displayColor(mix(sky, cloud.color, cloudOpacity(cloud.excess, cloud.transmittance))), 1.0);
}
