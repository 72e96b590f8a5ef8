// Terrain materials (paper 2.2, figures 1, 3 and 4): grass low, rock in between and on steep slopes, snow high,
// each a synthesised tileable texture with a tangent-space normal map and a gloss map; lit by the sun and the sky.
// Engine side: org.openworld.engine.terrain.material.TerrainMaterials (binds everything below), TerrainTextures (synthesis).
//
//   vec3 shadeTerrain(TerrainSurface s)       linear RGB, lit, before fog: steps 1-5 below, as the near terrain does
//   MatTexel terrainMaterial(TerrainSurface s, float coarseWeight, vec2 macroTint)
//                                             steps 1-3: albedo, detail slope and gloss, unlit
//   vec3 lightTerrain(TerrainSurface s, MatTexel m)   steps 4-5: the detail normal and the light
// The far variant of the terrain (terrain.frag with TERRAIN_FAR) reads steps 1-3 baked once into world textures
// (bake.frag, engine: FarMaterial) and lights them with lightTerrain; on the unbounded world, which has no
// bake, it runs steps 1-3 at the coarse scale alone (MAT_COARSE_ONLY: half the lookups).
//
// Steps of shadeTerrain:
//   1. texture coordinates: a fine tile (detailScale) and a coarse one 6.3 times larger and turned by 34 degrees,
//      mixed by distance, with a macro noise over tens of metres on top: no tiling grid from afar (paper section 6);
//      with MAT_STOCHASTIC (materials.tiling=stochastic) each scale is tiled stochastically, with MAT_WANG
//      (materials.tiling=quilted) each is laid with quilted Wang tiles, so neither repeats;
//      with MAT_TRIPLANAR (materials.cliffs=triplanar, near terrain only) the rock is also projected along X and Z;
//      with MAT_COARSE_ONLY (the unbounded world's far terrain) only the coarse tile is read
//   2. how much rock and snow: rock by altitude and slope, snow from the snow map (or plain altitude bands), both
//      with noise-bent edges; snow slides off steep slopes; what the erosion left (ErosionCover): its sediment as
//      alluvium on gentle ground and scree on steep, its bared bed as rock, snow gathering on the sediment
//   3. layering: rock over grass where rock's relief stands highest first, snow over both filling hollows first
//   4. detail: the blended tangent-space normal through the TBN (wsTangent, wsBitangent, wsNormal)
//   5. light: Lambert sun, the sky's and the sunlit ground's irradiance for the normal (frame.glsl skyIrradiance)
//      where the relief leaves the sky visible, the light of the terrain where it hides it (HorizonSearch), a
//      normalised Blinn-Phong highlight and a Fresnel-weighted reflection of the environment map (the sky
//      system's), both scaled by the gloss map; each highlight widened by the normal's spread over the pixel
//      (specular anti-aliasing, materials.specular-aa)
#include "common/frame.glsl"
#include "common/environment.glsl"
#include "common/shadow.glsl"

uniform sampler2DArray uMatAlbedo; // layers MAT_GRASS, MAT_ROCK, MAT_SNOW; sRGB-stored colour, sampled linear
uniform sampler2DArray uMatDetail; // rg: tangent-space normal xy * 0.5 + 0.5; b: relief 0..1; a: gloss 0..1
uniform float uMatDetailScale;     // metres per fine tile
// The render origin's share of the lattices and tiles below (engine: origin.MaterialOrigin), computed in double and
// split into a whole part (xy, reduced modulo the hash's period) and a fraction (zw), so that a point's place
// on a lattice is a small float (its offset from the origin) plus these: its cell is floor(small + fraction) +
// whole, exact, and its place in the cell fract(small + fraction). All zero at the world's origin.
uniform vec4 uMatMacroOrigin[8];   // the macro noise's 8 octave lattices: matMacro's brightness [0..3], tint [4..7]
uniform vec4 uMatTileOrigin[6];    // the tiles' coordinates: [2 plane] fine, [2 plane + 1] coarse, planes xz, zy, xy
uniform int uMatSnowMode;          // MAT_SNOW_MAP or MAT_ALTITUDE_BANDS
uniform vec2 uMatSnowBand;         // ALTITUDE_BANDS: normalised heights where snow starts and is full (SnowLines)
uniform int uMatNormalMap;         // 1: perturb the normal with the normal maps
uniform int uMatGlossMap;          // 1: highlight and sky reflection, scaled by the gloss maps
uniform float uMatSkyOcclusion;    // 1: the relief hides its share of the sky (TerrainSurface.skyVisibility), 0: not
uniform float uMatSpecularAa;      // 1: highlights widened by the normal's spread over the pixel (step 5), 0: not

