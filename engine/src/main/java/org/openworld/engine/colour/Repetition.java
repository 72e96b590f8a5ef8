package org.openworld.engine.colour;

import org.jtransforms.fft.DoubleFFT_2D;
import org.openworld.engine.core.FftThreads;
import org.openworld.engine.gl.Image;

/**
 * How much a picture repeats itself, as one number: the strongest peak of the normalised autocorrelation of its
 * luminance's detail away from zero shift (the paper's named flaw, section 6: 1 m detail textures that tile visibly).
 *
 * <p>For the luminance L with its mean taken out, the autocorrelation at a shift T = (tx, ty) is
 * <pre>
 *   r(T) = [ Σ L(p) L(p + T) / n(T) ] / [ Σ L(p)² / n(0) ]
 * </pre>
 * over the n(T) pixels p where both p and p + T lie in the picture: 1 at T = 0, near 1 again where the picture
 * matches a shifted copy of itself (a texture repeating every T), near 0 for a picture that does not repeat. The
 * sums come from the power spectrum (Wiener–Khinchin: the autocorrelation is the inverse transform of |F(L)|²), with
 * the picture padded to twice its size in zeros so a shift does not wrap around; dividing by n(T) makes a long
 * shift, which overlaps less of the picture, count like a short one. Shifts beyond half the picture are left out
 * (too few pixels overlap to judge), and so are those shorter than {@code minShift} pixels, where a picture
 * correlates with itself merely because neighbouring pixels are alike (the width of a texture's own features).
 * The whole picture's variance stands in for that of the part a shift overlaps, so an exact repeat may read a
 * little over 1 (by 0.2 % for a 20-pixel tile in a 160 × 96 picture).
 *
 * <p><b>A picture's detail only.</b> Variation smoother than the shortest counted shift (light and shade over a
 * slope, the ground's large-scale tint) correlates with itself at every short shift whether or not anything repeats,
 * and would read as repetition: seen from 500 m a terrain's macro tint alone gave 0.8. So {@link #peak(Image, int)}
 * first takes each pixel's mean over the (2 minShift + 1)² pixels around it out of the luminance (a box high-pass)
 * and measures what is left, the texture: a tile's blades, cracks and grains repeat with it, a smooth field is gone.
 * The limit: a repeat made only of features wider than that box (a pattern of large soft blobs) is not seen.
 *
 * <p>Cost: two FFTs of 4 × width × height complex values; about 50 ms for 320 × 180 on one core.
 */
public final class Repetition {

    private Repetition() {
    }

    /**
     * The largest r(T) of the picture's detail (its luminance less the mean over the (2 minShift + 1)² pixels around
     * each pixel) over shifts with |T| ≥ {@code minShift} and |tx| ≤ width / 2, |ty| ≤ height / 2.
     *
     * @param minShift pixels; a shift shorter than this is not counted as a repeat, nor variation smoother than this
     * @return the peak: about 1 for an exact repeat, near 0 for none; 0 for a picture of one colour, which has nothing
     *         to repeat
     */
    public static double peak(Image image, int minShift) {
        int w = image.width();
        int h = image.height();
        // summed-area table of the luminance, for the box means
        double[] sums = new double[(w + 1) * (h + 1)];
        double[] luma = new double[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                luma[y * w + x] = image.luma(x, y);
                sums[(y + 1) * (w + 1) + x + 1] = luma[y * w + x] + sums[y * (w + 1) + x + 1]
                        + sums[(y + 1) * (w + 1) + x] - sums[y * (w + 1) + x];
            }
        }
        double[] detail = new double[w * h];
        for (int y = 0; y < h; y++) {
            int y0 = Math.max(0, y - minShift);
            int y1 = Math.min(h, y + minShift + 1);
            for (int x = 0; x < w; x++) {
                int x0 = Math.max(0, x - minShift);
                int x1 = Math.min(w, x + minShift + 1);
                double box = sums[y1 * (w + 1) + x1] - sums[y0 * (w + 1) + x1] - sums[y1 * (w + 1) + x0]
                        + sums[y0 * (w + 1) + x0];
                detail[y * w + x] = luma[y * w + x] - box / ((x1 - x0) * (y1 - y0));
            }
        }
        return peak(detail, w, h, minShift);
    }

    /**
     * The same for any field sampled on a grid (a height map, a picture's detail), row by row and as it is (no
     * high-pass): the largest r(T) over shifts with |T| ≥ {@code minShift} samples and |tx| ≤ width / 2,
     * |ty| ≤ height / 2.
     */
    public static double peak(double[] values, int w, int h, double minShift) {
        double mean = 0;
        for (double v : values) {
            mean += v;
        }
        mean /= w * h;
        int pw = 2 * w;
        int ph = 2 * h;
        double[] a = new double[2 * pw * ph]; // complex, row-major, zero padding
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                a[2 * (y * pw + x)] = values[y * w + x] - mean;
            }
        }
        DoubleFFT_2D fft = new DoubleFFT_2D(ph, pw);
        FftThreads.pinned(() -> fft.complexForward(a));
        for (int i = 0; i < pw * ph; i++) {
            double re = a[2 * i];
            double im = a[2 * i + 1];
            a[2 * i] = re * re + im * im;
            a[2 * i + 1] = 0;
        }
        FftThreads.pinned(() -> fft.complexInverse(a, true));
        double zero = a[0] / (w * h);
        if (zero <= 0) {
            return 0;
        }
        double peak = Double.NEGATIVE_INFINITY;
        double min2 = minShift * minShift;
        for (int ty = -h / 2; ty <= h / 2; ty++) {
            for (int tx = -w / 2; tx <= w / 2; tx++) {
                if ((double) tx * tx + (double) ty * ty < min2) {
                    continue;
                }
                int overlap = (w - Math.abs(tx)) * (h - Math.abs(ty));
                int index = Math.floorMod(ty, ph) * pw + Math.floorMod(tx, pw);
                peak = Math.max(peak, a[2 * index] / overlap / zero);
            }
        }
        return peak;
    }
}
