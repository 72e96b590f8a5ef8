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
