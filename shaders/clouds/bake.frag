#version 330 core
// The base shape's field at this moment (engine: org.openworld.engine.sky.clouds.CloudVolumeSystem): one tile of the
// 3D field (2 axes of space, 1 of time) read at the texels' centres and the clouds' time, into a 2D texture of the
// same texels. Read bilinearly, it gives what the 3D field's trilinear read gives (the time's interpolation is the
// same for every texel), at four texels a read instead of eight: every sample of the march, the shadow map and the
// panorama reads it, so this pass of one tile's texels a frame halves the cost of the base shape's reads.

out vec4 field;

uniform sampler3D cloudFieldVolume; // the base shape's field: s, t one tile; r one period. Repeat
uniform vec2 uSize;                 // the tile's texels (the field's resolution)
uniform float uTime;                // the field's time coordinate: the clouds' phase plus half a frame

void main() {
    field = vec4(texture(cloudFieldVolume, vec3(gl_FragCoord.xy / uSize, uTime)).r, 0.0, 0.0, 1.0);
}
