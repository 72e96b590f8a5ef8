#version 330 core
// Virtual-pipe erosion, pass 1 (PipeErosion.fluxPass): rain, then each pipe's flux accelerated by the drop of the
// water's surface to the neighbour's, f = max(0, f + dt l g dh), and all four scaled so the cell loses no more
// water than it holds.
#include "erosion/pipe.glsl"

out vec4 outFlux;

void main() {
    ivec2 c = ivec2(gl_FragCoord.xy);
    vec4 here = texelFetch(uState, c, 0);
    vec4 old = texelFetch(uFlux, c, 0);
    float rain = uDt * uRain;
    float accel = uDt * uSpacing * GRAVITY;
    float area = uSpacing * uSpacing;
    float water = here.g + rain;
    float surface = here.r + water;
    vec4 f;
    float total = 0.0;
    for (int k = 0; k < 4; k++) {
        ivec2 at;
        float other = here.r;
        if (neighbour(c, k, at)) {
            vec4 there = texelFetch(uState, at, 0);
            other = there.r + (there.g + rain);
        }
        f[k] = max(0.0, old[k] + accel * (surface - other));
        total += f[k];
    }
    float scale = total > 0.0 ? min(1.0, water * area / (total * uDt)) : 1.0;
    outFlux = f * scale;
}
