package org.openworld.engine.colour;

import org.openworld.engine.gl.Image;

/**
 * Shimmer: how much of a picture changes between two frames by more than the motion between them explains. Two
 * frames of a static world from poses a little apart differ wherever the picture moved, aliased or not; what a
 * perfectly anti-aliased renderer would show is the same pair supersampled (many samples per pixel, averaged). A pixel
 * <em>shimmers</em> when its change between the frames exceeds its reference's change by more than just noticeable:
 *
 * <pre>    ΔE00(A, B) &gt; ΔE00(A_ref, B_ref) + 1</pre>
 *
 * <p>where A, B are the frames and A_ref, B_ref the same frames rendered {@code k} times larger and reduced by
 * {@link #reduce} (k² samples per pixel, a box filter in linear light, the resolve of supersampling). The share of
 * such pixels is the figure; the raw share, {@code ΔE00(A, B) > 1}, is kept beside it.
 *
 * <p>Why against the reference and not against frame A reprojected into pose B: reprojection resamples A between its
 * pixels, and a sharp textured picture resampled half a pixel over differs from the same picture rendered there by
 * as much as the motion itself (a bilinear look-up is a blur), so the floor of the raw figure would stay. Here a
 * renderer equal to its reference scores 0 under any motion, and a pure translation that the reference shares
 * scores 0 too. Cost: two more frames at k² the pixels, and two comparisons.
 *
 * <p>Limits: a picture softer than its reference changes less and is not counted (softness is another figure:
 * {@link #meanError}, the mean ΔE00 of a frame from its reference); a pixel whose colour changes as much as the
 * reference's but the other way is not counted either. The reference's own aliasing (k² samples) is the floor.
 */
public final class Shimmer {

    /** ΔE00 above which a difference is just noticeable side by side (CIEDE2000's scale is built so). */
    public static final double NOTICEABLE = 1;

    private final double share;
    private final double rawShare;
    private final double meanError;

    private Shimmer(double share, double rawShare, double meanError) {
        this.share = share;
        this.rawShare = rawShare;
        this.meanError = meanError;
    }

    /**
     * Measures frames {@code first} and {@code second} against their references of the same size.
     *
     * @throws IllegalArgumentException if the four sizes differ
     */
    public static Shimmer of(Image first, Image second, Image firstReference, Image secondReference) {
        ImageComparison frames = ImageComparison.of(first, second);
        ImageComparison references = ImageComparison.of(firstReference, secondReference);
        int above = 0;
        for (int y = 0; y < frames.height(); y++) {
            for (int x = 0; x < frames.width(); x++) {
                above += frames.deltaE(x, y) > references.deltaE(x, y) + NOTICEABLE ? 1 : 0;
            }
        }
        double error = (ImageComparison.of(first, firstReference).meanDeltaE()
                + ImageComparison.of(second, secondReference).meanDeltaE()) / 2;
        double pixels = frames.pixels();
        return new Shimmer(above / pixels, frames.pixelsAbove(NOTICEABLE) / pixels, error);
    }

    /**
     * The picture {@code factor} times smaller on each side, each pixel the mean of its {@code factor}² pixels in
     * linear light (decoded from sRGB, averaged, encoded again), alpha opaque.
     *
     * @throws IllegalArgumentException if a side is not a multiple of {@code factor}
     */
    public static Image reduce(Image image, int factor) {
        if (factor < 1 || image.width() % factor != 0 || image.height() % factor != 0) {
            throw new IllegalArgumentException(image.width() + "x" + image.height() + " is not a multiple of "
                    + factor);
        }
        int width = image.width() / factor;
        int height = image.height() / factor;
        byte[] rgba = new byte[width * height * 4];
        double samples = factor * factor;
        for (int y = 0, i = 0; y < height; y++) {
            for (int x = 0; x < width; x++, i += 4) {
                for (int c = 0; c < 3; c++) {
                    double sum = 0;
                    for (int sy = 0; sy < factor; sy++) {
                        for (int sx = 0; sx < factor; sx++) {
                            sum += Lab.linear(image.channel(x * factor + sx, y * factor + sy, c));
                        }
                    }
                    rgba[i + c] = (byte) encode(sum / samples);
                }
                rgba[i + 3] = (byte) 0xFF;
            }
        }
        return new Image(width, height, rgba);
    }

    /** The 8-bit sRGB code value nearest linear light {@code v} (0 to 1; IEC 61966-2-1's encoding). */
    private static int encode(double v) {
        double c = v <= 0.0031308 ? v * 12.92 : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
        return (int) Math.round(Math.max(0, Math.min(1, c)) * 255);
    }

    /** Share of the pixels (0 to 1) that change noticeably more than their reference does. */
    public double share() {
        return share;
    }

    /** Share of the pixels (0 to 1) that change noticeably at all, motion included. */
    public double rawShare() {
        return rawShare;
    }

    /** Mean ΔE00 of the two frames from their references: how far the pictures are from supersampled ones. */
    public double meanError() {
        return meanError;
    }
}
