package org.openworld.engine.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;
import org.openworld.engine.gl.Image;

/**
 * The shimmer measure on synthetic pictures: grey patterns sampled once a pixel (the frame) or 16 times and reduced
 * (the reference), moved by half a pixel between the two frames, as a camera's small step moves the ground.
 */
class ShimmerTest {

    private static final int W = 96;
    private static final int H = 64;
    /** Samples a side of the references, as the command takes them. */
    private static final int SCALE = 4;
    /** The second frame's shift, pixels: the far ground's motion under a 1 m step at 480 × 270. */
    private static final double SHIFT = 0.5;

    /** A smooth pattern (periods of 16 and 13 pixels): one sample a pixel already resolves it. */
    private static final DoubleBinaryOperator SMOOTH = (u, v) ->
            0.2 + 0.1 * Math.sin(2 * Math.PI * u / 16) * Math.sin(2 * Math.PI * v / 13);
    /** Bars 0.8 pixels wide every 3.3 pixels: one sample a pixel catches a bar or misses it, a staircase that crawls. */
    private static final DoubleBinaryOperator BARS = (u, v) -> (u + 0.4 * v) / 3.3 % 1 < 0.8 / 3.3 ? 0.8 : 0.05;

    /** The pattern (linear light) shifted right by {@code shift} pixels, {@code k}² samples a pixel, sRGB-encoded. */
    private static Image render(DoubleBinaryOperator pattern, double shift, int k) {
        byte[] rgba = new byte[W * k * H * k * 4];
        for (int y = 0, i = 0; y < H * k; y++) {
            for (int x = 0; x < W * k; x++, i += 4) {
                double linear = pattern.applyAsDouble((x + 0.5) / k - shift, (y + 0.5) / k);
                double code = linear <= 0.0031308 ? linear * 12.92 : 1.055 * Math.pow(linear, 1 / 2.4) - 0.055;
                byte grey = (byte) Math.round(code * 255);
                rgba[i] = grey;
                rgba[i + 1] = grey;
                rgba[i + 2] = grey;
                rgba[i + 3] = (byte) 255;
            }
        }
        Image image = new Image(W * k, H * k, rgba);
        return k == 1 ? image : Shimmer.reduce(image, k);
    }

    private static Shimmer moved(DoubleBinaryOperator pattern) {
        return Shimmer.of(render(pattern, 0, 1), render(pattern, SHIFT, 1),
                render(pattern, 0, SCALE), render(pattern, SHIFT, SCALE));
    }

    @Test
    void aTranslationThatTheReferenceSharesIsNoShimmer() {
        Shimmer smooth = moved(SMOOTH);
        // the motion itself is noticeable: half a pixel of a pattern whose slope reaches 0.04 of linear light a pixel
        // changes the grey by several ΔE00, except near the crests and the zero lines where the slope along x
        // vanishes: a quarter of the pixels at least
        assertTrue(smooth.rawShare() > 0.25, "raw share " + smooth.rawShare());
        // one sample and sixteen differ by a code's rounding and the box's 0.6 % loss of amplitude at a 16-pixel
        // period, far below one ΔE00 in both frames, so no pixel changes noticeably more than its reference
        assertEquals(0, smooth.share(), "shimmer share");
        assertTrue(smooth.meanError() < Shimmer.NOTICEABLE, "mean error " + smooth.meanError());
    }

    @Test
    void aliasedBarsShimmer() {
        Shimmer bars = moved(BARS);
        // a bar covers 0.8 / 3.3 of a pixel row on average: its reference pixels are mixtures that change smoothly
        // with the shift, while the single sample flips between bar and ground at a quarter of the pixels or so
        // (those whose centre a bar's edge crosses in half a pixel: 2 edges x 0.5 / 3.3 = 30 %)
        assertTrue(bars.share() > 0.15, "shimmer share " + bars.share());
        assertTrue(bars.share() <= bars.rawShare(), "shimmer within the raw changes");
    }

    @Test
    void injectedFlickerIsCountedPixelForPixel() {
        Image still = render(SMOOTH, 0, 1);
        Image reference = render(SMOOTH, 0, SCALE);
        byte[] rgba = new byte[W * H * 4];
        int flickered = 0;
        for (int y = 0, i = 0; y < H; y++) {
            for (int x = 0; x < W; x++, i += 4) {
                // every seventh pixel 40 codes brighter (about 10 ΔE00 at these greys): a glint on in one frame only
                boolean flicker = (x + W * y) % 7 == 0;
                flickered += flicker ? 1 : 0;
                for (int c = 0; c < 3; c++) {
                    rgba[i + c] = (byte) (still.channel(x, y, c) + (flicker ? 40 : 0));
                }
                rgba[i + 3] = (byte) 255;
            }
        }
        Shimmer flicker = Shimmer.of(still, new Image(W, H, rgba), reference, reference);
        assertEquals((double) flickered / (W * H), flicker.share(), 1e-12);
    }

    @Test
    void reduceAveragesInLinearLight() {
        // black and white halves: linear mean 0.5, which sRGB encodes as 188 (not the codes' mean, 128)
        byte[] rgba = {0, 0, 0, (byte) 255, (byte) 255, (byte) 255, (byte) 255, (byte) 255};
        Image half = Shimmer.reduce(new Image(2, 1, rgba), 1);
        assertEquals(255, half.channel(1, 0, 0), "factor 1 keeps the picture");
        Image mean = Shimmer.reduce(new Image(2, 2, new byte[] {
            0, 0, 0, (byte) 255, (byte) 255, (byte) 255, (byte) 255, (byte) 255,
            0, 0, 0, (byte) 255, (byte) 255, (byte) 255, (byte) 255, (byte) 255}), 2);
        assertEquals(188, mean.channel(0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> Shimmer.reduce(new Image(3, 2, new byte[24]), 2));
    }
}
