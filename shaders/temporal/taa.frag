#version 330 core
// Temporal anti-aliasing's resolve (engine: org.openworld.engine.temporal.TemporalAntialias), per pixel:
//   1. the pixel's point: its centre and depth in the current frame, to normalised device coordinates
//   2. reprojected: the previous frame's clip position of that point (reprojection = VP_prev * VP_now^-1, both
//      without jitter), so a static world needs no motion vectors; a point that was off screen has no history
//   3. the history there (bilinear), clamped to the box of colours of the pixel's 3x3 neighbourhood in this frame:
//      what this frame cannot show near the pixel (a surface uncovered, a thing moved) is not kept (no ghosting);
//      the clamp's share grows with the pixel's motion, none where the view is still: there the history is the
//      same surface, and clamping it to one jittered frame's box would cut what that frame's samples missed (a
//      sub-pixel trunk, a ridge's thin edge), which the next frames add back: a still picture that keeps changing
//   4. blended: history + weight * (current - history), the weight 1/n for the first frames (an exact mean of the
//      samples so far) and never below the setting (an exponential average of about 2/weight frames)
// The scene is tone-mapped and sRGB-encoded, so the blend and the clamp work on what the eye compares.
uniform sampler2D scene;    // this frame, drawn with its projection jittered
uniform sampler2D depth;    // its depth, 0 near .. 1 far
uniform sampler2D history;  // the last output, RGBA16F, linear filtering
uniform mat4 reprojection;  // NDC now -> clip space of the previous frame
uniform float weight;       // this frame's share of the output; 1 when there is no history
layout(location = 0) out vec4 fragColor; // the history, RGBA16F
layout(location = 1) out vec4 picture;   // the same colour into the anti-aliased target, RGBA8: no copy after

// Pixels of motion from which the history is wholly clamped: a surface uncovered in one frame is at most the motion
// wide, and from half a pixel on it is most of a pixel; below, the bilinear history blends it with its neighbours.
const float FULL_CLAMP = 0.5;

void main() {
    ivec2 size = textureSize(scene, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 current = texelFetch(scene, p, 0).rgb;
    vec3 lo = current;
    vec3 hi = current;
    for (int dy = -1; dy <= 1; dy++) {
        for (int dx = -1; dx <= 1; dx++) {
            vec3 c = texelFetch(scene, clamp(p + ivec2(dx, dy), ivec2(0), size - 1), 0).rgb;
            lo = min(lo, c);
            hi = max(hi, c);
        }
    }
    // 1. and 2.
    vec2 uv = gl_FragCoord.xy / vec2(size);
    float z = texelFetch(depth, p, 0).r;
    vec4 previous = reprojection * vec4(uv * 2.0 - 1.0, z * 2.0 - 1.0, 1.0);
    vec2 then = previous.xy / previous.w * 0.5 + 0.5;
    bool seen = previous.w > 0.0 && all(greaterThanEqual(then, vec2(0.0))) && all(lessThanEqual(then, vec2(1.0)));
    // 3. and 4.
    vec3 held = texture(history, then).rgb;
    float motion = length((then - uv) * vec2(size)); // pixels since the last frame
    vec3 kept = mix(held, clamp(held, lo, hi), min(motion / FULL_CLAMP, 1.0));
    fragColor = vec4(seen ? mix(kept, current, weight) : current, 1.0);
    picture = fragColor;
}
