#version 330 core
// Water by two pictures (the paper's proposal in section 5, made physical): the mirrored scene from the reflection
// pass and the scene behind the water (copied just before the water is drawn), mixed by the Fresnel reflectance of
// the rippled surface, with the light the water absorbs on its way through and scatters back, and the sun's
// glitter. Also the view from under the water. Engine: org.openworld.engine.water.WaterSystem.
//
// Above the water, at the point P where the view ray meets it, with ripple normal n and reflectance F:
//   colour = F * reflection + (1 - F) * (T * behind + (1 - T) * body) + glitter
//   T = exp(-extinction * (path through the water to the ground and the ground's depth below the surface))
// The pictures arrive tone-mapped (each shader maps its own colours), so they are mixed in the display's linear
// light; the water's own light (body, glitter) is tone-mapped into that space first.
#include "common/frame.glsl"
#include "common/color.glsl"
#include "common/fog.glsl"
#include "common/environment.glsl"
#include "common/shadow.glsl"
#include "water/surface.glsl"

in vec2 ndc;
out vec4 fragColor;

uniform sampler2D reflection;    // the mirrored scene, aligned with the screen; alpha 0 where nothing was drawn
uniform sampler2D refraction;    // the scene before the water, display colours
uniform sampler2D depthCopy;     // its depth
uniform sampler2D fresnelTable;  // reflectance by cos(angle to the normal): row 0 from the air, row 1 from the water
uniform sampler2DArray ripples;  // slopes (RippleField): rg = 128 + 127 * slope / scale, one layer per frame
uniform int uReflected;          // 1 when the reflection pass ran this frame
uniform int uUnderwater;         // 1 when the eye is below the water
uniform vec3 uExtinction;        // per metre, rgb
uniform vec3 uBody;              // reflectance of deep water from the light scattered back inside it, rgb
uniform vec3 uInside;            // the water's glow seen from within, per unit of light entering it, rgb
uniform vec4 uRipple;            // x: 1 / tile (1/m); y: frames; z: time / period; w: slope scale
uniform float uMicroSlope2;      // mean square slope of the ripples finer than the texture (the glitter's spread)

// Where the second, smaller layer of ripples is drawn from: a scale unrelated to the first, so the two tiles never
// repeat together, and its weight (the two are summed, then rescaled to the first's slope).
const float SMALL_SCALE = 0.37;
const float SMALL_WEIGHT = 0.6;
// Furthest that ripples shift what is seen through the water, metres of path (the shift grows with the path).
const float REFRACTION_REACH = 4.0;
const float WATER_INDEX = 1.333;

vec2 slopes(vec2 xz, float scale, float cycles) {
    float frames = uRipple.y;
    float f = fract(cycles) * frames;
    float layer = floor(f);
    vec2 uv = xz * uRipple.x / scale;
    vec2 a = texture(ripples, vec3(uv, layer)).rg;
    vec2 b = texture(ripples, vec3(uv, mod(layer + 1.0, frames))).rg;
    return (mix(a, b, f - layer) * 255.0 - 128.0) / 127.0 * uRipple.w;
}

// The rippled surface's upward normal. The smaller layer runs slower by 1/sqrt(scale): deep-water waves' frequency
// goes as the square root of their wavenumber (omega^2 = g k), so geometrically smaller waves are also quicker.
vec3 rippleNormal(vec2 xz) {
    vec2 s = slopes(xz, 1.0, uRipple.z)
           + SMALL_WEIGHT * slopes(xz + vec2(17.3, -5.1), SMALL_SCALE, uRipple.z / sqrt(SMALL_SCALE));
    s /= sqrt(1.0 + SMALL_WEIGHT * SMALL_WEIGHT);
    return normalize(vec3(-s.x, 1.0, -s.y));
}

float fresnel(float cosAngle, bool fromBelow) {
    return texture(fresnelTable, vec2(clamp(cosAngle, 0.0, 1.0), fromBelow ? 0.75 : 0.25)).r;
}

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

vec3 picture(sampler2D image, vec2 uv) {
    return srgbToLinear(texture(image, uv).rgb);
}

