// The sky panorama's layout (engine: org.openworld.engine.sky.SkyPanorama): the sky and its clouds for every
// direction, drawn into textures when the sun or the clouds moved; the sky pass and the environment map read them
// with one lookup per pixel. Two hemi-octahedral squares side by side, the upper hemisphere (Y up) on the left, the
// lower on the right: a direction d is projected onto the octahedron |x| + |y| + |z| = 1, whose half is a diamond
// |x| + |z| <= 1, turned by 45 degrees (s = x + z, t = x - z) to fill a square with the zenith (or the nadir) at its
// centre and the horizon its border. No trigonometry per pixel (an equirectangular map needs an atan and an asin,
// which are dear on a software rasteriser), texels of nearly one solid angle (within a factor of about 2), and the
// horizon on the squares' edges, where clamping keeps the sky above it from being blended with the ground below (a
// plain octahedral map has its horizon across the texels, diagonally).
#include "common/conventions.glsl"

// Texture coordinates of the direction wsDir (any length) in a panorama of size texels (2N x N).
vec2 panoramaUv(vec3 wsDir, vec2 size) {
    vec3 p = wsDir / (abs(wsDir.x) + abs(wsDir.y) + abs(wsDir.z));
    vec2 unit = vec2(p.x + p.z, p.x - p.z) * 0.5 + 0.5;
    // texel centres: the border texels lie on the horizon, so the lookup never reaches across it
    vec2 texel = 0.5 / size.yy + unit * (1.0 - 1.0 / size.yy);
    return vec2((texel.x + (wsDir.y < 0.0 ? 1.0 : 0.0)) * 0.5, texel.y);
}

// The unit direction of the texel whose centre is at pixel coordinates fragCoord (gl_FragCoord.xy) of a panorama of
// size texels: the inverse of panoramaUv at texel centres.
vec3 panoramaDirection(vec2 fragCoord, vec2 size) {
    float lower = fragCoord.x >= size.y ? 1.0 : 0.0;
    vec2 unit = (vec2(fragCoord.x - lower * size.y, fragCoord.y) - 0.5) / (size.y - 1.0);
    vec2 st = unit * 2.0 - 1.0;
    vec2 xz = vec2(st.x + st.y, st.x - st.y) * 0.5;
    // 1 - |x| - |z| equals 1 - max(|s|, |t|), and only the latter is exact on the border, where |s| or |t| is 1: the
    // former leaves the rounding of x and z, a hair above or below 0, and a texel of the upper square a hair below
    // takes the distant ground's light (panorama.frag): every few texels along two of its edges, a row of brighter
    // dots on the horizon that the water mirrors. Exact, the border of either square holds the horizon's sky alone
    // (-0 is not below it); max() keeps it so on a driver whose division overshoots 1 there.
    float y = max(1.0 - max(abs(st.x), abs(st.y)), 0.0);
    return normalize(vec3(xz.x, lower > 0.5 ? -y : y, xz.y));
}
