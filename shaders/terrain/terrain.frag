#version 330 core
// Terrain surface: the slope from the gradient map gives the tangent frame, the snow map and the height choose the
// materials (terrain/material/material.glsl), then the shared fog and the display transform.
// Variants, each its own program (#defines), chosen per patch on the CPU (engine: TerrainShading), so none pays for
// another's work (a branch on a uniform runs both sides on a software rasteriser):
//   (none)                 near patches: every material layer, fading into the far material over farBand;
//                          with MAT_TRIPLANAR (materials.cliffs=triplanar) the rock projected three ways
//   TERRAIN_FAR            patches wholly beyond farBand.y: the baked far material and the ground's slope (two
//                          lookups), the sky's reflection and light from the vertices (terrain.vert); with
//                          TERRAIN_CLIPMAP the material's coarse scale alone (MAT_COARSE_ONLY), as the near
//                          program shows it at farBand.y, since the unbounded world bakes none
//   TERRAIN_LEVELS         with TERRAIN_FAR: one colour per level of detail, lit (figure 6)
//   TERRAIN_TANGENT_SPACE  the tangent frame as colour (figure 4), no material
//   TERRAIN_CLIPMAP        the unbounded world (terrain.world=unbounded): the slope and the snow from the streamed
//                          clipmap's layer of the patch's level; the near program fades its fine scale out over
//                          farBand instead of fading into a baked material
//   TERRAIN_FARFIELD       with TERRAIN_FAR: the far field's ring (terrain/farfield.vert, FarField) instead of patches
#include "common/frame.glsl"
#include "common/color.glsl"
#include "terrain/material/material.glsl"
#ifdef TERRAIN_CLIPMAP
#include "terrain/stream/clipmap.glsl"
#endif
#ifdef TERRAIN_FAR
#include "common/forest.glsl"
#endif

in vec3 wsPos;
in vec4 air;                   // the air to this point, per vertex (terrain.vert)
flat in int lodLevel;
out vec4 fragColor;

#ifdef TERRAIN_CLIPMAP
uniform sampler2DArray slopes; // (dh/dx, dh/dz) of each level's window around the camera, wrapping (HeightClipmap)
uniform sampler2DArray snowMap; // r snow coverage (StreamedSnow), g the share of the sky seen (1 until it streams);
                                // b, a as the tile's (two channels: b 0, a 1, no erosion)
uniform float clipExtent;      // metres across level 0's window: clipSize · spacing
  #ifdef TERRAIN_FARFIELD
in float farRelief;            // 1 on the streamed relief, 0 on level ground where the window may not reach
uniform float uFarSnow;        // the level ground's snow: what the snow rule leaves at the mean height
  #endif
#else
uniform sampler2D gradients;   // (dh/dx, dh/dz) of the finest level, filtered (not read by the far variants)
uniform sampler2D snowMap;     // r snow coverage 0..1, g the share of the sky the relief leaves (HorizonSearch),
                               // b the erosion's sediment cover, a 1 - the bed it bared (ErosionCover)
uniform sampler2D farColour;   // baked steps 1-3 of material.glsl (FarMaterial): rgb albedo (sRGB stored), a gloss
uniform sampler2D farSlope;    // ... and rg the detail slope, encoded s * 0.5 + 0.5, ba the ground's (dh/dx, dh/dz)
uniform float extent;          // metres per map tile
#endif
uniform vec2 heightRange;      // lowest height, 1 / (highest - lowest), metres
uniform vec2 farBand;          // metres from the eye: the near material fades into the far one from x to y

// A distinct colour per level, so the quadtree cut reads at a glance.
vec3 levelColour(int level) {
    const vec3 palette[8] = vec3[8](vec3(0.90, 0.20, 0.15), vec3(0.95, 0.60, 0.10), vec3(0.90, 0.90, 0.20),
                                    vec3(0.30, 0.80, 0.25), vec3(0.15, 0.70, 0.80), vec3(0.20, 0.35, 0.90),
                                    vec3(0.60, 0.30, 0.85), vec3(0.85, 0.85, 0.85));
    return palette[min(level, 7)];
}