// The sun and sky light entering the water, dimmed on its way down to `depth` metres (scene units); `sunSeen` is
// how much of the sun reaches the surface there (0 in a shadow).
vec3 lightAtDepth(float depth, float sunSeen) {
    vec3 entering = frame.sunColor.rgb * max(sunDir().y, 0.0) * sunSeen + frame.ambientColor.rgb;
    return entering * exp(-uExtinction * max(depth, 0.0));
}

// The sun's glitter on the ripples: a microfacet lobe (Beckmann, slope variance uMicroSlope2) around the mirror
// direction, display units: pi * E_sun * F * D / (4 cos(view)), with D = exp(-tan^2/m^2) / (pi m^2 cos^4).
vec3 glitter(vec3 n, vec3 toEye) {
    vec3 l = sunDir();
    if (l.y <= 0.0) {
        return vec3(0.0);
    }
    vec3 h = normalize(l + toEye);
    float cosH = max(dot(n, h), 1e-3);
    float tan2 = (1.0 - cosH * cosH) / (cosH * cosH);
    float d = exp(-tan2 / uMicroSlope2) / (uMicroSlope2 * cosH * cosH * cosH * cosH);
    float f = fresnel(dot(h, toEye), false);
    return frame.sunColor.rgb * f * d / (4.0 * max(dot(n, toEye), 0.05));
}

vec3 aboveWater(vec3 eye, vec3 dir, float t, vec2 uv, float sceneDepth) {
    vec3 p = eye + t * dir;
    vec3 n = rippleNormal(p.xz);
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
    if (!onScreen(uvT) || depthT < gl_FragCoord.z || scenePoint(uvT, depthT).y > uLevel) {
        uvT = uv;
        depthT = sceneDepth;
    }
    bottom = scenePoint(uvT, depthT);
    float through = distance(eye, bottom) - t + (uLevel - bottom.y);
    vec3 transmittance = depthT >= 1.0 ? vec3(0.0) : exp(-uExtinction * through);
    vec3 body = toneMapped(lightAtDepth(0.0, sunSeen) * uBody * air.a + air.rgb);
    vec3 seen = transmittance * picture(refraction, uvT) + (1.0 - transmittance) * body;
    // 3. the mix, and the sun
    return f * reflected + (1.0 - f) * seen + toneMapped(glitter(n, toEye) * sunSeen * air.a);
}

vec3 underWater(vec3 eye, vec3 dir, float t, vec2 uv, float sceneDepth) {
    float depth = uLevel - eye.y;
    vec3 body = toneMapped(lightAtDepth(depth, sunVisibility(vec3(eye.x, uLevel, eye.z), vec3(0.0, 1.0, 0.0)))
                           * uInside);
    float sceneDistance = sceneDepth >= 1.0 ? 1e9 : distance(eye, scenePoint(uv, sceneDepth));
    vec3 seen;
    float path;
    if (t > 0.0 && t < sceneDistance) {
        // the surface from below: the world above through Snell's window, the water mirrored beyond it
        vec3 n = -rippleNormal((eye + t * dir).xz);
        float f = fresnel(dot(n, -dir), true);
        seen = (1.0 - f) * picture(refraction, uv) + f * body;
        path = t;
    } else {
        seen = picture(refraction, uv);
        path = sceneDistance;
    }
    vec3 transmittance = exp(-uExtinction * path);
    return transmittance * seen + (1.0 - transmittance) * body;
}

void main() {
    vec3 eye = cameraPos();
    vec3 dir = normalize(viewRay(ndc));
    vec2 uv = gl_FragCoord.xy * frame.viewport.zw;
    float sceneDepth = texture(depthCopy, uv).r;
    float t = planeDistance(eye, dir);
    vec3 color;
    if (uUnderwater == 1) {
        color = underWater(eye, dir, t, uv, sceneDepth);
        gl_FragDepth = t > 0.0 ? min(windowDepth(eye + t * dir), sceneDepth) : sceneDepth;
    } else {
        vec3 p = eye + t * dir;
        float waterDepth = windowDepth(p);
        if (t < 0.0 || waterDepth >= sceneDepth) {
            discard;
        }
        color = aboveWater(eye, dir, t, uv, sceneDepth);
        gl_FragDepth = waterDepth;
    }
    fragColor = vec4(linearToSrgb(clamp(color, 0.0, 1.0)), 1.0);
}
