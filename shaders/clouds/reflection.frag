#version 330 core
// The volumetric clouds in the water's reflection (engine: org.openworld.engine.sky.clouds.CloudPanoramaMarch): one
// lookup of the clouds' panorama (panorama.frag) per sky pixel of the reflection, along the pass camera's (mirrored)
// ray, blended over the sky as the picture's composite blends the marched clouds (composite.frag). On the far plane,
// depth-tested, so only the pixels no mirrored surface covers are drawn.
#include "common/frame.glsl"
#include "common/color.glsl"
#include "sky/panorama.glsl"

out vec4 fragColor;

uniform sampler2D cloudPanorama; // rgb: light towards the eye after the air in front (display units); a: transmittance

// Least light share that still counts as cloud in the colour's division: below it the pixel is clear
// (composite.frag's).
const float MIN_OPACITY = 1e-3;

void main() {
    vec3 dir = normalize(viewRay(2.0 * gl_FragCoord.xy * frame.viewport.zw - 1.0));
    // textureLod: the panorama has no mip levels, and an explicit level spares the rasteriser the derivatives
    vec4 cloud = textureLod(cloudPanorama, panoramaUv(dir, vec2(textureSize(cloudPanorama, 0))), 0.0);
    float opacity = 1.0 - cloud.a;
    if (opacity < MIN_OPACITY) {
        discard;
    }
    fragColor = vec4(displayColor(cloud.rgb / opacity), opacity);
}
