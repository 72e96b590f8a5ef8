// The virtual-pipe erosion's shared state and helpers (Mei, Decaudin and Hu 2007; the Java package
// org.openworld.engine.erosion.hydraulic has the equations and PipeErosion the CPU reference, which these passes
// follow operation for operation). One texel per cell, read exactly with texelFetch:
//   state: r terrain height b (m), g water depth d (m), b suspended sediment s (m), a water after the rain d1 (m)
//   flux:  the outflow through the pipes to the left (x - 1), right (x + 1), top (z - 1) and bottom (z + 1), m^3/s

uniform sampler2D uState;
uniform sampler2D uFlux;
uniform int uSize;         // cells per side
uniform int uPeriodic;     // 1: the grid wraps; 0: an apron, past whose edge lies dry ground
uniform float uDt;         // s
uniform float uRain;       // m/s
uniform float uSpacing;    // m: the pipes' length l
uniform float uCapacity;   // K_c, s/m
uniform float uDepthCap;   // m: deeper water carries no more
uniform float uDissolve;   // K_s
uniform float uDeposit;    // K_d
uniform float uEvaporate;  // K_e, 1/s
uniform float uMinSine;    // least sin(alpha) counted
uniform float uTalus;      // steepest slope left by the thermal step, m/m

const float GRAVITY = 9.81;       // m/s^2
const float THERMAL_SHARE = 0.125; // share of each side's excess drop that slides in one step
const float DRY = 1e-4;           // m: shallower water has no velocity
const ivec2 STEPS[4] = ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));

// The neighbour of cell c in direction k, wrapped; false past an apron's edge.
bool neighbour(ivec2 c, int k, out ivec2 at) {
    at = c + STEPS[k];
    if (uPeriodic == 1) {
        at = (at + uSize) % uSize;
        return true;
    }
    return all(greaterThanEqual(at, ivec2(0))) && all(lessThan(at, ivec2(uSize)));
}

// The flux of the neighbour in direction k through its pipe back towards c (0 past an apron's edge).
float inflow(ivec2 c, int k) {
    ivec2 at;
    if (!neighbour(c, k, at)) {
        return 0.0;
    }
    vec4 f = texelFetch(uFlux, at, 0);
    return k == 0 ? f.g : k == 1 ? f.r : k == 2 ? f.a : f.b; // left's right, right's left, top's bottom, bottom's top
}

// Velocity along one axis, m/s: the mean net flow through the cell's two faces over the face's width and the depth.
float velocity(float inLow, float outLow, float outHigh, float inHigh, float meanDepth) {
    if (meanDepth <= DRY) {
        return 0.0;
    }
    return 0.5 * ((inLow - outLow) + (outHigh - inHigh)) / (uSpacing * meanDepth);
}
