#version 330 core
// The snow's update by transform feedback (paper section 4; engine: org.openworld.engine.particles.ParticleSystem,
// CPU reference and analysis: SnowMotion, in the same float operations). One vertex per flake: its state comes in
// as attributes, the new state goes out as captured outputs into the other buffer; nothing is rasterised.
//
//   v <- v + dt (-g y + k (w - v)) + sigma sqrt(dt) xi      gravity, drag towards the wind, Brownian motion
//   p <- p + dt v                                           then wrapped into the cube around the eye (through a
//                                                           side face at the same height above the ground);
//                                                           below the ground: back to the cube's top
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 velocity;

out vec3 outPosition;
out vec3 outVelocity;

uniform vec4 uForces;   // x: g (m/s^2); y: k (1/s); z: sigma sqrt(dt), the Brownian kick (m/s); w: dt (s)
uniform vec3 uWind;     // w, m/s
uniform vec4 uVolume;   // xyz: the cube's centre, the eye (m); w: its side L (m)
uniform int uStepKey;   // this step's hash key (SnowMotion.stepKey): seed and step number mixed
uniform sampler2D ground; // R32F heights (m), one texel per sample of the ground patch
uniform vec4 uGround;   // xy: world x, z of the first sample (m); z: 1 / spacing (1/m); w: samples a side

// PCG hash (Jarzynski and Olano 2020): one round of a permuted congruential generator.
uint pcg(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// The top 24 bits of a hash as a float in (0, 1], exactly.
float uniform01(uint h) {
    return float((h >> 8u) + 1u) * (1.0 / 16777216.0);
}

// Three standard normal numbers: Box-Muller twice on four chained hashes.
vec3 gaussians(uint key) {
    const float TWO_PI = 6.28318530718;
    uint h1 = pcg(key);
    uint h2 = pcg(h1);
    uint h3 = pcg(h2);
    uint h4 = pcg(h3);
    float r1 = sqrt(-2.0 * log(uniform01(h1)));
    float r2 = sqrt(-2.0 * log(uniform01(h3)));
    float a1 = TWO_PI * uniform01(h2);
    float a2 = TWO_PI * uniform01(h4);
    return vec3(r1 * cos(a1), r1 * sin(a1), r2 * cos(a2));
}

// The ground's height under (x, z): bilinear by hand from four exact texels, as GroundPatch.heightAt.
float groundAt(vec2 xz) {
    float last = uGround.w - 1.0;
    vec2 g = clamp((xz - uGround.xy) * uGround.z, 0.0, last);
    ivec2 i = min(ivec2(floor(g)), ivec2(int(uGround.w) - 2));
    vec2 f = g - vec2(i);
    float h00 = texelFetch(ground, i, 0).r;
    float h10 = texelFetch(ground, i + ivec2(1, 0), 0).r;
    float h01 = texelFetch(ground, i + ivec2(0, 1), 0).r;
    float h11 = texelFetch(ground, i + ivec2(1, 1), 0).r;
    float near = h00 + (h10 - h00) * f.x;
    float far = h01 + (h11 - h01) * f.x;
    return near + (far - near) * f.y;
}

void main() {
    float dt = uForces.w;
    vec3 xi = uForces.z > 0.0 ? gaussians(uint(gl_VertexID) ^ uint(uStepKey)) : vec3(0.0);
    vec3 v = velocity + dt * (vec3(0.0, -uForces.x, 0.0) + uForces.y * (uWind - velocity)) + uForces.z * xi;
    float side = uVolume.w;
    float halfSide = 0.5 * side;
    vec3 moved = position + dt * v;
    vec3 a = moved - uVolume.xyz + halfSide;
    vec2 laps = floor(a.xz / side);
    vec3 p = vec3(uVolume.xz + (a.xz - side * laps) - halfSide, moved.y).xzy;
    if (laps.x != 0.0 || laps.y != 0.0) {
        // back in through the opposite side face, as high above the ground there as it was where it left
        p.y += groundAt(p.xz) - groundAt(moved.xz);
    }
    float ay = p.y - uVolume.y + halfSide;
    p.y = uVolume.y + (ay - side * floor(ay / side)) - halfSide;
    float groundY = groundAt(p.xz);
    if (p.y < groundY) {
        p.y = uVolume.y + halfSide - (groundY - p.y);
    }
    outPosition = p;
    outVelocity = v;
}
