// The environment map: the sky's radiance around the scene (display units), rendered by the sky system into a cube
// map when the sky changes; its mip levels are ever blurrier skies for ever rougher reflections.
// Engine: org.openworld.engine.environment.SkyMaps; bound by the engine (gl.SharedTexture.ENVIRONMENT).

uniform samplerCube environmentMap;

// Levels of the cube map: ENVIRONMENT_SIZE (64) texels a side down to 1, so lod 0 .. 6.
const float ENVIRONMENT_MAX_LOD = 6.0;

// The sky's radiance towards wsDir, lod 0 sharp .. ENVIRONMENT_MAX_LOD the average over about a hemisphere.
vec3 environmentRadiance(vec3 wsDir, float lod) {
    return textureLod(environmentMap, wsDir, lod).rgb;
}

// Two fixed levels for a surface that reads the environment per vertex and blends per pixel (the far terrain,
// terrain/terrain.vert): a cube map lookup is the dearest texture read on a software rasteriser (a face chosen and a
// seamless trilinear filter per pixel), and a distant surface's reflection varies little across a triangle.
const float ENVIRONMENT_SHARP_LOD = 2.0; // 16 texels a face side: gloss 2/3 (wet rock, snow)
const float ENVIRONMENT_ROUGH_LOD = 5.0; // 2 texels a face side: gloss 1/6 (grass)

// The radiance at level lod from the two fixed levels' radiance: linear in the level between them, as a trilinear
// filter is between neighbouring levels, and the nearer one's outside.
vec3 environmentBetween(vec3 sharp, vec3 rough, float lod) {
    float t = clamp((lod - ENVIRONMENT_SHARP_LOD) / (ENVIRONMENT_ROUGH_LOD - ENVIRONMENT_SHARP_LOD), 0.0, 1.0);
    return mix(sharp, rough, t);
}
