// Where a point of the unbounded world lies in the streamed clipmap's texture arrays (engine: HeightClipmap,
// UnboundedWorld): level L's sample i lies at x = i · d_L and is texel i mod clipSize, whose centre is at
// (i + 0.5) / clipSize, so wrapping bilinear filtering reads a level's window as if it were the whole world.

// The texture coordinates (u, v, layer) of the point wsXZ (metres) on level `level`, whose window spans
// clipExtent · 2^level metres (clipExtent: level 0's, clipSize · spacing).
vec3 clipmapCoordinates(vec2 wsXZ, int level, float clipExtent, int clipSize) {
    return vec3(wsXZ / (clipExtent * exp2(float(level))) + 0.5 / float(clipSize), float(level));
}
