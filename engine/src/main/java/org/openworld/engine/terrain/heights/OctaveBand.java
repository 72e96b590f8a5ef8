package org.openworld.engine.terrain.heights;

import java.util.SplittableRandom;

/**
 * One octave of the unbounded world ({@link BandedHeights}): the frequencies 1/(4d) ≤ ω &lt; 1/(2d) of a 1/ω^β
 * spectrum, d the spacing of the band's pyramid level, as a periodic tile of {@link #TILE}² samples d/2 apart,
 * rotated and shifted over the plane, read between its samples by a cubic B-spline.
 *
 * <h2>The tile</h2>
 * {@link SpectralSynthesis#fillSpectrum} fills the tile's spectrum (the same random phases and 1/k^β amplitudes as the
 * periodic world) between the band's cut-offs, here {@code TILE/8 ≤ k < TILE/4} cycles per tile. Two factors
 * change the coefficients before the inverse FFT:
 * <ul>
 *   <li>{@code E^(β−1)}, E the tile's side in metres, relative to band 0's: a tile of side E holds E² coefficients
 *       per unit of frequency area, so each coefficient needs the amplitude ω^−β / E for the power spectral density
 *       ω^−2β to continue across bands of different tiles (k^−β · E^(β−1) = (k/E)^−β / E);</li>
 *   <li>{@code 1 / (sinc⁴(kx/TILE) · sinc⁴(kz/TILE))}: the samples become the coefficients of a cubic B-spline
 *       whose base frequencies are exactly the spectrum's (see below).</li>
 * </ul>
 *
 * <h2>Why a cubic B-spline, and why samples d/2 apart</h2>
 * A spline through coefficients c_i has the Fourier transform ĉ(f) · sinc⁴(f s) for samples s apart: the tile's
 * periodic spectrum ĉ repeated every 1/s, times the B-spline's own response. Dividing by sinc⁴ beforehand makes the
 * band exact (the base frequencies keep their amplitude); what is left are the images at f ± 1/s, weighted by
 * sinc⁴(f s ± 1) / sinc⁴(f s). The band reaches f s = 1/4 (its highest frequency 1/(2d) with s = d/2), where the
 * nearest image, at 3/4, keeps 0.0081 / 0.66 = 1.2 % of the amplitude (0.015 % of the power), and less for the rest
 * of the band: the interpolation adds almost nothing above the band and removes nothing inside it. Linear
 * interpolation (sinc²) would leave 11 % images and, without a correction, lose 19 % of the top frequency; a tile at
 * spacing d (f s = 1/2) would put the band's top on its images. Cost of a value: 16 samples and 8 cubic weights.
 *
 * <h2>Placement</h2>
 * The tile is rotated by a random angle and shifted by a random offset, both drawn per seed and band, so its lattice
 * of periods (side {@code TILE · d/2}) lines up with no other band's. Positions are doubles in metres: at 10 000 km a
 * double still resolves 2 nm, and the sample index is taken modulo {@link #TILE} as an integer.
 */
final class OctaveBand {

    /** Samples per side of a band's tile: a band repeats every TILE · d/2, 131 km for the 1–2 km octave. */
    static final int TILE = 512;

    private final float[] coefficients;
    private final double spacing;
    private final double cos;
    private final double sin;
    private final double offsetX;
    private final double offsetZ;
    private final double variance;

    private OctaveBand(float[] coefficients, double spacing, double angle, double offsetX, double offsetZ,
                       double variance) {
        this.coefficients = coefficients;
        this.spacing = spacing;
        this.cos = StrictMath.cos(angle);
        this.sin = StrictMath.sin(angle);
        this.offsetX = offsetX;
        this.offsetZ = offsetZ;
        this.variance = variance;
    }

