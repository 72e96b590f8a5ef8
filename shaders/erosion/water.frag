#version 330 core
// Virtual-pipe erosion, pass 2 (PipeErosion.waterPass): the water moved by the fluxes, its velocity, and the bed
// eroded or built up towards the carrying capacity C = K_c sin(alpha) |v| min(d, depth cap).
#include "erosion/pipe.glsl"

out vec4 outState;

void main() {
    ivec2 c = ivec2(gl_FragCoord.xy);
    vec4 here = texelFetch(uState, c, 0);
    vec4 out4 = texelFetch(uFlux, c, 0);
    float l = uSpacing;
    float area = l * l;
    float d1 = here.g + uDt * uRain;
    vec4 in4;
    vec4 h;
    float inSum = 0.0;
    float outSum = 0.0;
    for (int k = 0; k < 4; k++) {
        ivec2 at;
        in4[k] = inflow(c, k);
        h[k] = neighbour(c, k, at) ? texelFetch(uState, at, 0).r : here.r;
        inSum += in4[k];
        outSum += out4[k];
    }
    float water = max(0.0, d1 + uDt * (inSum - outSum) / area);
    float mean = 0.5 * (d1 + water);
    float u = velocity(in4[0], out4[0], out4[1], in4[1], mean);
    float v = velocity(in4[2], out4[2], out4[3], in4[3], mean);
    float gx = (h[1] - h[0]) / (2.0 * l);
    float gz = (h[3] - h[2]) / (2.0 * l);
    float tan2 = gx * gx + gz * gz;
    float sine = max(uMinSine, sqrt(tan2 / (1.0 + tan2)));
    float cap = uCapacity * sine * sqrt(u * u + v * v) * min(water, uDepthCap);
    float bed = here.r;
    float load = here.b;
    if (cap > load) {
        float e = uDissolve * (cap - load);
        bed -= e;
        load += e;
    } else {
        float e = uDeposit * (load - cap);
        bed += e;
        load -= e;
    }
    outState = vec4(bed, water, load, d1);
}