#ifdef TERRAIN_FAR
// The far terrain's sky reflection, per vertex at two levels of blur, and its sky light (terrain.vert): for the
// ground's normal there, without the detail normal, whose bumps are smaller than a far pixel anyway.
in vec3 skySharp;
in vec3 skyRough;
in vec3 skyLight;
#endif

// The light of the sky and of the ground around on the normal n, where the relief leaves `visible` of the sky
// (engine: HorizonSearch; frame.glsl skyIrradiance); the far ground's comes per vertex, already occluded.
vec3 matSkyLight(vec3 n, float visible) {
#ifdef TERRAIN_FAR
    return skyLight;
#else
    return skyIrradiance(n, mix(1.0, visible, uMatSkyOcclusion));
#endif
}

// The environment's radiance reflected towards the eye along r, blurred to level lod.
vec3 matSkyReflection(vec3 r, float lod) {
#ifdef TERRAIN_FAR
    return environmentBetween(skySharp, skyRough, lod);
#else
    return environmentRadiance(r, lod);
#endif
}

struct TerrainSurface {
    vec3 wsPos;        // world position, metres
    vec3 wsNormal;     // unit geometric normal of the terrain (from the height field)
    vec3 wsTangent;    // unit, along +X tilted with the slope:  normalize(vec3(1, dh/dx, 0))
    vec3 wsBitangent;  // unit, along +Z tilted with the slope: normalize(vec3(0, dh/dz, 1))
    float height01;    // height normalised over the map's range, 0 = lowest, 1 = highest
    float snow;        // snow-map coverage here, 0..1 (already filtered)
    float skyVisibility; // share of the sky the relief leaves here, 0..1 (HorizonSearch; the far ground: per vertex)
    float sediment;    // the erosion's sediment cover here, 0..1 (ErosionCover; 0 where none ran)
    float bare;        // the bed the erosion bared here, 0..1
};

const float MAT_GRASS = 0.0;         // texture array layers (TerrainTextures.Material order)
const float MAT_ROCK = 1.0;
const float MAT_SNOW = 2.0;
const int MAT_SNOW_MAP = 0;          // MaterialSettings.SnowMode
const int MAT_ALTITUDE_BANDS = 1;

// 1. scales
const float MAT_COARSE_FACTOR = 6.3; // coarse tile / fine tile (2.7 m -> 17 m): not an integer, so the two grids
                                     // never fall into step and their sum does not repeat at any visible distance
const float MAT_COARSE_TURN = 0.6;   // radians (34 deg) the coarse tile is turned, so its rows cross the fine ones
const float MAT_COARSE_NEAR = 6.0;   // metres: closer, the fine tile dominates (the coarse one's texels look blurry)
const float MAT_COARSE_FAR = 60.0;   // metres: farther, the coarse tile dominates (the fine one would repeat visibly)
const float MAT_MACRO_SCALE = 120.0; // metres: wavelength of the macro noise's lowest octave
// 2. where the materials lie
const float MAT_GRASS_LINE = 0.45;   // normalised height where grass gives way to rock
const float MAT_ROCK_SLOPE = 0.82;   // normal.y (35 deg) from which soil no longer holds and rock shows...
const float MAT_ROCK_CLIFF = 0.68;   // ... fully rock at normal.y 0.68 (47 deg)
const float MAT_SNOW_HOLDS = 0.62;   // normal.y (52 deg) beyond which snow starts to slide off...
const float MAT_SNOW_SLIDES = 0.48;  // ... and is gone at normal.y 0.48 (61 deg)
const float MAT_SCREE_SLOPE = 0.9;   // normal.y (26 deg) from which sediment lies as scree rather than alluvium...
const float MAT_SCREE_FULL = 0.8;    // ... all scree at normal.y 0.8 (37 deg, the talus the erosion leaves: 38 deg)
const float MAT_SNOW_GULLY = 0.35;   // snow-map probability added where the erosion's sediment lies: snow slides
                                     // off the faces above into the gullies and onto the scree below them
