// Where a point of the unbounded world lies in the streamed clipmap's texture arrays (engine: HeightClipmap,
// UnboundedWorld): level L's sample i lies at x = i · d_L and is texel i mod clipSize, whose centre is at
// (i + 0.5) / clipSize, so wrapping bilinear filtering reads a level's window as if it were the whole world.

//
// Positions come from the render origin (frame.glsl's origin), a whole number of steps, each a root's side and so
// a whole number of samples of every level: the origin's share of a sample index is added in int, exactly, and the
// float part of a coordinate stays a few kilometres.

// The render origin's world sample index on `level` (level 0's samples: spacing = clipExtent / clipSize apart).
ivec2 clipmapOrigin(int level, float clipExtent, int clipSize) {
    int samplesPerStep = int(round(frame.origin.w * float(clipSize) / clipExtent));
    return (ivec2(frame.origin.xz) * samplesPerStep) >> level;
}

// The texture coordinates (u, v, layer) of the point wsXZ (metres from the render origin) on level `level`, whose
// window spans clipExtent · 2^level metres (clipExtent: level 0's, clipSize · spacing).
vec3 clipmapCoordinates(vec2 wsXZ, int level, float clipExtent, int clipSize) {
    vec2 originTexel = vec2(clipmapOrigin(level, clipExtent, clipSize) & (clipSize - 1));
    return vec3(wsXZ / (clipExtent * exp2(float(level))) + (originTexel + 0.5) / float(clipSize), float(level));
}
