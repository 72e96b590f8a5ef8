// The cloud volume (engine: org.openworld.engine.clouds, package-info has the method): a layer between two spheres
// around the Earth's centre, its density a 3D-DFT field (2 axes of space, 1 of time; the sky's phases, a steeper
// spectrum) shaped by the cover and a height profile, and eroded by the sky's own field at a finer scale, its time
// axis turned upright. Lit by the sun
// (frame.sunColor: through the atmosphere's transmittance table to the eye) with a dual-lobe Henyey-Greenstein phase
// and octaves of attenuated scattering for the light scattered many times, and by the sky's irradiance (the
// harmonics of frame.sky) from above and from the ground below.
#include "common/frame.glsl"

uniform sampler2D cloudField;  // the base shape's field (power 1/f^3) at this moment (clouds/bake.frag): mean 0,
                               // standard deviation 1; s, t: one tile. Repeat
uniform sampler3D cloudDetail; // the sky's own field (clouds.beta), the same phases, for the erosion
uniform sampler2D cloudOptics; // 256 x 1 (CloudOptics.table): r the height profile over the layer's height 0..1;
                               // gba the phase of octaves 0, 1, 2 over cos(angle to the sun), -1..1
uniform vec4 uLayer;           // x: base radius, y: top radius (m, from the Earth's centre); z: the field's tile (m);
                               // w: the density threshold of the cover (standard deviations)
uniform vec4 uMotion;          // xy: the wind's offset of the field (m, world x, z); z: time phase 0..1; w: half a
                               // frame of the field's time axis (1 / 2 frames: frame i's texel centre is (i + 0.5) / n)

// The Earth's radius, metres (the atmosphere's: org.openworld.engine.sky.Atmosphere). The layer is curved around a
// centre below the viewer's eye (in every pass, so the reflection's clouds are the picture's), so it falls away
// towards the horizon as a real one does.
const float EARTH_RADIUS = 6360e3;
// Standard deviations of the field above the threshold over which the cover's strength rises from 0 to 1: the
// width of a cloud's soft rim in the base shape.
const float COVER_SPREAD = 1.5;
// The detail field's scale against the base shape's: features 7 times smaller (a 12 km tile: 94 m texels become
// 13 m ones), and metres of height per period of its upright axis.
const float DETAIL_SCALE = 7.0;
const float DETAIL_HEIGHT = 800.0;
// How much of a thin region the detail can eat: the base shape below this times the detail is cleared.
const float EROSION = 0.45;
// Extinction of the densest cloud, 1/m: a mean free path of 25 m, cumulus's (liquid water 0.5 g/m^3, droplets of
// 10 um: beta = 1.5 LWC / (rho r) ~ 0.075/m), lowered a little so that the rims stay translucent.
const float EXTINCTION = 0.04;
// Multiple scattering by octaves (Wrenninge et al. 2013, "Oz: the great and volumetric"; Hillaire 2016): octave i
// scatters OCTAVE_A^i of the light, sees the optical depth times OCTAVE_B^i and the phase's anisotropy times
// OCTAVE_C^i (the phase table's g, b, a channels). 0.5 each, the papers' values.
const float OCTAVE_A = 0.5;
const float OCTAVE_B = 0.5;
// Metres from a sample towards the sun of the three samples of the light's optical depth, each standing for the
// stretch from the one before: the shadow of the cloud's own near parts, then of its far side.
const vec3 SUN_STEPS = vec3(50.0, 180.0, 450.0);

vec3 earthCentre() {
    return vec3(viewerPos().x, -EARTH_RADIUS, viewerPos().z);
}

// 0 at the base, 1 at the top of the layer (outside it: below 0 or above 1).
float layerHeight(vec3 wsPos) {
    return (length(wsPos - earthCentre()) - uLayer.x) / (uLayer.y - uLayer.x);
}

// The base shape at a point of height fraction h: the cover's strength where the profile allows it, 0..1.
float cloudShape(vec3 wsPos, float h) {
    vec2 st = (wsPos.xz - uMotion.xy) / uLayer.z;
    float field = texture(cloudField, st).r;
    float cover = clamp((field - uLayer.w) / COVER_SPREAD, 0.0, 1.0);
    if (cover <= 0.0) {
        return 0.0; // the profile is at most 1, so no cover is no cloud: the profile's read is spared
    }
    float profile = texture(cloudOptics, vec2(clamp(h, 0.0, 1.0), 0.5)).r;
    return clamp(cover + profile - 1.0, 0.0, 1.0) * step(0.0, h) * step(h, 1.0);
}

// The density, 0..1, the base shape eroded by the detail field where the shape is thin.
float cloudDensity(vec3 wsPos, float h, float shape) {
    vec2 st = (wsPos.xz - uMotion.xy) / uLayer.z * DETAIL_SCALE;
    float detail = texture(cloudDetail, vec3(st, uMotion.z + uMotion.w + wsPos.y / DETAIL_HEIGHT)).r;
    float eaten = EROSION * clamp(0.5 + 0.25 * detail, 0.0, 1.0);
    return clamp((shape - eaten) / (1.0 - eaten), 0.0, 1.0);
}

// The optical depth from a point towards the sun, over the base shape only.
float opticalDepthToSun(vec3 wsPos) {
    float depth = 0.0;
    float from = 0.0;
    for (int i = 0; i < 3; i++) {
        vec3 p = wsPos + sunDir() * SUN_STEPS[i];
        depth += cloudShape(p, layerHeight(p)) * (SUN_STEPS[i] - from);
        from = SUN_STEPS[i];
    }
    return depth * EXTINCTION;
}

// Both roots of |o + t d - c| = r (d unit), or (-1, -1) when the ray misses.
vec2 sphereHits(vec3 o, vec3 d, float r) {
    vec3 oc = o - earthCentre();
    float b = dot(oc, d);
    float disc = b * b - (dot(oc, oc) - r * r);
    if (disc < 0.0) {
        return vec2(-1.0);
    }
    float s = sqrt(disc);
    return vec2(-b - s, -b + s);
}

// The stretch [enter, leave] of the ray inside the layer, from the eye, metres; enter > leave when there is none.
// Below the base: from the base up to the top. Inside: from the eye to the base (looking down) or the top. Above:
// from the top down to the base, or out through the top again.
vec2 layerSpan(vec3 o, vec3 d) {
    float r = length(o - earthCentre());
    vec2 base = sphereHits(o, d, uLayer.x);
    vec2 top = sphereHits(o, d, uLayer.y);
    if (r < uLayer.x) {
        return vec2(base.y, top.y);
    }
    float downToBase = base.x > 0.0 ? base.x : top.y;
    if (r <= uLayer.y) {
        return vec2(0.0, downToBase);
    }
    return top.x > 0.0 ? vec2(top.x, downToBase) : vec2(1.0, 0.0);
}
