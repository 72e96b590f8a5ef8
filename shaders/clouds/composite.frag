#version 330 core
// The clouds over the picture (engine: org.openworld.engine.clouds.CloudVolumeSystem): the quarter grid upsampled
// with depth-aware weights, so a cloud stops at a mountain's silhouette instead of bleeding over it: of the four
// grid texels around a pixel, each weighs its bilinear share times how closely the scene's distance it was marched
// against matches this pixel's. Blended over the shown picture with the cloud's opacity 1 - T, its colour the mean
// radiance of the cloud (light / opacity), exposed and tone-mapped as every surface is.
#include "clouds/screen.glsl"
#include "common/color.glsl"

out vec4 fragColor;

uniform sampler2D cloudLight; // the resolved quarter grid: rgb light, a transmittance
uniform sampler2D cloudDepth; // y: the scene's distance each texel was marched against
uniform vec2 uGridSize;       // the quarter grid's size, texels

// Relative difference of distance over which a grid texel's weight falls by e: a texel marched against a surface a
// tenth nearer or farther than this pixel's belongs to another object.
const float DEPTH_TOLERANCE = 0.1;
// Least light share that still counts as cloud in the colour's division: below it the pixel is clear.
const float MIN_OPACITY = 1e-3;

void main() {
    vec2 uv = gl_FragCoord.xy * frame.viewport.zw;
    float surface = min(sceneDistance(uv, viewRay(2.0 * uv - 1.0)), NO_SURFACE);
    vec2 position = uv * uGridSize - 0.5;
    vec2 origin = floor(position);
    vec2 f = position - origin;
    vec4 sum = vec4(0.0);
    float total = 0.0;
    vec4 nearest = vec4(0.0, 0.0, 0.0, 1.0);
    float best = 1e30;
    for (int i = 0; i < 4; i++) {
        vec2 corner = vec2(i & 1, i >> 1);
        ivec2 texel = ivec2(clamp(origin + corner, vec2(0.0), uGridSize - 1.0));
        vec4 light = texelFetch(cloudLight, texel, 0);
        float difference = abs(texelFetch(cloudDepth, texel, 0).y - surface) / surface;
        float bilinear = (corner.x > 0.5 ? f.x : 1.0 - f.x) * (corner.y > 0.5 ? f.y : 1.0 - f.y);
        float weight = bilinear * exp(-difference / DEPTH_TOLERANCE);
        sum += weight * light;
        total += weight;
        if (difference < best) {
            best = difference;
            nearest = light;
        }
    }
    // where no texel matches (a thin silhouette between grid texels), the closest in distance alone
    vec4 cloud = total > 1e-4 ? sum / total : nearest;
    float opacity = 1.0 - cloud.a;
    if (opacity < MIN_OPACITY) {
        discard;
    }
    fragColor = vec4(displayColor(cloud.rgb / opacity), opacity);
}