const float MAT_EDGE_NOISE = 0.12;   // normalised height / slope by which the macro noise bends the blend edges
const float MAT_LAYER_SOFTNESS = 0.15; // relief units over which a layer's cover fades (height-based blending)
// 5. light
const float MAT_F0 = 0.04;           // Fresnel reflectance at normal incidence of rock, leaves and ice (IOR ~1.3-1.5)
const float MAT_MAX_POWER = 2048.0;  // Blinn-Phong exponent at gloss 1 (power = MAX_POWER^gloss): sharp sun glints
const float MAT_PIXEL_VARIANCE = 0.25; // square pixels: the variance of a pixel's filter (a Gaussian of 0.5 px),
                                       // times the normal's change per pixel squared: its spread over the pixel
const float MAT_MAX_SPREAD = 0.18;   // most spread counted (Kaplanyan et al.'s kappa): a crease or a silhouette,
                                     // where the normal jumps between pixels, dulls the highlight but keeps some

// Schlick's Fresnel reflectance at a cosine: F0 + (1 - F0)(1 - cos)^5, the fifth power by multiplications (a pow
// is a log and an exponential per pixel on a rasteriser without special-function units).
float matFresnel(float cosine) {
    float m = 1.0 - cosine;
    float m2 = m * m;
    return MAT_F0 + (1.0 - MAT_F0) * m2 * m2 * m;
}

