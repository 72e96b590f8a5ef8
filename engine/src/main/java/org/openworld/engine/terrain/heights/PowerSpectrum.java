package org.openworld.engine.terrain.heights;

import java.util.ArrayList;
import java.util.List;
import org.jtransforms.fft.FloatFFT_2D;
import org.openworld.engine.core.FftThreads;

/**
 * The radially averaged power spectrum of a height map: |F(k)|² of its 2D DFT ({@link FloatFFT_2D#realForward}),
 * averaged over rings of equal radial frequency, and a straight-line fit of log₁₀ power against log₁₀ frequency. For
 * heights whose amplitude falls as 1/ω^β the power falls as 1/ω^{2β}: the fitted slope is −2β. This is how the tests
 * and {@code openworld heightmap} check {@link SpectralSynthesis}.
 *
 * <p>Ring k holds the frequencies whose radius |(kx, kz)| rounds to k (cycles per tile), k = 1 .. size/2 − 1; rings
 * beyond size/2 − 1 are cut by the square grid and left out. The transform works on a copy of the heights, 4 · size²
 * bytes, with JTransforms' thread count pinned by {@link FftThreads} like every FFT in the engine, so a map gives the
 * same spectrum on any machine.
 */
public final class PowerSpectrum {

    /**
     * One ring: its frequency in cycles per metre and the mean |F|² of its coefficients, F the unnormalised DFT of
     * the heights in metres (so m², scaled by the sample count; only ratios and slopes matter).
     */
    public record Bin(double frequency, double power) {
    }

    /** log₁₀ power ≈ slope · log₁₀ frequency + intercept. */
    public record Fit(double slope, double intercept) {

        /** The fitted power at a frequency, cycles per metre. */
        public double power(double frequency) {
            return Math.pow(10, intercept + slope * Math.log10(frequency));
        }
    }

    private final List<Bin> bins;
    private final double extent;

    private PowerSpectrum(List<Bin> bins, double extent) {
        this.bins = bins;
        this.extent = extent;
    }

    /** The spectrum of a map (its mean is not part of any ring, so it need not be removed). */
    public static PowerSpectrum of(HeightMap map) {
        int n = map.size();
        float[] a = map.heights().clone();
        FftThreads.pinned(() -> new FloatFFT_2D(n, n).realForward(a));
        int rings = n / 2;
        double[] sum = new double[rings];
        long[] count = new long[rings];
        // The packed layout (see SpectralSynthesis.fillSpectrum): row r is kz = r or r − n, slots 2kx, 2kx + 1 hold
        // (kx, kz) for 0 < kx < n/2, slot pair 0, 1 holds (0, r) for 0 < r < n/2. Each is one of a conjugate pair of
        // equal power, so one half plane gives the rings' means.
        for (int r = 0; r < n; r++) {
            long kz = r < n / 2 ? r : r - n;
            for (int kx = 0; kx < n / 2; kx++) {
                if (kx == 0 && !(r > 0 && r < n / 2)) {
                    continue;
                }
                int ring = (int) Math.round(Math.sqrt(kx * (double) kx + kz * kz));
                if (ring >= 1 && ring < rings) {
                    double re = a[r * n + 2 * kx];
                    double im = a[r * n + 2 * kx + 1];
                    sum[ring] += re * re + im * im;
                    count[ring]++;
                }
            }
        }
        double extent = map.extent();
        List<Bin> bins = new ArrayList<>();
        for (int k = 1; k < rings; k++) {
            if (count[k] > 0) {
                bins.add(new Bin(k / extent, sum[k] / count[k]));
            }
        }
        return new PowerSpectrum(List.copyOf(bins), extent);
    }

    /**
     * The spectrum of a window cut from a larger, non-periodic field (a window of {@link BandedHeights}): the mean is
     * removed and the heights tapered by a Hann window {@code sin²(π i / n)} on each axis before the transform.
     * Without the taper the jump between opposite edges, which the DFT takes as periodic, adds power falling as
     * 1/f², more than a 1/f^4.4 field has at high frequencies, and flattens the fitted slope; the taper's own
     * leakage falls as 1/f⁶, below the field's.
     */
    public static PowerSpectrum tapered(HeightMap map) {
        int n = map.size();
        float[] h = map.heights();
        double mean = 0;
        for (float v : h) {
            mean += v;
        }
        mean /= h.length;
        double[] hann = new double[n];
        for (int i = 0; i < n; i++) {
            double s = Math.sin(Math.PI * i / n);
            hann[i] = s * s;
        }
        float[] a = new float[n * n];
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                a[z * n + x] = (float) ((h[z * n + x] - mean) * hann[x] * hann[z]);
            }
        }
        return of(new HeightMap(n, map.spacing(), a, false));
    }

    /** The rings, lowest frequency first. */
    public List<Bin> bins() {
        return bins;
    }

    /** How many rings with power lie wholly inside [lowFrequency, highFrequency]: those {@link #fit} uses. */
    public int ringsWithin(double lowFrequency, double highFrequency) {
        return (int) bins.stream().filter(b -> within(b, lowFrequency, highFrequency)).count();
    }

    private boolean within(Bin b, double lowFrequency, double highFrequency) {
        double halfRing = 0.5 / extent;
        return b.frequency() - halfRing >= lowFrequency && b.frequency() + halfRing <= highFrequency && b.power() > 0;
    }

    /**
     * Least-squares line through (log₁₀ f, log₁₀ P) of the rings lying wholly inside [lowFrequency, highFrequency]
     * (cycles per metre): a ring half inside a cut-off would bend the line.
     *
     * @throws IllegalArgumentException if fewer than two rings lie in the band ({@link #ringsWithin})
     */
    public Fit fit(double lowFrequency, double highFrequency) {
        double sx = 0;
        double sy = 0;
        double sxx = 0;
        double sxy = 0;
        int m = 0;
        for (Bin b : bins) {
            if (within(b, lowFrequency, highFrequency)) {
                double x = Math.log10(b.frequency());
                double y = Math.log10(b.power());
                sx += x;
                sy += y;
                sxx += x * x;
                sxy += x * y;
                m++;
            }
        }
        if (m < 2) {
            throw new IllegalArgumentException("fewer than two spectrum rings lie between " + lowFrequency + " and "
                    + highFrequency + " cycles/m");
        }
        double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
        return new Fit(slope, (sy - slope * sx) / m);
    }

    /** The fit over the band a generated map was synthesised in: 1/maxWavelength to 1/minWavelength. */
    public Fit fit(TerrainSettings s) {
        return fit(1 / s.maxWavelength(), 1 / s.minWavelength());
    }
}
