package org.openworld.engine.temporal;

import org.joml.Matrix4f;
import org.openworld.engine.core.ViewCamera;

/**
 * The sub-pixel offsets of temporal anti-aliasing: frame n of a run of history is drawn with its projection moved by
 * a fraction of a pixel, so that a cycle of N frames ({@code antialias.samples}) samples each pixel at N places: the
 * Halton (2, 3) points 1 to N less one half, a low-discrepancy set that covers the pixel evenly at every prefix, whose
 * first point (1/2, 1/3) is moved to the pixel's centre, so that a single frame, with no history to blend, is the
 * plain picture. When N is a power of two the N points fall one in each N-th of the pixel along x.
 */
public final class Jitter {

    private Jitter() {
    }

    /**
     * The offset of frame {@code n} of a run with a cycle of {@code cycle} offsets, pixels along x (0) or y (1), each
     * in [−0.5, 0.5).
     */
    public static double offset(long n, int axis, int cycle) {
        int index = (int) (n % cycle);
        return index == 0 ? 0 : halton(index + 1, axis == 0 ? 2 : 3) - 0.5;
    }

    /** The radical inverse of {@code index} in {@code base}: its digits mirrored about the point. */
    static double halton(int index, int base) {
        double result = 0;
        double scale = 1.0 / base;
        for (int i = index; i > 0; i /= base) {
            result += scale * (i % base);
            scale /= base;
        }
        return result;
    }

    /**
     * {@code camera} with its projection moved by frame {@code n}'s offset in a cycle of {@code cycle} on a target of
     * {@code width} ×
     * {@code height} pixels: a translation of 2·offset / size in clip space after the projection, so every vertex
     * moves by the same fraction of a pixel and depth is unchanged.
     */
    public static ViewCamera apply(ViewCamera camera, long n, int cycle, int width, int height) {
        Matrix4f projection = new Matrix4f()
                .translation((float) (2 * offset(n, 0, cycle) / width), (float) (2 * offset(n, 1, cycle) / height), 0)
                .mul(camera.projection());
        return new ViewCamera(camera.exactView(), projection, camera.exactPosition(), camera.near(), camera.far());
    }
}
