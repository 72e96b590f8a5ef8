// A plant's surface (engine: org.openworld.engine.vegetation): its albedo and its shading normal, made from the
// shape's own coordinates: clumps of leaves that turn their own way, and bark from the textures synthesised at start
// (BarkTextures, PlantMaps): furrowed plates on the conifers, smooth grey on the broadleaves and bushes, with their
// relief's normals. Shared by the meshes (tree.frag) and the impostors' bake (bake.frag), so the two agree.

// Albedos, linear, dark and light ends of each kind's foliage: spruce needles reflect 3-8 % of visible light (dark,
// bluish green), beech and oak leaves 8-12 % (yellower), shrubs in between; bark a little more, brown.
const vec3 FOLIAGE_DARK[3] = vec3[](vec3(0.026, 0.050, 0.030), vec3(0.045, 0.075, 0.025), vec3(0.040, 0.060, 0.028));
const vec3 FOLIAGE_LIGHT[3] = vec3[](vec3(0.050, 0.080, 0.035), vec3(0.085, 0.120, 0.035), vec3(0.070, 0.095, 0.035));
// Leaf clumps about 0.7 m across, needle tufts a little finer; they tilt the normal by up to this much.
const float CLUMP_PER_M = 1.4;
const float CLUMP_TILT = 0.45;
// The bark's tile wraps this many times round a trunk (a whole number, so the seam at atan's +-pi is seamless) and
// repeats every BARK_TILE_M up it: at a 16 m tree's 0.5 m trunk radius a tile is about 1 m square, 4 mm a texel.
const float BARK_AROUND = 3.0;
const float BARK_TILE_M = 1.0;
// The plants' tints spread the bark's brightness by this much either side of the texture's.
const float BARK_TINT = 0.15;

uniform sampler2DArray uBarkAlbedo; // layers: 0 the conifers' bark, 1 the broadleaves' (and the bushes')
uniform sampler2DArray uBarkDetail; // rg the tangent-space normal * 0.5 + 0.5 (x round the stem, y up it)

vec3 hash3(vec3 p) {
    p = fract(p * vec3(0.1031, 0.1030, 0.0973));
    p += dot(p, p.yxz + 33.33);
    return fract((p.xxy + p.yxx) * p.zyx);
}

// 4 x 4 ordered dither (Bayer), 0..1: where a plant is in a cross-fade, a pixel is drawn by one representation or
// the other.
float bayer(ivec2 p) {
    const float M[16] = float[](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);
    return (M[(p.y & 3) * 4 + (p.x & 3)] + 0.5) / 16.0;
}

struct PlantSurface {
    vec3 albedo; // linear
    vec3 normal; // the shading normal, in the space of n
    bool foliage;
};

// n: the shape's normal; msShape: the shape's point in metres (for the patterns); tint: the plant's 0..1
PlantSurface plantSurface(vec3 n, vec3 msShape, bool foliage, float tint, int kind) {
    PlantSurface p;
    p.foliage = foliage;
    if (foliage) {
        // a clump of leaves: one random tilt and shade per cell of the shape's space
        vec3 cell = hash3(floor(msShape * CLUMP_PER_M * (kind == 0 ? 1.5 : 1.0)) + tint * 17.0);
        p.normal = normalize(n + CLUMP_TILT * (cell - 0.5));
        p.albedo = mix(FOLIAGE_DARK[kind], FOLIAGE_LIGHT[kind], 0.5 * tint + 0.5 * cell.x);
    } else {
        // bark: the tile wrapped round the stem; the derivatives of u lose atan's jump of BARK_AROUND at the seam,
        // so the mipmap chosen there is its neighbours'
        vec2 uv = vec2(atan(msShape.z, msShape.x) * (BARK_AROUND / 6.2831853), msShape.y / BARK_TILE_M);
        vec2 ddx = dFdx(uv);
        vec2 ddy = dFdy(uv);
        ddx.x -= BARK_AROUND * round(ddx.x / BARK_AROUND);
        ddy.x -= BARK_AROUND * round(ddy.x / BARK_AROUND);
        vec3 at = vec3(uv, kind == 0 ? 0.0 : 1.0);
        vec2 t = textureGrad(uBarkDetail, at, ddx, ddy).xy * 2.0 - 1.0;
        // the frame: round the stem (u grows with atan(z, x)), up it, out of it
        vec3 around = cross(n, vec3(0.0, 1.0, 0.0));
        vec3 along = length(around) > 1e-3 ? normalize(around) : vec3(1.0, 0.0, 0.0);
        vec3 up = cross(along, n);
        p.normal = normalize(t.x * along + t.y * up + sqrt(max(1.0 - dot(t, t), 0.0)) * n);
        p.albedo = textureGrad(uBarkAlbedo, at, ddx, ddy).rgb * (1.0 + BARK_TINT * (2.0 * tint - 1.0));
    }
    return p;
}
