/**
 * The benchmark recorder's output: per-frame records ({@link org.openworld.engine.bench.FrameRecord}) become
 * {@code frames.csv}, {@code summary.json} (medians and percentiles, with the renderer and every setting) and
 * {@code frametime.png} (GPU time per pass and system stacked under the frame time), and two summaries compare side by side
 * with their ratio ({@link org.openworld.engine.bench.BenchComparison}). See {@code docs/benchmarks.md}.
 *
 * <p>A frame's time is its wall-clock interval with at most two frames in flight; CPU time per system and GPU time
 * per system in each pass explain it. A profiled run ({@code bench --profile}) finishes the GPU around each span, so
 * its GPU times are exact wall times that add up to the frame, at the price of a serialised frame. Each run also
 * records its memory ({@link org.openworld.engine.bench.MemoryMeter}): the heap's peak, and its peak just after a
 * collection (what the run holds, whatever garbage piles up between collections), the process's peak resident
 * set, GPU memory where the driver reports it, and the texture memory by the engine's own count
 * ({@link org.openworld.engine.gl.TextureMemory}: texels × bytes per texel over every mip level and layer, kept as
 * each texture is made and closed), which every driver has: {@code texturePeakMib} and {@code textureEndMib} in
 * {@code summary.json}'s {@code memory}.
 */
package org.openworld.engine.bench;
