#version 330 core
// Water by two pictures (the paper's proposal in section 5, made physical), seen from above: the mirrored scene
// from the reflection pass and the scene behind the water (copied just before the water is drawn), mixed by the
// Fresnel reflectance of the rippled surface, with the light the water absorbs on its way through and scatters back,
// and the sun's glitter. Engine: org.openworld.engine.water.WaterSystem; the view from below is underwater.frag.
//
// At the point P where the view ray meets the water, with ripple normal n and reflectance F:
//   colour = F * reflection + (1 - F) * (T * behind + (1 - T) * body) + glitter
//   T = exp(-extinction * (path through the water to the ground and the ground's depth below the surface))
// The rasteriser gives each pixel the plane's depth (water.vert), so this runs only where the water is seen: no
// discard, no depth written here, and the depth test rejects the water under the terrain before it is shaded.
#include "water/optics.glsl"
#include "common/fog.glsl"
#include "common/environment.glsl"

in vec2 ndc;
out vec4 fragColor;

uniform sampler2D reflection;    // the mirrored scene, aligned with the screen; alpha 0 where nothing was drawn
uniform int uReflected;          // 1 when the reflection pass ran this frame
uniform vec3 uBody;              // reflectance of deep water from the light scattered back inside it, rgb
uniform float uMicroSlope2;      // mean square slope of the ripples finer than the texture (the glitter's spread)
uniform float uResolvedSlope2;   // mean square slope of the ripples the texture holds

// Pixels a ripple's wavelength must span for its slope to bend the reflection smoothly from pixel to pixel: with
// fewer, neighbouring pixels see unrelated slopes and mirror unrelated things (a mosaic); at 8 they are 45 degrees
// of the wave's phase apart.
const float PIXELS_PER_WAVE = 8.0;

// Furthest that ripples shift what is seen through the water, metres of path (the shift grows with the path).
const float REFRACTION_REACH = 4.0;

vec2 screenUv(vec3 wsPos) {
    vec4 clip = frame.viewProjection * vec4(wsPos, 1.0);
    return clip.xy / clip.w * 0.5 + 0.5;
}

// Where a distant thing seen along wsDir appears on the screen (the direction's vanishing point).
vec2 screenUvOfDirection(vec3 wsDir) {
    vec4 clip = frame.viewProjection * vec4(wsDir, 0.0);
    return clip.xy / clip.w * 0.5 + 0.5;
}