    /**
     * Band k of a world whose finest level has samples {@code d0} apart, or null if the cut-offs
     * ({@code minWavelength}, {@code maxWavelength}] leave it no frequency.
     *
     * @param random draws this band's phases, angle and offset; the caller's order of draws makes it deterministic
     */
    static OctaveBand make(int k, double d0, double beta, double minWavelength, double maxWavelength,
                           SplittableRandom random) {
        long phases = random.nextLong();
        double angle = 2 * Math.PI * random.nextDouble();
        double offsetX = TILE * random.nextDouble();
        double offsetZ = TILE * random.nextDouble();
        double d = Math.scalb(d0, k);
        double shortest = Math.max(2 * d, minWavelength);
        double longest = Math.min(4 * d, maxWavelength);
        if (!(shortest < longest)) {
            return null;
        }
        int n = TILE;
        float[] a = new float[n * n];
        SpectralSynthesis.fillSpectrum(a, n, n * d / 2, beta, shortest, longest, phases);
        double gain = StrictMath.pow(2, k * (beta - 1)); // (E_k / E_0)^(β−1), E_k = 2^k E_0
        double[] spline = new double[n / 2 + 1]; // 1 / sinc⁴(k/n) for k = 0 .. n/2
        for (int i = 0; i <= n / 2; i++) {
            double x = Math.PI * i / n;
            double sinc = i == 0 ? 1 : StrictMath.sin(x) / x;
            spline[i] = 1 / (sinc * sinc * sinc * sinc);
        }
        // JTransforms' unscaled real inverse turns each stored coefficient c (with its unstored conjugate) into the
        // wave Re(c e^iθ), of mean square |c|² / 2
        double sum = 0;
        for (int r = 0; r < n; r++) {
            int kz = Math.abs(r < n / 2 ? r : r - n);
            for (int kx = 0; kx < n / 2; kx++) {
                int at = r * n + 2 * kx;
                double re = gain * a[at];
                double im = gain * a[at + 1];
                sum += re * re + im * im;
                double g = gain * spline[kx] * spline[kz];
                a[at] = (float) (a[at] * g);
                a[at + 1] = (float) (a[at + 1] * g);
            }
        }
        SpectralSynthesis.inverseTransform(a, n);
        return new OctaveBand(a, d / 2, angle, offsetX, offsetZ, sum / 2);
    }

    /** The mean square of the band over its period (Parseval), in the raw units of {@link #value}. */
    double variance() {
        return variance;
    }

    /**
     * No value of the band exceeds this in magnitude: the largest |coefficient|, since a value is a convex
     * combination of sixteen coefficients (the cubic B-spline's weights are positive and sum to 1). Raw units.
     */
    double bound() {
        double m = 0;
        for (float c : coefficients) {
            m = Math.max(m, Math.abs(c));
        }
        return m;
    }

    /** The band at world position (x, z), metres; raw units (the world scales them to metres). */
    double value(double x, double z) {
        double u = (cos * x + sin * z) / spacing + offsetX;
        double v = (-sin * x + cos * z) / spacing + offsetZ;
        double fu = Math.floor(u);
        double fv = Math.floor(v);
        double tu = u - fu;
        double tv = v - fv;
        int mask = TILE - 1;
        int iu = (int) ((long) fu & mask); // two's complement: & mask is the floor modulo for a power of two
        int iv = (int) ((long) fv & mask);
        double wu0 = cubic0(tu);
        double wu1 = cubic1(tu);
        double wu2 = cubic1(1 - tu);
        double wu3 = cubic0(1 - tu);
        int c0 = (iu - 1) & mask;
        int c2 = (iu + 1) & mask;
        int c3 = (iu + 2) & mask;
        double sum = 0;
        for (int j = -1; j <= 2; j++) {
            double wv = j == -1 ? cubic0(tv) : j == 0 ? cubic1(tv) : j == 1 ? cubic1(1 - tv) : cubic0(1 - tv);
            int row = ((iv + j) & mask) * TILE;
            sum += wv * (wu0 * coefficients[row + c0] + wu1 * coefficients[row + iu]
                    + wu2 * coefficients[row + c2] + wu3 * coefficients[row + c3]);
        }
        return sum;
    }

    /** The cubic B-spline's weight for the sample one before the cell, t across the cell: (1 − t)³ / 6. */
    private static double cubic0(double t) {
        double s = 1 - t;
        return s * s * s / 6;
    }

    /** The weight of the cell's own first sample: (3t³ − 6t² + 4) / 6; {@code cubic1(1 − t)} is the next one's. */
    private static double cubic1(double t) {
        return (3 * t * t * t - 6 * t * t + 4) / 6;
    }
}
