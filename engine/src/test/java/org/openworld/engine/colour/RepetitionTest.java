package org.openworld.engine.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.function.IntBinaryOperator;
import org.junit.jupiter.api.Test;
import org.openworld.engine.gl.Image;

/**
 * The repetition measure on pictures whose answer is known: a tiled pattern, noise, one colour, and either under a
 * strong smooth variation, which is not repetition.
 */
class RepetitionTest {

    static final int W = 160;
    static final int H = 96;

    /** A grey picture whose level at (x, y) the function gives, 0–255. */
    static Image grey(IntBinaryOperator level) {
        byte[] rgba = new byte[W * H * 4];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int v = Math.max(0, Math.min(255, level.applyAsInt(x, y)));
                int i = (y * W + x) * 4;
                rgba[i] = rgba[i + 1] = rgba[i + 2] = (byte) v;
                rgba[i + 3] = (byte) 255;
            }
        }
        return new Image(W, H, rgba);
    }

    /** Random levels, the same for the same seed. */
    static int[] noise(long seed, int n) {
        Random random = new Random(seed);
        int[] v = new int[n];
        for (int i = 0; i < n; i++) {
            v[i] = random.nextInt(256);
        }
        return v;
    }

    @Test
    void aTiledPatternRepeatsFully() {
        int[] tile = noise(1, 20 * 20);
        double peak = Repetition.peak(grey((x, y) -> tile[(y % 20) * 20 + x % 20]), 8);
        // within 1 %: the whole picture's variance stands in for that of the part a shift overlaps
        assertEquals(1.0, peak, 0.01, "a 20-pixel tile matches itself shifted by 20");
    }

    @Test
    void noiseDoesNotRepeat() {
        int[] v = noise(2, W * H);
        double peak = Repetition.peak(grey((x, y) -> v[y * W + x]), 8);
        // noise: r at one shift has σ ≈ 1/√(overlap) ≈ 0.016 at the smallest overlap (a quarter of 160 × 96); the
        // largest of ~15 000 shifts is ~4σ ≈ 0.07, so 0.15 is twice the expected maximum
        assertTrue(peak < 0.15, "independent pixels: " + peak);
    }

    @Test
    void aTileUnderNoiseRepeatsByItsShareOfTheVariance() {
        // equal variances: the tile's part correlates fully at its period, the noise's not at all, so r is about 1/2
        int[] tile = noise(3, 32 * 32);
        int[] v = noise(4, W * H);
        double peak = Repetition.peak(grey((x, y) -> (tile[(y % 32) * 32 + x % 32] + v[y * W + x]) / 2), 8);
        // 0.5 ± 0.1: the two variances are equal only in expectation (each drawn from 256 levels), plus the ~0.07
        // maximum of pure noise over all shifts (see noiseDoesNotRepeat)
        assertEquals(0.5, peak, 0.1);
    }

    @Test
    void shiftsShorterThanTheMinimumAreNotRepeats() {
        // noise blurred over 9 × 9 samples: like itself a sample away, not twenty samples away
        int[] v = noise(5, W * H);
        double[] blurred = new double[W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int dy = -4; dy <= 4; dy++) {
                    for (int dx = -4; dx <= 4; dx++) {
                        blurred[y * W + x] += v[Math.floorMod(y + dy, H) * W + Math.floorMod(x + dx, W)] / 81.0;
                    }
                }
            }
        }
        // a 9-wide box blur: a one-sample shift keeps 8/9 of the box in common (r ≈ 0.89 before the high-pass); 20
        // samples is more than twice the box width, so only the noise floor (~0.07) is left, 0.25 allows for the blur's
        // fewer independent samples
        assertTrue(Repetition.peak(blurred, W, H, 1) > 0.8, "a one-sample shift of smooth noise");
        assertTrue(Repetition.peak(blurred, W, H, 20) < 0.25, "twenty samples away");
    }

    /** A wave 200 pixels long across the picture, 80 levels high: light and shade, or a terrain's large-scale tint. */
    static int swell(int x, int y) {
        return (int) Math.round(40 * Math.sin(2 * Math.PI * (x + 0.6 * y) / 200));
    }

    @Test
    void aSmoothVariationIsNotRepetition() {
        // noise at a quarter of the swell's amplitude: the raw luminance correlates with itself at every short shift
        // through the swell, the picture's detail does not
        int[] v = noise(6, W * H);
        Image picture = grey((x, y) -> 128 + swell(x, y) + (v[y * W + x] - 128) / 5);
        double[] luma = new double[W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                luma[y * W + x] = picture.luma(x, y);
            }
        }
        // the swell's amplitude is 4× the noise's (variance 16:1): a short shift of the raw luma correlates near 16/17
        // ≈ 0.94, 0.6 only has to show it is large; the high-passed detail is plain noise, held to noiseDoesNotRepeat's
        // 0.15
        assertTrue(Repetition.peak(luma, W, H, 8) > 0.6, "the swell fools the raw autocorrelation");
        assertTrue(Repetition.peak(picture, 8) < 0.15, "the detail does not repeat: " + Repetition.peak(picture, 8));
    }

    @Test
    void aTileUnderASmoothVariationStillRepeats() {
        int[] tile = noise(7, 24 * 24);
        Image picture = grey((x, y) -> 128 + swell(x, y) + (tile[(y % 24) * 24 + x % 24] - 128) / 5);
        // the detail is the tile alone (the swell is removed by the box high-pass): about 1 at the 24-pixel period,
        // less the swell's leak through the 17-pixel box
        assertTrue(Repetition.peak(picture, 8) > 0.9, "a 24-pixel tile: " + Repetition.peak(picture, 8));
    }

    @Test
    void oneColourHasNothingToRepeat() {
        assertEquals(0, Repetition.peak(grey((x, y) -> 90), 8));
    }
}
