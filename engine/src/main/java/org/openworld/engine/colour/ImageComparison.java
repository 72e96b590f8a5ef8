package org.openworld.engine.colour;

import java.util.BitSet;
import org.openworld.engine.gl.Image;

/**
 * Two pictures of one size compared pixel by pixel: how many pixels changed, and by how much to the eye (CIEDE2000,
 * {@link DeltaE}), with a difference image that shows where. {@code openworld diff} prints it; tests and the docs'
 * figures can use it to say "these two renders look the same" with a number.
 *
 * <p>A pixel is <em>changed</em> when any of its four channels differs, alpha included; its colour difference compares
 * the RGB colours only, so a change of alpha alone counts as changed with ΔE00 0. The cost is two CIELAB
 * conversions and one ΔE00 per changed pixel, nothing for an equal one: about 1 s for a 1920×1080 pair in which
 * every pixel differs (measured on a busy two-core machine), far less for two renders that differ in places.
 */
public final class ImageComparison {

    /** How much of the first picture's brightness the difference image keeps for its grey background. */
    private static final double BACKGROUND_BRIGHTNESS = 0.5;
    private static final int OPAQUE = 255;
    /** How far the difference image lifts the red of a pixel that changed too little to notice. */
    private static final int FAINT_RED = 96;

    private final Image first;
    private final float[] deltaE;
    private final BitSet changed;
    private final double mean;
    private final int maxIndex;

    private ImageComparison(Image first, float[] deltaE, BitSet changed, double mean, int maxIndex) {
        this.first = first;
        this.deltaE = deltaE;
        this.changed = changed;
        this.mean = mean;
        this.maxIndex = maxIndex;
    }

    /**
     * Compares two pictures of the same size.
     *
     * @throws IllegalArgumentException if their sizes differ
     */
    public static ImageComparison of(Image first, Image second) {
        int width = first.width();
        int height = first.height();
        if (second.width() != width || second.height() != height) {
            throw new IllegalArgumentException("sizes differ: " + width + "x" + height + " and "
                    + second.width() + "x" + second.height());
        }
        float[] deltaE = new float[width * height];
        BitSet changed = new BitSet(deltaE.length);
        double sum = 0;
        int maxIndex = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                if (samePixel(first, second, x, y)) {
                    continue;
                }
                int i = y * width + x;
                changed.set(i);
                deltaE[i] = (float) DeltaE.ciede2000(lab(first, x, y), lab(second, x, y));
                sum += deltaE[i];
                if (deltaE[i] > deltaE[maxIndex]) {
                    maxIndex = i;
                }
            }
        }
        return new ImageComparison(first, deltaE, changed, sum / deltaE.length, maxIndex);
    }

    private static boolean samePixel(Image first, Image second, int x, int y) {
        for (int c = 0; c < 4; c++) {
            if (first.channel(x, y, c) != second.channel(x, y, c)) {
                return false;
            }
        }
        return true;
    }

    private static Lab lab(Image image, int x, int y) {
        return Lab.fromSrgb(image.channel(x, y, 0), image.channel(x, y, 1), image.channel(x, y, 2));
    }

    public int width() {
        return first.width();
    }

    public int height() {
        return first.height();
    }

    /** Width times height. */
    public int pixels() {
        return deltaE.length;
    }

    /** Pixels with any channel different. */
    public int changedPixels() {
        return changed.cardinality();
    }

    /** Pixels whose colour differs by more than this ΔE00, e.g. 1 for "noticeable side by side". */
    public int pixelsAbove(double threshold) {
        int count = 0;
        for (float d : deltaE) {
            count += d > threshold ? 1 : 0;
        }
        return count;
    }

    /** ΔE00 at (x, y), 0 where the colours are equal; y = 0 is the top row. */
    public double deltaE(int x, int y) {
        return deltaE[y * width() + x];
    }

    /** Mean ΔE00 over every pixel, unchanged ones included. */
    public double meanDeltaE() {
        return mean;
    }

    /** The largest ΔE00, 0 when the colours are all equal. */
    public double maxDeltaE() {
        return deltaE[maxIndex];
    }

    /** Column of the largest difference (the first in reading order on a tie; 0 when there is none). */
    public int maxX() {
        return maxIndex % width();
    }

    /** Row of the largest difference, 0 at the top. */
    public int maxY() {
        return maxIndex / width();
    }

    /**
     * A picture of where the two differ, in three kinds of pixel. Unchanged: the first picture in grey at half
     * brightness. Changed but by no more than {@code noticeable} ΔE00 (rounding, a shade no one would see): that grey
     * with its red lifted by {@value #FAINT_RED} and its green and blue halved, so such changes show as a faint red
     * cast that leaves the picture readable. Noticeable: a heat colour from pure red (just above {@code noticeable})
     * to yellow (the largest, {@link #maxDeltaE()}), so the changes a viewer would see stand out, the worst most.
     */
    public Image differenceImage(double noticeable) {
        int width = width();
        byte[] rgba = new byte[deltaE.length * 4];
        double span = maxDeltaE() - noticeable;
        for (int i = 0; i < deltaE.length; i++) {
            int grey = (int) Math.round(BACKGROUND_BRIGHTNESS * first.luma(i % width, i / width));
            int r = grey;
            int g = grey;
            int b = grey;
            if (changed.get(i) && deltaE[i] > noticeable) {
                r = OPAQUE;
                g = (int) Math.round(OPAQUE * (span > 0 ? (deltaE[i] - noticeable) / span : 1));
                b = 0;
            } else if (changed.get(i)) {
                r = Math.min(OPAQUE, grey + FAINT_RED);
                g = grey / 2;
                b = grey / 2;
            }
            rgba[i * 4] = (byte) r;
            rgba[i * 4 + 1] = (byte) g;
            rgba[i * 4 + 2] = (byte) b;
            rgba[i * 4 + 3] = (byte) OPAQUE;
        }
        return new Image(width, height(), rgba);
    }
}
