// The clouds' ray march along one ray (engine: org.openworld.engine.sky.clouds, package-info has the method), shared
// by the picture's quarter grid (march.frag) and the panorama the reflection and the environment map read
// (panorama.frag): the sun's and the sky's light scattered in the layer, integrated step by step, then the air in
// front of the cloud.
#include "common/fog.glsl"
#include "clouds/volume.glsl"

// Steps along the ray through the layer; the first is jittered per texel so the steps' banding becomes noise.
const int STEPS = 24;
// Empty space is crossed COARSE fine steps at a time (the fine steps' points, every COARSE-th): the first sample in
// a cloud steps back to the fine points skipped before it, and the march stays fine until FINE_AFTER samples in a
// row hold no cloud. Every sample is one of the fine march's, so the picture is the fine march's but for a cloud
// that lies wholly between two coarse points (the base shape is smooth over the field's 94 m texels and the
// profile's height; the fine step is 62 m looking up, 2.5 km at the horizon's 60 km).
const int COARSE = 2;
const int FINE_AFTER = 2;
// Metres of the ray beyond which nothing is marched: the aerial perspective's table ends at 64 km, and a cloud
// that far is a few pixels of haze.
const float MAX_DISTANCE = 60000.0;
// Transmittance below which the march stops: the rest of the ray would add under 1 % of the light.
const float OPAQUE = 0.01;

// Interleaved gradient noise (Jimenez 2014): a fixed value in 0..1 per pixel, without a texture.
float jitter(vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// The cloud along the ray from eye in the unit direction dir, cut at limit metres, the first step at jitter (0..1)
// of a step: rgb the light towards the eye after the air in front of the cloud (display units), a the
// transmittance; distance: the cloud's mean distance (weighted by the light's share), or where the ray enters the
// layer when it met no cloud.
vec4 marchClouds(vec3 eye, vec3 dir, float limit, float jitter, out float distance) {
    vec2 span = layerSpan(eye, dir);
    span.y = min(span.y, min(limit, MAX_DISTANCE));
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
        float t = span.x + jitter * dt;
        int fine = 0; // fine steps left since the last sample in a cloud
        for (int i = 0; i < 2 * STEPS && t < span.y; i++) {
            vec3 p = eye + dir * t;
            float h = layerHeight(p);
            float shape = cloudShape(p, h);
            if (fine == 0) {
                if (shape <= 0.0) {
                    t += float(COARSE) * dt; // empty space: every COARSE-th point of the fine steps
                    continue;
                }
                // a cloud: back to the fine point skipped before it, then fine steps through it
                fine = FINE_AFTER;
                if (i > 0) {
                    t -= float(COARSE - 1) * dt;
                    continue;
                }
            }
            if (shape > 0.0) {
                fine = FINE_AFTER;
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
            } else {
                fine--;
            }
            t += dt;
        }
    }
    distance = shares > 1e-4 ? weighted / shares : max(span.x, 0.0) + 1.0;
    // 4. the air between the eye and the cloud: light = light T_air + (1 - T_cloud) in-scattered
    vec4 air = airAlong(dir, distance);
    return vec4(light * air.a + (1.0 - transmittance) * air.rgb, transmittance);
}
