// A plant's surface (engine: org.openworld.engine.vegetation): its albedo and its shading normal, made from the
// shape's own coordinates (no texture to download or bake): clumps of leaves that turn their own way, bark in
// vertical streaks. Shared by the meshes (tree.frag) and the impostors' bake (bake.frag), so the two agree.

// Albedos, linear, dark and light ends of each kind's foliage: spruce needles reflect 3-8 % of visible light (dark,
// bluish green), beech and oak leaves 8-12 % (yellower), shrubs in between; bark a little more, brown.
const vec3 FOLIAGE_DARK[3] = vec3[](vec3(0.026, 0.050, 0.030), vec3(0.045, 0.075, 0.025), vec3(0.040, 0.060, 0.028));
const vec3 FOLIAGE_LIGHT[3] = vec3[](vec3(0.050, 0.080, 0.035), vec3(0.085, 0.120, 0.035), vec3(0.070, 0.095, 0.035));
const vec3 BARK = vec3(0.10, 0.065, 0.040);
// Leaf clumps about 0.7 m across, needle tufts a little finer; they tilt the normal by up to this much.
const float CLUMP_PER_M = 1.4;
const float CLUMP_TILT = 0.45;

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
        // bark: streaks along the stem, a few centimetres across
        float streak = hash3(vec3(floor(atan(msShape.z, msShape.x) * 8.0), 0.0, tint)).x;
        p.normal = n;
        p.albedo = BARK * (0.7 + 0.6 * streak);
    }
    return p;
}