// Hash of a lattice point to 0..1, without sin (stable across GPUs): Dave Hoskins, "Hash without Sine". Periodic
// in 10000 cells (origin.MaterialOrigin.HASH_PERIOD): 0.1031 times it is the whole number 1031, which fract drops.
float matHash(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

// Value noise with quintic fade, 0..1, at the point p + whole of its lattice (whole: whole cells).
float matValueNoise(vec2 p, vec2 whole) {
    vec2 i = floor(p) + whole;
    vec2 f = fract(p);
    vec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    float a = matHash(i);
    float b = matHash(i + vec2(1.0, 0.0));
    float c = matHash(i + vec2(0.0, 1.0));
    float d = matHash(i + vec2(1.0, 1.0));
    return mix(mix(a, b, u.x), mix(c, d, u.x), u.y);
}

// Four octaves of value noise from MAT_MACRO_SCALE down to 15 m, 0..1 (mean 0.5); not periodic, so it never repeats
// (but for the hash's period, 1200 km). The lattices' first four origins (uMatMacroOrigin) from `first`.
float matMacro(vec2 wsXZ, int first) {
    const mat2 turn = mat2(0.80, 0.60, -0.60, 0.80); // each octave turned by 37 deg so the lattices do not align
    vec2 p = wsXZ / MAT_MACRO_SCALE;
    float sum = 0.0;
    float amplitude = 0.5;
    for (int i = 0; i < 4; i++) {
        vec4 origin = uMatMacroOrigin[first + i];
        sum += amplitude * matValueNoise(p + origin.zw, origin.xy);
        p = turn * p * 2.0 + 13.7;
        amplitude *= 0.5;
    }
    return sum / 0.9375;
}

// The macro variation at wsXZ: x brightens and darkens and bends the blend edges, y tints; both 0..1.
vec2 matMacroTint(vec2 wsXZ) {
    return vec2(matMacro(wsXZ, 0), matMacro(wsXZ.yx * 1.7 + 311.0, 4));
}

// One material's texels at both scales, mixed; slope is the tangent-space normal's xy in the world's X/Z frame.
struct MatTexel {
    vec3 albedo;
    vec2 slope;
    float height;
    float gloss;
};

#ifdef MAT_STOCHASTIC
// Stochastic tiling (Heitz and Neyret 2018, materials.tiling=stochastic; MaterialSettings.Tiling): the plane is cut
// into equilateral triangles MAT_STOCHASTIC_CELL tiles across, each triangle corner shifts the texture by its own
// random offset, and a pixel blends the three lookups of its triangle's corners by its barycentric weights w. A plain
// linear blend would wash the texture out towards its mean where three patches mix; the variance-preserving blend
//     x = mean + sum_i w_i (x_i - mean) / sqrt(sum_i w_i^2)
// keeps the contrast (for uncorrelated x_i of one variance, the variance of the sum is sum_i w_i^2 times it). The
// paper's full operator first makes the texture Gaussian and maps back through an inverse lookup table so the
// histogram is kept exactly; this one keeps the mean and the variance only (see docs/terrain.md, section 4).
const float MAT_STOCHASTIC_CELL = 0.29; // tiles per triangle side (1 / 2 sqrt 3, the paper's): a patch small enough
                                        // that no two triangles side by side show the same feature

// The triangle around uv (in tiles): the texture coordinates of its three corners' shifted copies and their weights.
struct MatTiles {
    vec2 uv0;
    vec2 uv1;
    vec2 uv2;
    vec3 w;
    float norm;  // 1 / sqrt(sum w^2)
    vec2 dx;     // derivatives of uv across the pixel, for every lookup: the shifted coordinates jump at triangle
    vec2 dy;     // edges, and implicit derivatives there would pick the coarsest mip (a seam of blur)
};

MatTiles matTiles(vec2 uv) {
    // skewed space: the triangular lattice becomes the square one, each square cut into two triangles by x + y = 1
    const mat2 toSkewed = mat2(1.0, 0.0, -0.57735027, 1.15470054); // columns: (1, 0), (-1/sqrt 3, 2/sqrt 3)
    vec2 skewed = toSkewed * (uv / MAT_STOCHASTIC_CELL);
    vec2 base = floor(skewed);
    vec2 f = skewed - base;
    float upper = step(1.0, f.x + f.y); // 0: lower triangle (corners base, +y, +x), 1: upper (+x+y, +x, +y)
    vec2 c0 = base + vec2(upper);
    vec2 c1 = base + vec2(upper, 1.0 - upper);
    vec2 c2 = base + vec2(1.0 - upper, upper);
    MatTiles t;
    // barycentric weights: each 1 at its own corner and 0 on the opposite edge
    t.w = mix(vec3(1.0 - f.x - f.y, f.y, f.x), vec3(f.x + f.y - 1.0, 1.0 - f.y, 1.0 - f.x), upper);
    t.norm = inversesqrt(dot(t.w, t.w));
    t.uv0 = uv + vec2(matHash(c0), matHash(c0 + 71.3));
    t.uv1 = uv + vec2(matHash(c1), matHash(c1 + 71.3));
    t.uv2 = uv + vec2(matHash(c2), matHash(c2 + 71.3));
    t.dx = dFdx(uv);
    t.dy = dFdy(uv);
    return t;
}

// The variance-preserving blend of the three shifted lookups of layer in tex, around the layer's mean (its 1x1 mip).
vec4 matLookup(sampler2DArray tex, float layer, MatTiles t) {
    vec4 mean = textureLod(tex, vec3(0.5, 0.5, layer), 16.0);
    vec4 sum = t.w.x * (textureGrad(tex, vec3(t.uv0, layer), t.dx, t.dy) - mean)
             + t.w.y * (textureGrad(tex, vec3(t.uv1, layer), t.dx, t.dy) - mean)
             + t.w.z * (textureGrad(tex, vec3(t.uv2, layer), t.dx, t.dy) - mean);
    return clamp(mean + sum * t.norm, 0.0, 1.0);
}

struct MatCoords {
    MatTiles fine;
    MatTiles coarse;
    float coarseWeight;
};
#elif defined(MAT_WANG)
// Quilted Wang tiles (Cohen et al. 2003, materials.tiling=quilted; engine: WangTiles): the textures are an atlas of
// 4 x 4 tiles, one per choice of two colours on each edge, with the same texels along every edge of one colour. Each
// cell of the tile grid (one tile per unit of uv) takes the colour of each of its edges from a hash of the edge's
// integer coordinates, so a cell and its neighbour agree on the edge they share and the ground is seamless, with no
// period. Atlas column by (west, east) colour: (0,0), (0,1), (1,1), (1,0), so column = 2 west + (west xor east);
// rows likewise by (north, south).
const float MAT_WANG_ATLAS = 4.0; // tiles along the atlas's side (WangTiles.ATLAS)

// Where to read a cell's tile: the atlas coordinates and the derivatives of the continuous uv.
struct MatCell {
    vec2 uv;
    vec2 dx; // explicit: the atlas coordinates jump at cell edges, and implicit derivatives there would pick the
    vec2 dy; // coarsest mip (a seam of blur)
};

MatCell matCell(vec2 uv, vec2 whole) {
    vec2 local = floor(uv);
    vec2 cell = local + whole;
    // a horizontal edge's colour from one hash, a vertical edge's from another (offset lattice)
    float north = step(0.5, matHash(cell));
    float south = step(0.5, matHash(cell + vec2(0.0, 1.0)));
    float west = step(0.5, matHash(cell + vec2(517.0, 211.0)));
    float east = step(0.5, matHash(cell + vec2(518.0, 211.0)));
    vec2 tile = vec2(2.0 * west + abs(west - east), 2.0 * north + abs(north - south));
    MatCell c;
    c.uv = (tile + (uv - local)) / MAT_WANG_ATLAS;
    c.dx = dFdx(uv) / MAT_WANG_ATLAS;
    c.dy = dFdy(uv) / MAT_WANG_ATLAS;
    return c;
}

vec4 matLookup(sampler2DArray tex, float layer, MatCell c) {
    return textureGrad(tex, vec3(c.uv, layer), c.dx, c.dy);
}

struct MatCoords {
    MatCell fine;
    MatCell coarse;
    float coarseWeight;
};
#else
struct MatCoords {
    vec2 fine;
    vec2 coarse;
    float coarseWeight;
};

// Implicit derivatives: every layer is sampled on every pixel, outside any branch (on a software rasteriser a branch
// skips nothing, and explicit gradients, which sampling under branches needs, cost a per-pixel LOD of their own).
vec4 matLookup(sampler2DArray tex, float layer, vec2 uv) {
    return texture(tex, vec3(uv, layer));
}
#endif

// The texture coordinates at both scales of a point p (metres from the render origin) in a projection's plane (0: xz,
// 1: zy, 2: xy): the fine tile, and the coarse one 6.3 times larger and turned. The tiles repeat every unit, so the
// origin's whole tiles matter only to the tilings that hash their cells.
MatCoords matCoords(vec2 p, float coarseWeight, int plane) {
    const mat2 turn = mat2(0.8253, 0.5646, -0.5646, 0.8253); // rotation by MAT_COARSE_TURN
    vec4 fineOrigin = uMatTileOrigin[2 * plane];
    vec4 coarseOrigin = uMatTileOrigin[2 * plane + 1];
    vec2 fine = p / uMatDetailScale;
    vec2 coarse = turn * fine / MAT_COARSE_FACTOR + coarseOrigin.zw;
    fine += fineOrigin.zw;
    MatCoords c;
#ifdef MAT_STOCHASTIC
    // (its triangles' lattice is skewed: the origin's whole tiles, reduced, shift it by a float, not a whole cell)
    c.coarse = matTiles(coarse + coarseOrigin.xy);
  #ifndef MAT_COARSE_ONLY
    c.fine = matTiles(fine + fineOrigin.xy);
  #endif
#elif defined(MAT_WANG)
    c.coarse = matCell(coarse, coarseOrigin.xy);
  #ifndef MAT_COARSE_ONLY
    c.fine = matCell(fine, fineOrigin.xy);
  #endif
#else
    c.fine = fine;
    c.coarse = coarse;
#endif
    c.coarseWeight = coarseWeight;
    return c;
}

// One material at both scales: repeated, Wang or stochastic tiles (matLookup), the same for albedo and detail.
MatTexel matSample(float layer, MatCoords c) {
    const mat2 unturn = mat2(0.8253, -0.5646, 0.5646, 0.8253); // rotation by -MAT_COARSE_TURN: coarse slopes to world
#ifdef MAT_COARSE_ONLY
    vec4 albedoCoarse = matLookup(uMatAlbedo, layer, c.coarse);
    vec4 detailCoarse = matLookup(uMatDetail, layer, c.coarse);
    MatTexel t;
    t.albedo = albedoCoarse.rgb;
    t.slope = unturn * (detailCoarse.rg * 2.0 - 1.0);
    t.height = detailCoarse.b;
    t.gloss = detailCoarse.a;
    return t;
#else
    vec4 albedoFine = matLookup(uMatAlbedo, layer, c.fine);
    vec4 detailFine = matLookup(uMatDetail, layer, c.fine);
    vec4 albedoCoarse = matLookup(uMatAlbedo, layer, c.coarse);
    vec4 detailCoarse = matLookup(uMatDetail, layer, c.coarse);
    MatTexel t;
    t.albedo = mix(albedoFine.rgb, albedoCoarse.rgb, c.coarseWeight);
    t.slope = mix(detailFine.rg * 2.0 - 1.0, unturn * (detailCoarse.rg * 2.0 - 1.0), c.coarseWeight);
    t.height = mix(detailFine.b, detailCoarse.b, c.coarseWeight);
    t.gloss = mix(detailFine.a, detailCoarse.a, c.coarseWeight);
    return t;
#endif
}

#ifdef MAT_TRIPLANAR
// Cliffs (materials.cliffs=triplanar, the near program only; MaterialSettings.Cliffs): seen from above, a face of
// slope a stretches the texture by 1 / cos a down its fall line (2.9 times at 70 degrees). So the rock is also
// projected along the world's X and Z axes, onto the planes (z, y) and (x, y), and the three projections blend by the
// geometric normal n with weights w = |n|^k / sum |n|^k, k = 8: each plane shows where the surface faces it (stretched
// at most sqrt 3 times where it weighs most, 1.06 times on a 70 degree face), and the blend band is narrow (a side
// plane weighs 5 % at 35 degrees of slope and the top one 5 % at 55). Only rock: grass and snow do not lie on cliffs.

// The rock at s, projected three ways and blended by the normal; top is the projection from above.
MatTexel matRockTriplanar(TerrainSurface s, MatCoords top) {
    vec3 n2 = s.wsNormal * s.wsNormal;
    vec3 n4 = n2 * n2;
    vec3 w = n4 * n4; // |n|^8 by multiplications: a pow is a log and an exponential per pixel on a rasteriser
    w /= w.x + w.y + w.z;
    MatTexel fromTop = matSample(MAT_ROCK, top);
    MatTexel alongX = matSample(MAT_ROCK, matCoords(s.wsPos.zy, top.coarseWeight, 1));
    MatTexel alongZ = matSample(MAT_ROCK, matCoords(s.wsPos.xy, top.coarseWeight, 2));
    // The detail slope is the normal map's tangent-space xy along a projection's texture axes u, v; lightTerrain
    // reads it along the terrain's frame T (the slope along +X) and B (along +Z). The (z, y) plane's u runs along +Z,
    // which is B's direction on a face that faces X, and its v runs up, which is T or -T (T rises with the ground
    // along +X); so its (u, v) is the frame's (y, +-x). Likewise the (x, y) plane's u is T and its v is +-B. Without
    // this swizzle the bumps on a cliff would be lit from the wrong side.
    float up = s.wsTangent.y < 0.0 ? -1.0 : 1.0;
    alongX.slope = vec2(up * alongX.slope.y, alongX.slope.x);
    up = s.wsBitangent.y < 0.0 ? -1.0 : 1.0;
    alongZ.slope = vec2(alongZ.slope.x, up * alongZ.slope.y);
    MatTexel t;
    t.albedo = w.y * fromTop.albedo + w.x * alongX.albedo + w.z * alongZ.albedo;
    t.slope = w.y * fromTop.slope + w.x * alongX.slope + w.z * alongZ.slope;
    t.height = w.y * fromTop.height + w.x * alongX.height + w.z * alongZ.height;
    t.gloss = w.y * fromTop.gloss + w.x * alongX.gloss + w.z * alongZ.gloss;
    return t;
}
#endif

// Cover of a layer of amount 0..1 over ground whose relief is 0..1: it first fills where relief is low.
float matCover(float amount, float relief) {
    float s = MAT_LAYER_SOFTNESS;
    return smoothstep(relief - s, relief + s, amount * (1.0 + 2.0 * s) - s);
}

// The coarse tile's weight seen from eyeDistance metres: from 0.3 within MAT_COARSE_NEAR to 0.8 beyond MAT_COARSE_FAR.
float matCoarseWeight(float eyeDistance) {
    return mix(0.3, 0.8, smoothstep(MAT_COARSE_NEAR, MAT_COARSE_FAR, eyeDistance));
}

// Steps 1-3 at s with the coarse tile weighing coarseWeight (matCoarseWeight, or 1 where only it is read), under the
// macro variation macroTint (matMacroTint): the surface's albedo, detail slope and gloss, before light.
MatTexel terrainMaterial(TerrainSurface s, float coarseWeight, vec2 macroTint) {
    float n0y = s.wsNormal.y;

    // 1. texture coordinates at two scales, projected from above, and the macro variation
    MatCoords c = matCoords(s.wsPos.xz, coarseWeight, 0);
    float macro = macroTint.x;
    float tint = macroTint.y;
    float edge = (macro - 0.5) * 2.0 * MAT_EDGE_NOISE;

    // 2. amounts of rock and snow
    float rockByHeight = smoothstep(MAT_GRASS_LINE - 0.06, MAT_GRASS_LINE + 0.06, s.height01 + edge);
    float rockBySlope = smoothstep(MAT_ROCK_SLOPE, MAT_ROCK_CLIFF, n0y + 0.5 * edge);
    float rockAmount = max(rockByHeight, rockBySlope);
    // what the erosion left (ErosionCover): sediment is scree on steep ground (the talus's foot), alluvium on gentle
    // ground (valley floors, over the rock that the height alone would put there); the bared bed is rock
    float screeShare = smoothstep(MAT_SCREE_SLOPE, MAT_SCREE_FULL, n0y + 0.5 * edge);
    float scree = s.sediment * screeShare;
    float alluvium = s.sediment * (1.0 - screeShare);
    rockAmount = max(max(rockAmount * (1.0 - alluvium), s.bare), scree);
    float sticks = smoothstep(MAT_SNOW_SLIDES, MAT_SNOW_HOLDS, n0y) * (1.0 - s.bare);
    float snowByMap = smoothstep(0.3, 0.7, s.snow + edge * 2.0 + MAT_SNOW_GULLY * s.sediment) * sticks;
    float snowByBand = smoothstep(uMatSnowBand.x, uMatSnowBand.y, s.height01);
    float snowAmount = uMatSnowMode == MAT_SNOW_MAP ? snowByMap : snowByBand;

    // 3. layers: grass, rock over grass (its highest relief first), snow over both (hollows first); a layer that is
    // absent covers nothing (matCover(0, relief) = 0), so every layer is blended without a branch
    MatTexel grass = matSample(MAT_GRASS, c);
#ifdef MAT_TRIPLANAR
    MatTexel rock = matRockTriplanar(s, c);
#else
    MatTexel rock = matSample(MAT_ROCK, c);
#endif
    MatTexel snow = matSample(MAT_SNOW, c);
    // macro: greener and yellower, lighter and darker patches of meadow
    grass.albedo *= mix(vec3(0.75, 0.85, 0.8), vec3(1.3, 1.15, 0.8), tint) * (0.8 + 0.4 * macro);
    float rockCover = matCover(rockAmount, 1.0 - rock.height);
    MatTexel surface;
    surface.albedo = mix(grass.albedo, rock.albedo, rockCover);
    surface.slope = mix(grass.slope, rock.slope, rockCover);
    surface.height = mix(grass.height, rock.height, rockCover);
    surface.gloss = mix(grass.gloss, rock.gloss, rockCover);
    surface.albedo *= mix(vec3(1.0), vec3(0.85 + 0.3 * tint, 0.85 + 0.25 * tint, 0.9 + 0.15 * tint), rockCover);
    // scree: fresh broken rock, lighter than the weathered faces it fell from; alluvium: pale grey-beige gravel and
    // sand (the rock's texels, washed), matte, under a thin meadow where the macro noise is green
    surface.albedo *= 1.0 + 0.3 * scree;
    float gravel = matCover(alluvium * (1.1 - 0.4 * tint), 1.0 - rock.height);
    surface.albedo = mix(surface.albedo, rock.albedo * vec3(1.25, 1.18, 1.0), gravel);
    surface.slope = mix(surface.slope, rock.slope * 0.5, gravel);
    surface.gloss = mix(surface.gloss, 0.5 * rock.gloss, gravel);
    float snowCover = matCover(snowAmount, surface.height);
    surface.albedo = mix(surface.albedo, snow.albedo, snowCover);
    surface.slope = mix(surface.slope, snow.slope, snowCover);
    surface.gloss = mix(surface.gloss, snow.gloss, snowCover);
    return surface;
}

// Steps 4-5: the material m lit at s (its slope ignored while the normal maps are off).
vec3 lightTerrain(TerrainSurface s, MatTexel m) {
    vec3 toEye = cameraPos() - s.wsPos;
    vec3 v = toEye / max(length(toEye), 1e-4);
    vec3 l = sunDir();
    vec3 n0 = s.wsNormal;

    // 4. detail normal: tangent-space (x along +u = +X, y along +v = +Z) through the terrain's TBN
    vec3 n = n0;
    if (uMatNormalMap == 1) {
        vec3 ts = vec3(m.slope, sqrt(max(1.0 - dot(m.slope, m.slope), 0.0)));
        n = normalize(s.wsTangent * ts.x + s.wsBitangent * ts.y + n0 * ts.z);
    }

    // 5. light: the sun only where it is seen (the shadow maps)
    float sunFacing = smoothstep(-0.05, 0.1, dot(n0, l)); // bumps cannot be lit from behind the terrain itself
    sunFacing *= sunVisibility(s.wsPos, n0);
    float nl = max(dot(n, l), 0.0) * sunFacing;
    vec3 sky = matSkyLight(n, s.skyVisibility); // the sky, and the sunlit ground around: the light in the shadows
    vec3 color = m.albedo * (frame.sunColor.rgb * nl + sky);
    // specular anti-aliasing (Toksvig 2005, the normal's spread over the pixel measured in screen space after
    // Kaplanyan, Hill, Patney and Lefohn 2016): a pixel covers normals that differ by about its neighbours' change,
    // and Toksvig widens a Blinn-Phong lobe of power p over normals of spread s2 to p / (1 + p s2); computed before
    // the branch, as derivatives need every pixel of the quad
    vec3 dnx = dFdx(n);
    vec3 dny = dFdy(n);
    float spread = uMatSpecularAa * min(MAT_PIXEL_VARIANCE * (dot(dnx, dnx) + dot(dny, dny)), MAT_MAX_SPREAD);
    if (uMatGlossMap == 1) {
        float gloss = m.gloss;
        float power = pow(MAT_MAX_POWER, gloss);
        power /= 1.0 + power * spread;
        float sharpness = log2(power) / log2(MAT_MAX_POWER); // the widened lobe's gloss: how blurred the sky is
        vec3 h = normalize(l + v);
        float vh = max(dot(v, h), 0.0);
        float fresnelSun = matFresnel(vh);
        // normalised Blinn-Phong: (p + 8) / (8 pi) keeps the highlight's energy as it sharpens
        float specular = (power + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), power) * fresnelSun * gloss;
        color += frame.sunColor.rgb * specular * nl;
        vec3 r = reflect(-v, n);
        float nv = max(dot(n, v), 0.0);
        float fresnelView = matFresnel(nv);
        color += matSkyReflection(r, (1.0 - sharpness) * ENVIRONMENT_MAX_LOD) * fresnelView * gloss * gloss;
    }
    return color;
}

// Steps 1-5: the surface at s, lit.
vec3 shadeTerrain(TerrainSurface s) {
    float coarseWeight = matCoarseWeight(length(cameraPos() - s.wsPos));
    return lightTerrain(s, terrainMaterial(s, coarseWeight, matMacroTint(s.wsPos.xz)));
}
