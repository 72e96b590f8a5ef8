#version 330 core
// Virtual-pipe erosion, pass 3 (PipeErosion.transportPass and thermalPass): the suspended sediment moved with the
// water, evaporation, and the thermal slide. uAdvection 1: donor cell along the pipes (each pipe carries its share of
// the cell's water's load: conservative); 0: the paper's semi-Lagrangian step, the load found at x - v dt read
// bilinearly. The thermal step (Musgrave, Kolb and Mace 1989) reads the bed this pass reads, which the transport
// does not change, so it joins this pass: an eighth of each side's drop in excess of the talus slides down, nothing
// across an apron's edge.
#include "erosion/pipe.glsl"

uniform int uAdvection;

out vec4 outState;

// The part of a cell's load that a pipe carries: the share of the cell's water it carries this step.
float share(float load, float f, float water, float area) {
    return water > 0.0 ? load * (f * uDt / (water * area)) : 0.0;
}

float donorCell(ivec2 c, vec4 here, float area) {
    vec4 out4 = texelFetch(uFlux, c, 0);
    float stays = here.b;
    for (int k = 0; k < 4; k++) {
        stays -= share(here.b, out4[k], here.a, area);
        ivec2 at;
        if (neighbour(c, k, at)) {
            vec4 there = texelFetch(uState, at, 0);
            stays += share(there.b, inflow(c, k), there.a, area);
        }
    }
    return stays;
}

float loadAt(ivec2 i) {
    i = uPeriodic == 1 ? (i + uSize) % uSize : clamp(i, ivec2(0), ivec2(uSize - 1));
    return texelFetch(uState, i, 0).b;
}

float upstream(ivec2 c, vec4 here) {
    vec4 out4 = texelFetch(uFlux, c, 0);
    float mean = 0.5 * (here.a + here.g);
    float u = velocity(inflow(c, 0), out4[0], out4[1], inflow(c, 1), mean);
    float v = velocity(inflow(c, 2), out4[2], out4[3], inflow(c, 3), mean);
    vec2 p = vec2(c) - vec2(u, v) * uDt / uSpacing;
    vec2 p0 = floor(p);
    vec2 t = p - p0;
    ivec2 i0 = ivec2(p0);
    float top = loadAt(i0) + (loadAt(i0 + ivec2(1, 0)) - loadAt(i0)) * t.x;
    float bottom = loadAt(i0 + ivec2(0, 1)) + (loadAt(i0 + ivec2(1, 1)) - loadAt(i0 + ivec2(0, 1))) * t.x;
    return top + (bottom - top) * t.y;
}

float thermal(ivec2 c, float bed) {
    float limit = uTalus * uSpacing;
    float change = 0.0;
    for (int k = 0; k < 4; k++) {
        ivec2 at;
        if (neighbour(c, k, at)) {
            float there = texelFetch(uState, at, 0).r;
            change += THERMAL_SHARE * max(0.0, there - bed - limit) - THERMAL_SHARE * max(0.0, bed - there - limit);
        }
    }
    return bed + change;
}

void main() {
    ivec2 c = ivec2(gl_FragCoord.xy);
    vec4 here = texelFetch(uState, c, 0);
    float load = uAdvection == 1 ? donorCell(c, here, uSpacing * uSpacing) : upstream(c, here);
    outState = vec4(thermal(c, here.r), here.g * (1.0 - uEvaporate * uDt), load, 0.0);
}