bool onScreen(vec2 uv) {
    return all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

// The share of the ripples' slope the pixel can show, as an amplitude: Phillips' spectrum (P ~ k^-4) puts equal slope
// variance in every octave of wavelength, from the tile's width down to two texels, and the waves shorter than
// PIXELS_PER_WAVE pixel footprints are dropped. `footprint` is the pixel's longer side on the water (m); grazing
// views stretch it along the view, so far water turns to a still mirror there first. Specular anti-aliasing: what
// is dropped from the normal widens the glitter's lobe instead (see aboveWater).
float resolvedAmplitude(float footprint) {
    float tile = 1.0 / uRipple.x;                       // metres, the larger layer's repeat
    float octaves = log2(float(textureSize(ripples, 0).x) / 2.0);
    float large = clamp(log2(tile / (PIXELS_PER_WAVE * footprint)) / octaves, 0.0, 1.0);
    float small = clamp(log2(SMALL_SCALE * tile / (PIXELS_PER_WAVE * footprint)) / octaves, 0.0, 1.0);
    return sqrt((large + SMALL_WEIGHT * SMALL_WEIGHT * small) / (1.0 + SMALL_WEIGHT * SMALL_WEIGHT));
}

// Whether the mirror picture at uv shows a reflection on water the viewer sees: the scene there lies on or behind the
// water plane. Where the terrain stands in front of the water (above a shore's mirrored waterline), the mirror
// picture holds what the shore hides: sky, or ground far behind it. `texel` is one mirror texel up, so the bilinear
// look-up's upper texel is checked too.
bool mirrorSeen(vec3 eye, vec2 uv, float texel) {
    vec2 above = uv + vec2(0.0, texel);
    vec3 dir = viewRay(above * 2.0 - 1.0);
    if (dir.y >= 0.0) {
        return false;
    }
    float plane = windowDepth(eye + (uLevel - eye.y) / dir.y * dir);
    return texture(depthCopy, above).r >= plane;
}

// The sun's glitter on the ripples: a microfacet lobe (Beckmann, slope variance m2: uMicroSlope2, plus the share of
// uResolvedSlope2 that `amplitude` took off the normal) around the mirror direction, display units:
// pi * E_sun * F * D / (4 cos(view)), with D = exp(-tan^2/m2) / (pi m2 cos^4).
vec3 glitter(vec3 n, vec3 toEye, float amplitude) {
    vec3 l = sunDir();
    if (l.y <= 0.0) {
        return vec3(0.0);
    }
    vec3 h = normalize(l + toEye);
    float cosH = max(dot(n, h), 1e-3);
    float tan2 = (1.0 - cosH * cosH) / (cosH * cosH);
    float m2 = uMicroSlope2 + (1.0 - amplitude * amplitude) * uResolvedSlope2; // what the normal lost
    float d = exp(-tan2 / m2) / (m2 * cosH * cosH * cosH * cosH);
    float f = fresnel(dot(h, toEye), false);
    return frame.sunColor.rgb * f * d / (4.0 * max(dot(n, toEye), 0.05));
}

vec3 aboveWater(vec3 eye, vec3 dir, float t, vec2 uv, float sceneDepth) {
    vec3 p = eye + t * dir;
    float footprint = max(length(dFdx(p.xz)), length(dFdy(p.xz)));
    float amplitude = resolvedAmplitude(footprint);
    vec3 n = rippleNormal(p.xz, amplitude);
    vec3 toEye = -dir;
    float f = fresnel(dot(n, toEye), false);
    vec4 air = airTo(p);
    float sunSeen = sunVisibility(p, vec3(0.0, 1.0, 0.0)); // a mountain's shadow on the water takes the sun's share
    // 1. the reflection: the mirrored scene where the ripple-bent ray points, else the sky's cube map
    vec3 r = reflect(dir, n);
    r.y = max(r.y, 1e-3);
    vec3 sky = toneMapped(environmentRadiance(r, 0.0) * air.a + air.rgb);
    vec3 reflected = sky;
    vec2 uvR = screenUvOfDirection(vec3(r.x, -r.y, r.z));
    if (!mirrorSeen(eye, uvR, 1.0 / float(textureSize(reflection, 0).y))) {
        uvR = uv; // the ripples reached past the mirrored waterline: the plain mirror, which is the shore's image
    }
    if (uReflected == 1 && onScreen(uvR)) {
        vec4 mirrored = texture(reflection, uvR);
        reflected = mix(sky, srgbToLinear(mirrored.rgb), mirrored.a);
    }
    // 2. what lies behind: the scene bent by the ripples (unless that would fetch something in front of the water)
    vec3 bottom = scenePoint(uv, sceneDepth);
    float path = min(distance(eye, bottom) - t, REFRACTION_REACH);
    vec3 bent = refract(dir, n, 1.0 / WATER_INDEX);
    vec3 straight = refract(dir, vec3(0.0, 1.0, 0.0), 1.0 / WATER_INDEX);
    vec2 uvT = uv + screenUv(p + path * bent) - screenUv(p + path * straight);
    float depthT = texture(depthCopy, uvT).r;
    vec3 bottomT = scenePoint(uvT, depthT);
    if (!onScreen(uvT) || depthT < gl_FragCoord.z || bottomT.y > uLevel) {
        uvT = uv;
        depthT = sceneDepth;
        bottomT = bottom;
    }
    float through = distance(eye, bottomT) - t + (uLevel - bottomT.y);
    vec3 transmittance = depthT >= 1.0 ? vec3(0.0) : exp(-uExtinction * through);
    vec3 body = toneMapped(lightAtDepth(0.0, sunSeen) * uBody * air.a + air.rgb);
    vec3 seen = transmittance * picture(refraction, uvT) + (1.0 - transmittance) * body;
    // 3. the mix, and the sun
    return f * reflected + (1.0 - f) * seen + toneMapped(glitter(n, toEye, amplitude) * sunSeen * air.a);
}

void main() {
    vec3 eye = cameraPos();
    vec3 dir = normalize(viewRay(ndc));
    vec2 uv = gl_FragCoord.xy * frame.viewport.zw;
    // the clip distance keeps this below the horizon, where the ray meets the plane in front of the eye
    float t = (uLevel - eye.y) / min(dir.y, -1e-7);
    vec3 color = aboveWater(eye, dir, t, uv, texture(depthCopy, uv).r);
    fragColor = vec4(linearToSrgb(clamp(color, 0.0, 1.0)), 1.0);
}
