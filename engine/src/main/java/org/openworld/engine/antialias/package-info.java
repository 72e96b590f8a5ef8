/**
 * Anti-aliasing of the picture: the engine's choice of method ({@link org.openworld.engine.antialias.Antialiasing},
 * {@code antialias.method}), and FXAA, fast approximate anti-aliasing (Timothy Lottes, NVIDIA 2009; the "quality"
 * path of FXAA 3.11), one post pass over the finished scene ({@link org.openworld.engine.antialias.Fxaa},
 * {@code shaders/antialias/fxaa.frag}). The default, temporal anti-aliasing, is a technique of its own:
 * {@link org.openworld.engine.temporal}. Page: {@code docs/design.md}, "Anti-aliasing".
 *
 * <p><b>Why two.</b> A forward renderer that shades every pixel once has three ways to smooth its edges: MSAA
 * (several coverage samples per pixel in the scene target, resolved at the end), a temporal method (TAA: the
 * projection jittered by a fraction of a pixel each frame and the frames blended through a reprojected history), or
 * a post filter that finds edges in the finished picture. On Mesa's llvmpipe, which rasterises on the CPU, MSAA
 * multiplies the depth, stencil and colour work per pixel and the water's copies of the scene. FXAA reads one
 * picture alone and smooths its edges, but cannot make motion steadier: it cannot tell a texel that flickers from
 * one that does not. TAA can, for about the same full-screen pass, and is the default; FXAA stays for a single
 * frame that must be smooth without a history.
 *
 * <p><b>Method.</b> Per pixel, with luma L of the sRGB-encoded colour (what the eye compares): the range of L over the
 * pixel and its four neighbours, below {@code max(1/32, L_max / 8)} no edge; the edge's direction from the second
 * differences of L across the two axes; its other side, the neighbour with the larger step; along the edge, both
 * ways, the mean L of the pair (this side, other side) until it leaves the edge's own by a quarter of the step: the
 * edge's ends at distances d₁, d₂. A pixel on the half of the staircase step that leans to its own side takes
 * {@code 0.5 − min(d₁, d₂) / (d₁ + d₂)} of the other side's colour, so a step becomes a ramp; and a pixel that
 * stands out from the mean of its 3×3 neighbourhood by a share s of the range takes {@code (3 − 2s)² s⁴ · subpixel}
 * of it (FXAA's sub-pixel term, {@code antialias.subpixel}); the larger of the two wins.
 *
 * <p><b>Data path.</b> The systems draw the scene target as before; after the last pass the engine draws one
 * full-screen triangle that reads the scene's colour texel by texel ({@code texelFetch}, a two-texel mix standing in
 * for FXAA's bilinear taps) and writes a colour target of the scene's size, which is the picture at render scale 1
 * and what is stretched over it below ({@code ScaledScene}); the settings panel and the HUD draw over the result.
 *
 * <p><b>Cost.</b> Five texel fetches for a pixel that is no edge; on an edge four more, then up to four per step of
 * the search ({@code SEARCH_STEPS} 12 each way). Measured as the span {@code antialias.engine}: 5 % of a profiled
 * 1280 × 720 frame of {@code valley.path} on llvmpipe (56 of 1105 ms, on two cores loaded by other runs; docs/benchmarks.md,
 * "Temporal stability"). Memory: one RGBA8 target of the scene's size (3.5 MiB at 1280 × 720).
 *
 * <p><b>Limits.</b> FXAA sees pixels, not geometry: an edge of less contrast than the threshold stays a staircase,
 * thin features narrower than a pixel break into dots it cannot rejoin, and texture detail with the contrast of an
 * edge is softened too. Being a per-frame filter with a threshold, it adds no temporal stability: a pixel near the
 * threshold is blended in one frame and not in the next. In motion the picture changes about as much with it as
 * without ({@code openworld stability}, docs/benchmarks.md, "Temporal stability").
 */
package org.openworld.engine.antialias;
