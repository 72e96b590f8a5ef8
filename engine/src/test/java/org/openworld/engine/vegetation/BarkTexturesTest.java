package org.openworld.engine.vegetation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The synthesised barks, without GL: deterministic, seamless, stretched up the stem, bark-dark. */
class BarkTexturesTest {

    static final int N = BarkTextures.SIZE;
    static BarkTextures bark;

    @BeforeAll
    static void make() {
        bark = BarkTextures.generate(7);
    }

    @Test
    void theSameSeedGivesTheSameTexelsAndAnotherOthers() {
        BarkTextures again = BarkTextures.generate(7);
        BarkTextures other = BarkTextures.generate(8);
        for (int layer = 0; layer < BarkTextures.LAYERS; layer++) {
            assertArrayEquals(bark.albedo().get(layer), again.albedo().get(layer), "albedo of layer " + layer);
            assertArrayEquals(bark.detail().get(layer), again.detail().get(layer), "detail of layer " + layer);
            assertFalse(Arrays.equals(bark.detail().get(layer), other.detail().get(layer)), "seed 8's layer " + layer);
        }
    }

    /** Channel c (0..255) of texel (x, y), indices wrapping. */
    static int at(byte[] texels, int x, int y, int c) {
        return texels[4 * (Math.floorMod(y, N) * N + Math.floorMod(x, N)) + c] & 0xFF;
    }

    /** Mean |relief(x + dx, y + dy) − relief(x, y)| over the pairs whose first texel's column (dx) or row is in. */
    static double step(byte[] detail, int dx, int dy, int from, int to) {
        double sum = 0;
        int pairs = 0;
        for (int a = from; a < to; a++) {
            for (int b = 0; b < N; b++) {
                int x = dx != 0 ? a : b;
                int y = dx != 0 ? b : a;
                sum += Math.abs(at(detail, x + dx, y + dy, 2) - at(detail, x, y, 2));
                pairs++;
            }
        }
        return sum / pairs;
    }

    @Test
    void theTileIsAsSmoothAcrossItsEdgesAsInside() {
        for (int layer = 0; layer < BarkTextures.LAYERS; layer++) {
            byte[] d = bark.detail().get(layer);
            // across the edge: the last column to the first (wrapped), and the last row to the first; against the
            // mean over every interior pair. A seam would be a step of the relief's whole spread (tens of levels);
            // a seamless edge is one sample of the same distribution as the interior's 255 pairs, so within half
            // again of their mean
            double acrossX = step(d, 1, 0, N - 1, N);
            double insideX = step(d, 1, 0, 0, N - 1);
            double acrossY = step(d, 0, 1, N - 1, N);
            double insideY = step(d, 0, 1, 0, N - 1);
            assertTrue(acrossX < 1.5 * insideX, "layer " + layer + ": " + acrossX + " across x, " + insideX + " inside");
            assertTrue(acrossY < 1.5 * insideY, "layer " + layer + ": " + acrossY + " across y, " + insideY + " inside");
        }
    }

    @Test
    void theConifersPlatesRunUpTheStem() {
        byte[] d = bark.detail().get(BarkTextures.CONIFER);
        // squeezed 4 times across, the plates' relief changes about 4 times faster across than up (the unstretched
        // fine grain, a fifth of their relief, pulls the ratio down a little): require at least twice
        double across = step(d, 1, 0, 0, N);
        double up = step(d, 0, 1, 0, N);
        assertTrue(across > 2 * up, "relief steps across " + across + ", up " + up);
    }

    @Test
    void theConifersBarkIsRougherThanTheBroadleaves() {
        double conifer = meanTilt(bark.detail().get(BarkTextures.CONIFER));
        double broadleaf = meanTilt(bark.detail().get(BarkTextures.BROADLEAF));
        // furrows FURROW_DEPTH = 4 texels deep against swells of 0.8: the conifer's normals lean further, by more
        // than the encoding's step (1/127.5)
        assertTrue(conifer > broadleaf + 1 / 127.5, "mean normal tilt: conifer " + conifer + ", broadleaf "
                + broadleaf);
    }

    /** The mean length of the tangent-space normal's (x, y): the sine of its lean from the surface's normal. */
    static double meanTilt(byte[] detail) {
        double sum = 0;
        for (int i = 0; i < N * N; i++) {
            double x = (detail[4 * i] & 0xFF) / 127.5 - 1;
            double y = (detail[4 * i + 1] & 0xFF) / 127.5 - 1;
            sum += Math.hypot(x, y);
        }
        return sum / (N * N);
    }

    @Test
    void barkReflectsFiveToTwentyPercent() {
        for (int layer = 0; layer < BarkTextures.LAYERS; layer++) {
            byte[] a = bark.albedo().get(layer);
            double[] mean = new double[3];
            for (int i = 0; i < N * N; i++) {
                for (int c = 0; c < 3; c++) {
                    mean[c] += linear((a[4 * i + c] & 0xFF) / 255.0) / (N * N);
                }
                assertEquals(255, a[4 * i + 3] & 0xFF, "alpha");
            }
            // bark reflects 5-20 % of visible light (the class comment), redder than blue
            double mid = (mean[0] + mean[1] + mean[2]) / 3;
            assertTrue(mid > 0.05 && mid < 0.2, "layer " + layer + " mean albedo " + Arrays.toString(mean));
            assertTrue(mean[0] > mean[2], "layer " + layer + " mean albedo " + Arrays.toString(mean));
        }
    }

    @Test
    void aStretchedFieldIsTheFieldReadKTimesFasterAcross() {
        double[] field = new double[N * N];
        for (int i = 0; i < field.length; i++) {
            field[i] = i;
        }
        double[] s = BarkTextures.stretched(field, 4);
        assertEquals(field[3 * N + 8], s[3 * N + 2], "(2, 3) reads (8, 3)");
        assertEquals(field[3 * N + 4], s[3 * N + N / 4 + 1], "(n/4 + 1, 3) wraps to (4, 3)");
    }

    static double linear(double e) {
        return e <= 0.04045 ? e / 12.92 : Math.pow((e + 0.055) / 1.055, 2.4);
    }
}
