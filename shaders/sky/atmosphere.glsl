// Lookups into the sky tables built on the CPU by org.openworld.engine.sky (Hillaire 2020, paper 3.1).
// The mapping is SkyView.uv's; the tables' sizes come from Java as defines (SkySystem.shaderConstants, from SkyView
// and AerialPerspective). Without a sky system the engine binds a one-texel stand-in of clear air, and so do these.
#include "common/conventions.glsl"

#ifndef AERIAL_MAX_DISTANCE
#define SKY_VIEW_WIDTH 1
#define SKY_VIEW_HEIGHT 1
#define AERIAL_WIDTH 1
#define AERIAL_HEIGHT 1
#define AERIAL_DEPTH 1
#define AERIAL_MAX_DISTANCE 1.0
#endif

// SkyView texture: u = azimuth from the sun's vertical plane / PI (0..PI: the sky is symmetric about that plane),
// v = elevation with texels crowded at the horizon, row 0 at v = 0 (nadir).
const vec2 SKY_VIEW_SIZE = vec2(SKY_VIEW_WIDTH, SKY_VIEW_HEIGHT);
// AerialPerspective texture: directions (same mapping as the sky view) x distance slices.
const vec3 AERIAL_SIZE = vec3(AERIAL_WIDTH, AERIAL_HEIGHT, AERIAL_DEPTH);
// AERIAL_MAX_DISTANCE: where the last slice ends, metres; slice k of n ends at AERIAL_MAX_DISTANCE * ((k + 1) / n)^2.

// Unit coordinates in [0, 1] to texture coordinates of texel centres: u = 0 is the centre of the first texel and
// u = 1 that of the last, so the table's end values are reached exactly (Hillaire's fromUnitToSubUvs).
vec2 unitToTexelCentres(vec2 unit, vec2 size) {
    return 0.5 / size + unit * (1.0 - 1.0 / size);
}

// Unit table coordinates of a world direction: x = azimuth from the sun / PI, y = Hillaire's non-linear elevation
// v = 0.5 + 0.5 * sign(e) * sqrt(|e| / (PI/2)).
vec2 skyTableUnit(vec3 wsDir, vec3 sunDir) {
    vec3 d = normalize(wsDir);
    float elevation = asin(clamp(d.y, -1.0, 1.0));
    vec2 view = d.xz;
    vec2 sun = sunDir.xz;
    // Angle between the horizontal projections, 0..PI; 0 when either points straight up or down.
    float azimuth = 0.0;
    if (dot(view, view) > 1e-12 && dot(sun, sun) > 1e-12) {
        azimuth = atan(abs(view.x * sun.y - view.y * sun.x), dot(view, sun));
    }
    float v = 0.5 + 0.5 * sign(elevation) * sqrt(abs(elevation) / (0.5 * PI));
    return vec2(azimuth / PI, v);
}

// Texture coordinates in the SkyView texture for a world direction and the direction toward the sun.
vec2 skyViewUv(vec3 wsDir, vec3 sunDir) {
    return unitToTexelCentres(skyTableUnit(wsDir, sunDir), SKY_VIEW_SIZE);
}

// Texture coordinates in the AerialPerspective texture for a world direction, the sun and a distance in metres.
// w = sqrt(distance / max) is (k + 1) / n at the end of slice k of n, whose texel centre is (k + 0.5) / n: so the
// texture coordinate is w - 0.5 / n, clamped to the first and last slice centres.
vec3 aerialPerspectiveUvw(vec3 wsDir, vec3 sunDir, float distanceM) {
    vec2 uv = unitToTexelCentres(skyTableUnit(wsDir, sunDir), AERIAL_SIZE.xy);
    float w = sqrt(max(distanceM, 0.0) / AERIAL_MAX_DISTANCE);
    float slice = clamp(w - 0.5 / AERIAL_SIZE.z, 0.5 / AERIAL_SIZE.z, 1.0 - 0.5 / AERIAL_SIZE.z);
    return vec3(uv, slice);
}

// Weight of the aerial-perspective texel below the first slice's end: 0 at the eye, 1 from the first slice on.
// Mix as mix(vec4(0, 0, 0, 1), texture(aerial, uvw), aerialPerspectiveWeight(d)).
float aerialPerspectiveWeight(float distanceM) {
    return clamp(sqrt(max(distanceM, 0.0) / AERIAL_MAX_DISTANCE) * AERIAL_SIZE.z, 0.0, 1.0);
}
