package org.openworld.engine.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.gl.Image;

/** Counts, colour differences, the worst pixel and the difference image, on small pictures with known edits. */
class ImageComparisonTest {

    private static final int W = 8;
    private static final int H = 6;

    /** A black opaque picture with one orange pixel at (7, 5). */
    private static byte[] base() {
        byte[] rgba = new byte[W * H * 4];
        for (int i = 0; i < W * H; i++) {
            rgba[i * 4 + 3] = (byte) 255;
        }
        set(rgba, 7, 5, 200, 100, 50, 255);
        return rgba;
    }

    private static void set(byte[] rgba, int x, int y, int r, int g, int b, int a) {
        int i = (y * W + x) * 4;
        rgba[i] = (byte) r;
        rgba[i + 1] = (byte) g;
        rgba[i + 2] = (byte) b;
        rgba[i + 3] = (byte) a;
    }

    private static void assertPixel(Image image, int x, int y, int r, int g, int b) {
        String at = "(" + x + ", " + y + ")";
        assertEquals(r, image.channel(x, y, 0), "red at " + at);
        assertEquals(g, image.channel(x, y, 1), "green at " + at);
        assertEquals(b, image.channel(x, y, 2), "blue at " + at);
        assertEquals(255, image.channel(x, y, 3), "alpha at " + at);
    }

    @Test
    void identicalPicturesHaveNothingChanged() {
        ImageComparison same = ImageComparison.of(new Image(W, H, base()), new Image(W, H, base()));
        assertEquals(W * H, same.pixels());
        assertEquals(0, same.changedPixels());
        assertEquals(0, same.pixelsAbove(0));
        assertEquals(0, same.meanDeltaE());
        assertEquals(0, same.maxDeltaE());
        Image difference = same.differenceImage(1);
        int grey = (int) Math.round(0.5 * new Image(W, H, base()).luma(7, 5));
        assertTrue(grey > 0, "the orange pixel shows in grey");
        assertPixel(difference, 7, 5, grey, grey, grey);
        assertPixel(difference, 0, 0, 0, 0, 0);
    }

    @Test
    void knownEditsAreCountedMeasuredAndDrawn() {
        byte[] edited = base();
        set(edited, 5, 3, 255, 255, 255, 255); // black to white: ΔE00 100
        set(edited, 2, 4, 40, 0, 0, 255);      // black to a dark red: a few units
        set(edited, 1, 1, 0, 0, 0, 128);       // alpha alone: changed, ΔE00 0
        ImageComparison diff = ImageComparison.of(new Image(W, H, base()), new Image(W, H, edited));

        double darkRed = DeltaE.ciede2000(Lab.fromSrgb(0, 0, 0), Lab.fromSrgb(40, 0, 0));
        assertTrue(darkRed > 1 && darkRed < 100, "dark red differs from black visibly, less than white: " + darkRed);
        assertEquals(3, diff.changedPixels());
        assertEquals(2, diff.pixelsAbove(1));
        assertEquals(1, diff.pixelsAbove(darkRed));
        // 1e-4 to 1e-5 ΔE00: double arithmetic in Lab.fromSrgb and ciede2000 rounds far below this; the test only
        // checks the sums
        assertEquals(100, diff.maxDeltaE(), 1e-4);
        assertEquals(5, diff.maxX());
        assertEquals(3, diff.maxY());
        assertEquals(darkRed, diff.deltaE(2, 4), 1e-5);
        assertEquals(0, diff.deltaE(1, 1));
        assertEquals((100 + darkRed) / (W * H), diff.meanDeltaE(), 1e-5);

        Image picture = diff.differenceImage(1);
        assertPixel(picture, 5, 3, 255, 255, 0);
        assertPixel(picture, 2, 4, 255, (int) Math.round(255 * (darkRed - 1) / (100 - 1)), 0);
        assertPixel(picture, 1, 1, 96, 0, 0);   // alpha alone, ΔE00 0: black with a faint red cast
        Image strict = diff.differenceImage(0);
        assertPixel(strict, 2, 4, 255, (int) Math.round(255 * darkRed / 100), 0);
        int grey = (int) Math.round(0.5 * new Image(W, H, base()).luma(7, 5));
        assertPixel(picture, 7, 5, grey, grey, grey);
        assertPixel(picture, 0, 0, 0, 0, 0);
    }

    @Test
    void picturesOfDifferentSizesAreRefused() {
        Image small = new Image(4, 4, new byte[4 * 4 * 4]);
        assertThrows(IllegalArgumentException.class, () -> ImageComparison.of(new Image(W, H, base()), small));
    }
}
