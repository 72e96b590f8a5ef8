#version 330 core
// The clouds over the picture (engine: org.openworld.engine.clouds.CloudVolumeSystem): the quarter grid upsampled
// with depth-aware weights, so a cloud stops at a mountain's silhouette instead of bleeding over it. Drawn twice on
// the far plane, the depth test choosing the pixels: once over the sky's (uSky 1), once over the surfaces' (uSky 0).
// Of the four grid texels around a pixel, each weighs its bilinear share if it was marched against the same kind
// (sky or a surface), and nothing otherwise; the scene's depth is not read here, as the picture's own depth buffer
// is attached while it is drawn into. Blended over the picture with the cloud's opacity 1 - T, its colour the mean
// radiance of the cloud (light / opacity), exposed and tone-mapped as every surface is.
#include "common/frame.glsl"
#include "common/color.glsl"

out vec4 fragColor;

uniform sampler2D cloudLight; // the resolved quarter grid: rgb light, a transmittance; bilinear
uniform sampler2D cloudDepth; // y: the scene's distance each texel was marched against
uniform vec2 uGridSize;       // the quarter grid's size, texels
uniform float uSky;           // 1: this draw covers the sky's pixels; 0: the surfaces'

// Distance at or beyond which a grid texel was marched against the sky (clouds/screen.glsl's NO_SURFACE, 10^7 m).
const float SKY_DISTANCE = 1e6;

// Least light share that still counts as cloud in the colour's division: below it the pixel is clear.
const float MIN_OPACITY = 1e-3;

void main() {
    vec2 uv = gl_FragCoord.xy * frame.viewport.zw;
    // 1. one bilinear read first: where none of the four texels holds a cloud (the clear sky, and nearly every
    // surface, which lies under the clouds), the pixel is done at a quarter of the reads
    if (1.0 - textureLod(cloudLight, uv, 0.0).a < MIN_OPACITY) {
        discard;
    }
    // 2. the depth-aware weights
    vec2 position = uv * uGridSize - 0.5;
    vec2 origin = floor(position);
    vec2 f = position - origin;
    vec4 sum = vec4(0.0);
    float total = 0.0;
    vec4 nearest = vec4(0.0, 0.0, 0.0, 1.0);
    float best = -1.0;
    for (int i = 0; i < 4; i++) {
        vec2 corner = vec2(i & 1, i >> 1);
        ivec2 texel = ivec2(clamp(origin + corner, vec2(0.0), uGridSize - 1.0));
        vec4 light = texelFetch(cloudLight, texel, 0);
        float sky = step(SKY_DISTANCE, texelFetch(cloudDepth, texel, 0).y);
        float bilinear = (corner.x > 0.5 ? f.x : 1.0 - f.x) * (corner.y > 0.5 ? f.y : 1.0 - f.y);
        float weight = bilinear * (1.0 - abs(sky - uSky));
        sum += weight * light;
        total += weight;
        if (bilinear > best) {
            best = bilinear;
            nearest = light;
        }
    }
    // where no texel matches (a peak thinner than a grid texel), the nearest texel
    vec4 cloud = total > 1e-4 ? sum / total : nearest;
    float opacity = 1.0 - cloud.a;
    if (opacity < MIN_OPACITY) {
        discard;
    }
    fragColor = vec4(displayColor(cloud.rgb / opacity), opacity);
}
