/**
 * The benchmark recorder's output: per-frame records ({@link org.openworld.engine.bench.FrameRecord}) become
 * {@code frames.csv}, {@code summary.json} (medians and percentiles, with the renderer and every setting) and
 * {@code frametime.png} (per-pass GPU time stacked under the frame time), and two summaries compare side by side
 * with their ratio ({@link org.openworld.engine.bench.BenchComparison}). See {@code docs/benchmarks.md}.
 *
 * <p>A frame's time is the larger of its CPU time and the sum of its passes' GPU time, since either can bound it.
 */
package org.openworld.engine.bench;
