// The share of the sky seen from level L's sample p (HorizonSearch): along each of SKY_DIRECTIONS azimuths the
// horizon is the steepest rise to the ground at the distances searched, each read from the level HorizonSearch.levelAt
// picks (or, where the includer's heightOf cannot give it, the next coarser level that can; a distance no level gives
// is left out); V = (1/N) Σ cos² of the horizon's rise above the tangent plane. The includer defines, before it:
//   bool heightOf(int k, ivec2 base, vec2 offset, out float h)  level k's height at sample coordinates base + offset
// and the caller defines SKY_DIRECTIONS (HorizonSearch.DIRECTIONS) and SKY_STEPS (the most distances searched).

uniform int levels;             // the levels there are
uniform float spacing0;         // metres between level 0's samples; level k's are 2^k times as far apart
uniform int level;              // L, the level whose samples are shaded
uniform int steps;              // distances searched from level L
uniform float searchDistance[SKY_STEPS]; // metres, HorizonSearch.distances(d_L)
uniform int searchLevel[SKY_STEPS];      // the level read at each, HorizonSearch.levelAt

// cos² of the horizon's rise above the tangent plane, both given as slopes.
float visibleShare(float horizon, float plane) {
    if (horizon <= plane) {
        return 1.0;
    }
    float c = 1.0 + horizon * plane;
    return c <= 0.0 ? 0.0 : c * c / ((1.0 + horizon * horizon) * (1.0 + plane * plane));
}

// V at level L's sample p, its height h0 and its slope (dh/dx, dh/dz).
float skyVisible(ivec2 p, float h0, vec2 slope) {
    float sum = 0.0;
    for (int m = 0; m < SKY_DIRECTIONS; m++) {
        float angle = 6.28318531 * float(m) / float(SKY_DIRECTIONS);
        vec2 direction = vec2(cos(angle), sin(angle));
        float horizon = -1e30; // no ground found: the sky down to the plane
        for (int j = 0; j < steps; j++) {
            for (int k = searchLevel[j]; k < levels; k++) {
                int shift = k - level;
                ivec2 base = p >> shift;
                vec2 within = vec2(p - (base << shift)) / float(1 << shift);
                float h;
                if (heightOf(k, base, within + direction * (searchDistance[j] / (spacing0 * float(1 << k))), h)) {
                    horizon = max(horizon, (h - h0) / searchDistance[j]);
                    break;
                }
            }
        }
        sum += visibleShare(horizon, dot(slope, direction));
    }
    return sum / float(SKY_DIRECTIONS);
}
