#version 330 core
// The clouds' ray march (engine: org.openworld.engine.clouds.CloudVolumeSystem), at a quarter of the picture's width
// and height. Each frame marches one texel of every 2 x 2 block of that grid (the frame's slot), or every texel when
// there is no history to fill the others from; the resolve pass (resolve.frag) fills the rest by reprojection.
// Out: the light the cloud sends to the eye after the air in front of it (display units) with the transmittance,
// and the cloud's distance with the scene's behind this texel, for the reprojection and the depth-aware upsampling.
#include "common/fog.glsl"
#include "clouds/volume.glsl"
#include "clouds/screen.glsl"

layout(location = 0) out vec4 cloudLight; // rgb: light towards the eye, display units; a: transmittance
layout(location = 1) out vec4 cloudDepth; // x: the cloud's distance (m); y: the scene's distance (m); zw: 0

uniform vec4 uGrid;           // xy: the quarter grid's size (texels); zw: this frame's slot in each 2 x 2 block
uniform float uEveryTexel;    // 1: march every texel of the grid (no history); 0: the frame's slot only

// Steps along the ray through the layer; the first is jittered per texel so the steps' banding becomes noise.
const int STEPS = 24;
// Metres of the ray beyond which nothing is marched: the aerial perspective's table ends at 64 km, and a cloud
// that far is a few pixels of haze.
const float MAX_DISTANCE = 60000.0;
// Transmittance below which the march stops: the rest of the ray would add under 1 % of the light.
const float OPAQUE = 0.01;
// Interleaved gradient noise (Jimenez 2014): a fixed value in 0..1 per pixel, without a texture.
float jitter(vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

void main() {
    vec2 texel = uEveryTexel > 0.5 ? floor(gl_FragCoord.xy) : 2.0 * floor(gl_FragCoord.xy) + uGrid.zw;
    vec2 uv = (texel + 0.5) / uGrid.xy;
    vec3 wsRay = viewRay(2.0 * uv - 1.0);
    vec3 dir = normalize(wsRay);
    float surface = sceneDistance(uv, wsRay);
    vec2 span = layerSpan(cameraPos(), dir);
    span.y = min(span.y, min(surface, MAX_DISTANCE));

    vec3 light = vec3(0.0);
    float transmittance = 1.0;
    float weighted = 0.0; // sum of distance times the light's share, for the cloud's distance
    float shares = 0.0;
    if (span.x < span.y) {
        // the sun's phase per octave for this ray's angle, and the sky's light from above and from below
        vec3 phase = texture(cloudOptics, vec2(0.5 + 0.5 * dot(dir, sunDir()), 0.5)).gba;
        vec3 skyAbove = skyIrradiance(vec3(0.0, 1.0, 0.0));
        vec3 skyBelow = skyIrradiance(vec3(0.0, -1.0, 0.0));
        float dt = (span.y - span.x) / float(STEPS);
        float t = span.x + jitter(texel) * dt;
        for (int i = 0; i < STEPS; i++) {
            vec3 p = cameraPos() + dir * t;
            float h = layerHeight(p);
            float shape = cloudShape(p, h);
            if (shape > 0.0) {
                float sigma = cloudDensity(p, h, shape) * EXTINCTION;
                float tau = opticalDepthToSun(p);
                // 1. the sun's light scattered here, three octaves (display units: pi times the phase)
                float sun = phase.x * exp(-tau) + OCTAVE_A * phase.y * exp(-OCTAVE_B * tau)
                        + OCTAVE_A * OCTAVE_A * phase.z * exp(-OCTAVE_B * OCTAVE_B * tau);
                // 2. the sky's, from above at the top and from the ground below at the base
                vec3 source = PI * sun * frame.sunColor.rgb + mix(skyBelow, skyAbove, clamp(h, 0.0, 1.0));
                // 3. integrated over the step with the albedo 1 (Hillaire 2016: S (1 - T_step))
                float stepThrough = exp(-sigma * dt);
                float share = transmittance * (1.0 - stepThrough);
                light += share * source;
                weighted += share * t;
                shares += share;
                transmittance *= stepThrough;
                if (transmittance < OPAQUE) {
                    break;
                }
            }
            t += dt;
        }
    }
    float distance = shares > 1e-4 ? weighted / shares : max(span.x, 0.0) + 1.0;
    // 4. the air between the eye and the cloud: light = light T_air + (1 - T_cloud) in-scattered
    vec4 air = airTo(cameraPos() + dir * distance);
    light = light * air.a + (1.0 - transmittance) * air.rgb;
    cloudLight = vec4(light, transmittance);
    cloudDepth = vec4(distance, min(surface, NO_SURFACE), 0.0, 0.0);
}
