package org.openworld.engine.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.function.IntBinaryOperator;
import org.junit.jupiter.api.Test;
import org.openworld.engine.gl.Image;

/** The repetition measure on pictures whose answer is known: a tiled pattern, noise, one colour, a gradient. */
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
        assertTrue(peak < 0.15, "independent pixels: " + peak);
    }

    @Test
    void aTileUnderNoiseRepeatsByItsShareOfTheVariance() {
        // equal variances: the tile's part correlates fully at its period, the noise's not at all, so r is about 1/2
        int[] tile = noise(3, 32 * 32);
        int[] v = noise(4, W * H);
        double peak = Repetition.peak(grey((x, y) -> (tile[(y % 32) * 32 + x % 32] + v[y * W + x]) / 2), 8);
        assertEquals(0.5, peak, 0.1);
    }

    @Test
    void shiftsShorterThanTheMinimumAreNotRepeats() {
        // noise blurred over 9 × 9 pixels: like itself a pixel away, not twenty pixels away
        int[] v = noise(5, W * H);
        Image blurred = grey((x, y) -> {
            int sum = 0;
            int n = 0;
            for (int dy = -4; dy <= 4; dy++) {
                for (int dx = -4; dx <= 4; dx++) {
                    int sx = Math.floorMod(x + dx, W);
                    int sy = Math.floorMod(y + dy, H);
                    sum += v[sy * W + sx];
                    n++;
                }
            }
            return 128 + (sum / n - 128) * 8;
        });
        assertTrue(Repetition.peak(blurred, 1) > 0.8, "a one-pixel shift of smooth noise");
        assertTrue(Repetition.peak(blurred, 20) < 0.25, "twenty pixels away");
    }

    @Test
    void oneColourHasNothingToRepeat() {
        assertEquals(0, Repetition.peak(grey((x, y) -> 90), 8));
    }
}
