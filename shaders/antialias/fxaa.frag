#version 330 core
// FXAA, fast approximate anti-aliasing (Lottes 2009; the "quality" path of FXAA 3.11), over the finished scene
// (engine: org.openworld.engine.antialias.Fxaa). The scene is already tone-mapped and sRGB-encoded, so luma here is
// perceptual, as FXAA wants. Per pixel:
//   1. contrast: the luma range over the pixel and its four neighbours; below a threshold it is no edge, kept as is
//   2. direction: the edge runs along whichever axis has the smaller second difference of luma across it
//   3. side: the neighbour across the edge with the steeper step is the other side of the edge
//   4. search: along the edge both ways, the mean luma of the pair (this row and the other side's) stays near the
//      edge's own until the edge ends, up to SEARCH_STEPS pixels; from the nearer end, the pixel's share of the
//      other side is 0.5 - distance / length (a staircase step becomes a ramp)
//   5. sub-pixel: a pixel that stands out from the mean of its 3x3 neighbourhood is blended by how much it does
//   6. the pixel mixed with its neighbour across the edge by the larger of the two shares
// Texels are fetched exactly (texelFetch): the blend of two texels along one axis is the bilinear lookup FXAA makes,
// without asking the scene target for linear filtering.
uniform sampler2D scene;   // the scene target's colour, sRGB-encoded
uniform float subpixel;    // 0..1, antialias.subpixel: the weight of step 5
out vec4 fragColor;

const float EDGE_THRESHOLD = 0.125;     // local contrast, range / brightest, below which there is no edge: FXAA's
                                        // "high quality" 1/8 (1/4 misses soft edges, 1/16 blurs texture)
const float EDGE_THRESHOLD_MIN = 0.0312; // luma range below which a dark pixel is left alone: FXAA's 1/32, about
                                         // eight 8-bit levels, under which a step in the dark is hardly seen
const int SEARCH_STEPS = 12;             // pixels searched each way along an edge: a staircase of steps up to 24
                                         // pixels long ramps fully (a 2.4 degree edge); longer ones partly

ivec2 size;

vec3 fetch(ivec2 p) {
    return texelFetch(scene, clamp(p, ivec2(0), size - 1), 0).rgb;
}

float luma(vec3 c) {
    return dot(c, vec3(0.299, 0.587, 0.114)); // Rec. 601 weights on the encoded values
}

float lumaAt(ivec2 p) {
    return luma(fetch(p));
}

void main() {
    size = textureSize(scene, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 colorM = fetch(p);
    float m = luma(colorM);
    float n = lumaAt(p + ivec2(0, 1));
    float s = lumaAt(p + ivec2(0, -1));
    float e = lumaAt(p + ivec2(1, 0));
    float w = lumaAt(p + ivec2(-1, 0));

    // 1. contrast
    float brightest = max(m, max(max(n, s), max(e, w)));
    float range = brightest - min(m, min(min(n, s), min(e, w)));
    if (range < max(EDGE_THRESHOLD_MIN, brightest * EDGE_THRESHOLD)) {
        fragColor = vec4(colorM, 1.0);
        return;
    }
    float nw = lumaAt(p + ivec2(-1, 1));
    float ne = lumaAt(p + ivec2(1, 1));
    float sw = lumaAt(p + ivec2(-1, -1));
    float se = lumaAt(p + ivec2(1, -1));

    // 2. direction: horizontal edges change luma along y
    float acrossY = abs(nw + sw - 2.0 * w) + 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e);
    float acrossX = abs(sw + se - 2.0 * s) + 2.0 * abs(w + e - 2.0 * m) + abs(nw + ne - 2.0 * n);
    bool horizontal = acrossY >= acrossX;
    ivec2 along = horizontal ? ivec2(1, 0) : ivec2(0, 1);

    // 3. side
    float before = horizontal ? s : w;
    float after = horizontal ? n : e;
    bool toAfter = abs(after - m) >= abs(before - m);
    ivec2 side = (toAfter ? 1 : -1) * (horizontal ? ivec2(0, 1) : ivec2(1, 0));
    float other = toAfter ? after : before;
    float gradient = 0.25 * abs(other - m);
    float edgeLuma = 0.5 * (m + other);

    // 4. search along the edge for its two ends
    float endBack = 0.0;
    float endOn = 0.0;
    float distBack = float(SEARCH_STEPS) + 0.5;
    float distOn = float(SEARCH_STEPS) + 0.5;
    bool doneBack = false;
    bool doneOn = false;
    for (int i = 1; i <= SEARCH_STEPS && !(doneBack && doneOn); i++) {
        if (!doneBack) {
            ivec2 q = p - i * along;
            endBack = 0.5 * (lumaAt(q) + lumaAt(q + side)) - edgeLuma;
            doneBack = abs(endBack) >= gradient;
            distBack = doneBack ? float(i) - 0.5 : distBack;
        }
        if (!doneOn) {
            ivec2 q = p + i * along;
            endOn = 0.5 * (lumaAt(q) + lumaAt(q + side)) - edgeLuma;
            doneOn = abs(endOn) >= gradient;
            distOn = doneOn ? float(i) - 0.5 : distOn;
        }
    }
    // the nearer end must turn towards the pixel's own side of the edge, else the pixel lies on the ramp's far half
    float nearEnd = distBack < distOn ? endBack : endOn;
    bool ramp = (nearEnd < 0.0) != (m - edgeLuma < 0.0);
    float edgeShare = ramp ? 0.5 - min(distBack, distOn) / (distBack + distOn) : 0.0;

    // 5. sub-pixel: the 3x3 mean, edge neighbours twice
    float mean = (2.0 * (n + s + e + w) + nw + ne + sw + se) / 12.0;
    float standsOut = clamp(abs(mean - m) / range, 0.0, 1.0);
    float eased = (3.0 - 2.0 * standsOut) * standsOut * standsOut;
    float subpixelShare = eased * eased * subpixel;

    // 6. blend with the other side
    fragColor = vec4(mix(colorM, fetch(p + side), max(edgeShare, subpixelShare)), 1.0);
}
