// Where a point of the unbounded world lies in the streamed clipmap's texture arrays (engine: HeightClipmap,
// UnboundedWorld): level L's sample i lies at x = i · d_L and is texel i mod clipSize, whose centre is at
// (i + 0.5) / clipSize, so wrapping bilinear filtering reads a level's window as if it were the whole world.

//
// Positions come from the render origin (frame.glsl's origin), a whole number of steps, each a root's side and so
// a whole number of samples of every level: the origin's share of a sample index is added in int, exactly, and the
// float part of a coordinate stays a few kilometres.

// Where the render origin lies in level `level`'s window, texels (level-L samples modulo clipSize, with the fraction
// a coarse level's samples leave): level 0's samples are clipExtent / clipSize apart, a step holds a whole number of
// them, and the remainder modulo clipSize · 2^level is exact in int and then in float.
vec2 clipmapOrigin(int level, float clipExtent, int clipSize) {
    int samplesPerStep = int(round(frame.origin.w * float(clipSize) / clipExtent));
    ivec2 sample0 = ivec2(frame.origin.xz) * samplesPerStep;
    return vec2(sample0 & ((clipSize << level) - 1)) / exp2(float(level));
}

// The texture coordinates (u, v, layer) of the point wsXZ (metres from the render origin) on level `level`, whose
// window spans clipExtent · 2^level metres (clipExtent: level 0's, clipSize · spacing).
vec3 clipmapCoordinates(vec2 wsXZ, int level, float clipExtent, int clipSize) {
    vec2 originTexel = clipmapOrigin(level, clipExtent, clipSize);
    return vec3(wsXZ / (clipExtent * exp2(float(level))) + (originTexel + 0.5) / float(clipSize), float(level));
}
