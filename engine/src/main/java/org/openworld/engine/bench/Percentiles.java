package org.openworld.engine.bench;

import java.util.Arrays;
import java.util.Collection;

/**
 * Order statistics of one set of samples, e.g. every frame's time.
 *
 * <p>Percentiles use <b>linear interpolation between closest ranks</b> (Hyndman &amp; Fan type 7, the default of
 * numpy's {@code percentile} and of Excel's {@code PERCENTILE.INC}): on the {@code n} samples sorted ascending, the
 * p-th percentile sits at zero-based position {@code h = (n - 1) * p / 100}, between the samples at
 * {@code floor(h)} and {@code ceil(h)}. So p = 0 is the minimum, p = 100 the maximum, and p = 50 the usual median
 * (the mean of the two middle samples when n is even). For the samples 1..100 this gives a median of 50.5, a p95 of
 * 95.05 and a p99 of 99.01.
 */
public final class Percentiles {

    private final double[] sorted;

    /** @param samples at least one sample; the array is copied, not changed */
    public Percentiles(double[] samples) {
        if (samples.length == 0) {
            throw new IllegalArgumentException("percentiles of no samples");
        }
        sorted = samples.clone();
        Arrays.sort(sorted);
    }

    /** @param samples at least one sample */
    public static Percentiles of(Collection<Double> samples) {
        return new Percentiles(samples.stream().mapToDouble(Double::doubleValue).toArray());
    }

    /**
     * @param percent which percentile, 0 to 100
     * @return the interpolated sample value at that percentile
     */
    public double at(double percent) {
        if (!(percent >= 0 && percent <= 100)) {
            throw new IllegalArgumentException("percentile outside 0..100: " + percent);
        }
        double h = (sorted.length - 1) * percent / 100.0;
        int below = (int) Math.floor(h);
        int above = (int) Math.ceil(h);
        return sorted[below] + (h - below) * (sorted[above] - sorted[below]);
    }

    /** The 50th percentile. */
    public double median() {
        return at(50);
    }

    public double max() {
        return sorted[sorted.length - 1];
    }

    public double mean() {
        return Arrays.stream(sorted).average().orElseThrow();
    }
}
