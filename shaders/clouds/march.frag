#version 330 core
// The clouds' ray march (engine: org.openworld.engine.clouds.CloudVolumeSystem), at a quarter of the picture's width
// and height. Each frame marches one texel of every 2 x 2 block of that grid (the frame's slot), or every texel when
// there is no history to fill the others from; the resolve pass (resolve.frag) fills the rest by reprojection.
// Out: the light the cloud sends to the eye after the air in front of it (display units) with the transmittance,
// and the cloud's distance with the scene's behind this texel, for the reprojection and the depth-aware upsampling.
#include "clouds/march.glsl"
#include "clouds/screen.glsl"

layout(location = 0) out vec4 cloudLight; // rgb: light towards the eye, display units; a: transmittance
layout(location = 1) out vec4 cloudDepth; // x: the cloud's distance (m); y: the scene's distance (m); zw: 0

uniform vec4 uGrid;           // xy: the quarter grid's size (texels); zw: this frame's slot in each 2 x 2 block
uniform float uEveryTexel;    // 1: march every texel of the grid (no history); 0: the frame's slot only

void main() {
    vec2 texel = uEveryTexel > 0.5 ? floor(gl_FragCoord.xy) : 2.0 * floor(gl_FragCoord.xy) + uGrid.zw;
    vec2 uv = (texel + 0.5) / uGrid.xy;
    vec3 wsRay = viewRay(2.0 * uv - 1.0);
    float surface = sceneDistance(uv, wsRay);
    float distance;
    cloudLight = marchClouds(cameraPos(), normalize(wsRay), surface, jitter(texel), distance);
    cloudDepth = vec4(distance, min(surface, NO_SURFACE), 0.0, 0.0);
}
