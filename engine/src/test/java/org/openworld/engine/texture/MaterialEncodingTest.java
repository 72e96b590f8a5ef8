package org.openworld.engine.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Packing the materials' fields into RGBA8, GL-free: the sRGB table, the normal, the height range, the wrap. */
class MaterialEncodingTest {

    private static final int N = 64;
    private final MaterialEncoding encoding = new MaterialEncoding(N);

    private static double srgbToLinear(int v) {
        double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /** Every 8-bit level, decoded to linear and encoded again, comes back: the table is exact where sRGB is steep. */
    @Test
    void everySrgbLevelSurvivesTheRoundTrip() {
        for (int v = 0; v <= 255; v++) {
            assertEquals(v, encoding.toSrgb((float) srgbToLinear(v)) & 0xFF, "level " + v);
        }
        assertEquals(0, encoding.toSrgb(-0.5f), "clamped below");
        assertEquals(255, encoding.toSrgb(7f) & 0xFF, "clamped above");
    }

    private static MaterialFields fields(float[] height) {
        float[] grey = new float[N * N];
        java.util.Arrays.fill(grey, 0.5f);
        return new MaterialFields(grey, grey, grey, height, grey);
    }

    /**
     * A relief of one sine wave along x, h = A sin(2π x / N): the normal's x is −h′ / √(h′² + 1) with h′ the central
     * difference, y is 0 (128), and at x = 0 the difference reaches back to column N − 1 across the wrap.
     */
    @Test
    void theNormalIsTheReliefsWrappedCentralDifference() {
        double amplitude = 6;
        float[] h = new float[N * N];
        for (int y = 0; y < N; y++) {
            for (int x = 0; x < N; x++) {
                h[y * N + x] = (float) (amplitude * Math.sin(2 * Math.PI * x / N));
            }
        }
        byte[] detail = encoding.detail(fields(h));
        for (int x : new int[] {0, 5, N / 4, N / 2, N - 1}) {
            double slope = (h[(x + 1) % N] - h[(x + N - 1) % N]) / 2;
            double nx = -slope / Math.sqrt(slope * slope + 1);
            int y = 17;
            int i = 4 * (y * N + x);
            assertEquals(Math.round((nx * 0.5 + 0.5) * 255), detail[i] & 0xFF, "normal x at column " + x);
            assertEquals(128, detail[i + 1] & 0xFF, "normal y at column " + x);
            assertEquals(128, detail[i + 3] & 0xFF, "gloss 0.5");
        }
        // at x = 0 the wave rises at its steepest; the difference spans columns 1 and N − 1: (h(1) − h(−1)) / 2
        double steepest = amplitude * Math.sin(2 * Math.PI / N); // 0.59 per texel, the normal tilted towards −x
        assertEquals(Math.round((-steepest / Math.sqrt(1 + steepest * steepest) * 0.5 + 0.5) * 255), detail[0] & 0xFF,
                "the wrap: column 0's neighbours are columns 1 and N − 1");
    }

    /** The relief's mean maps to the middle of the height channel and ± 2.5 standard deviations to its ends. */
    @Test
    void theHeightSpansMeanPlusMinusTwoAndAHalfStandardDeviations() {
        float[] h = new float[N * N];
        for (int i = 0; i < h.length; i++) {
            h[i] = i % 2 == 0 ? 13 : 9; // mean 11, standard deviation 2
        }
        byte[] detail = encoding.detail(fields(h));
        assertEquals(Math.round((0.5 + 2 / 10.0) * 255), detail[2] & 0xFF, "a texel one deviation high");
        assertEquals(Math.round((0.5 - 2 / 10.0) * 255), detail[4 + 2] & 0xFF, "a texel one deviation low");
    }

    @Test
    void albedoIsTheColourInSrgbWithOpaqueAlpha() {
        byte[] albedo = encoding.albedo(fields(new float[N * N]));
        assertEquals(encoding.toSrgb(0.5f), albedo[0]);
        assertEquals(188, albedo[1] & 0xFF, "linear 0.5 is sRGB 188");
        assertEquals(255, albedo[3] & 0xFF);
    }
}
