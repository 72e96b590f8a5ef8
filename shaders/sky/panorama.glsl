// The sky panorama's layout (engine: org.openworld.engine.sky.SkyPanorama): the sky and its clouds for every
// direction, drawn into square textures when the sun or the clouds moved; the sky pass and the environment map read
// them with one lookup per pixel. Octahedral (Engelhardt and Dachsbacher 2008; Cigolle et al. 2014): a direction d
// is projected onto the octahedron |x| + |y| + |z| = 1 and the octahedron unfolded into a square, the upper
// hemisphere (Y up) the diamond |u| + |v| <= 1 in the middle with the zenith at the centre and the horizon its edge,
// the lower hemisphere folded out into the four corners. No trigonometry per pixel (an equirectangular map needs an
// atan and an asin, which are dear on a software rasteriser), texels of nearly the same solid angle everywhere
// (within a factor of about 2), and the horizon, where the clouds' detail is finest, an interior line without a
// seam. The square's border is the nadir's neighbourhood, where the sky is the smooth distant ground.
#include "common/conventions.glsl"

// -1 or 1, never 0 (sign() gives 0 on the axes, which would fold a point onto the wrong corner).
vec2 signNotZero(vec2 v) {
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

// Texture coordinates (0..1 over the square) of the direction wsDir, of any length.
vec2 panoramaUv(vec3 wsDir) {
    vec3 p = wsDir / (abs(wsDir.x) + abs(wsDir.y) + abs(wsDir.z));
    vec2 square = p.y >= 0.0 ? p.xz : (1.0 - abs(p.zx)) * signNotZero(p.xz);
    return square * 0.5 + 0.5;
}

// The unit direction at texture coordinates uv (0..1 over the square): the inverse of panoramaUv.
vec3 panoramaDirection(vec2 uv) {
    vec2 square = uv * 2.0 - 1.0;
    vec3 d = vec3(square.x, 1.0 - abs(square.x) - abs(square.y), square.y);
    if (d.y < 0.0) {
        d.xz = (1.0 - abs(d.zx)) * signNotZero(d.xz);
    }
    return normalize(d);
}