void main() {
#ifdef TERRAIN_CLIPMAP
    vec3 clipUv = clipmapCoordinates(wsPos.xz, lodLevel, clipExtent, textureSize(slopes, 0).x);
    vec2 slope = texture(slopes, clipUv).xy;
    vec4 snowAndSky = texture(snowMap, clipUv); // the sky seen: the far program's comes per vertex
  #ifdef TERRAIN_FARFIELD // past the window the layer wraps round to other ground: level ground there (farfield.vert)
    slope *= farRelief;
    snowAndSky.r = mix(uFarSnow, snowAndSky.r, farRelief);
  #endif
#else
    vec2 uv = wsPos.xz / extent + 0.5;
  #ifdef TERRAIN_FAR
    // the far ground's gradient baked beside its detail slope: one lookup fewer (the gradient map itself is finer
    // only on maps over FarMaterial.MAX_SIZE samples, whose far ground reads coarse mips of it anyway)
    vec4 farSlopes = texture(farSlope, uv);
    vec2 slope = farSlopes.ba;
  #else
    vec2 slope = texture(gradients, uv).xy;
  #endif
#endif
    TerrainSurface s;
    s.wsPos = wsPos;
    s.wsTangent = normalize(vec3(1.0, slope.x, 0.0));
    s.wsBitangent = normalize(vec3(0.0, slope.y, 1.0));
    s.wsNormal = normalize(vec3(-slope.x, 1.0, -slope.y));
#ifdef TERRAIN_TANGENT_SPACE
    // Figure 4: the local frame as colour: the tangent's rise (slope along x) red, the normal's height (flatness)
    // green, the bitangent's rise (slope along z) blue; squared into linear light
    vec3 color = 0.5 + 0.5 * vec3(s.wsTangent.y, s.wsNormal.y, s.wsBitangent.y);
    color = color * color;
#else
    MatTexel m;
  #if defined(TERRAIN_FAR) && !defined(TERRAIN_CLIPMAP)
    vec4 far = texture(farColour, uv);
    m.albedo = far.rgb;
    m.slope = farSlopes.rg * 2.0 - 1.0;
    m.height = 0.5;
    m.gloss = far.a;
    s.skyVisibility = 1.0; // taken into the sky light per vertex (terrain.vert)
  #else
    s.height01 = clamp((wsPos.y - heightRange.x) * heightRange.y, 0.0, 1.0);
    #ifndef TERRAIN_CLIPMAP
    vec4 snowAndSky = texture(snowMap, uv);
    #endif
    s.snow = snowAndSky.r;
    s.sediment = snowAndSky.b;
    s.bare = 1.0 - snowAndSky.a;
    #ifdef TERRAIN_FAR // the unbounded world's far ground: the coarse scale alone, its sky per vertex
    s.skyVisibility = 1.0;
    m = terrainMaterial(s, 1.0, matMacroTint(wsPos.xz));
    #else
    s.skyVisibility = snowAndSky.g;
    float eyeDistance = length(cameraPos() - wsPos);
      #ifdef TERRAIN_CLIPMAP // the fine scale fades out, so the near ground meets the far at the coarse scale alone
    float toFar = smoothstep(farBand.x, farBand.y, eyeDistance);
    m = terrainMaterial(s, mix(matCoarseWeight(eyeDistance), 1.0, toFar), matMacroTint(wsPos.xz));
      #else // fade into the baked far material, its weight computed after the material (fewer values live across it)
    m = terrainMaterial(s, matCoarseWeight(eyeDistance), matMacroTint(wsPos.xz));
    vec4 far = texture(farColour, uv);
    float toFar = smoothstep(farBand.x, farBand.y, eyeDistance);
    m.albedo = mix(m.albedo, far.rgb, toFar);
    m.slope = mix(m.slope, texture(farSlope, uv).rg * 2.0 - 1.0, toFar);
    m.gloss = mix(m.gloss, far.a, toFar);
      #endif
    #endif
  #endif
  #ifdef TERRAIN_FAR // the forests past the plants' reach: their canopy's colour, matte (common/forest.glsl)
    float forestShown;
    vec3 forestCrowns;
    m.albedo = forestGround(m.albedo, wsPos, s.wsNormal, forestCrowns, forestShown);
  #endif
    vec3 color = lightTerrain(s, m);
  #ifdef TERRAIN_FAR
    color = mix(color, forestCrowns, forestShown);
  #endif
  #ifdef TERRAIN_LEVELS
    float lightness = dot(color, vec3(0.2126, 0.7152, 0.0722));
    color = levelColour(lodLevel) * (0.25 + 1.5 * lightness);
  #endif
    color = color * air.a + air.rgb;
#endif
    fragColor = vec4(displayColor(color), 1.0);
}
