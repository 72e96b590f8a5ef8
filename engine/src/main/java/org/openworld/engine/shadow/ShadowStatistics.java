package org.openworld.engine.shadow;

import java.util.Optional;
import org.joml.Vector3fc;
import org.openworld.engine.core.HeightField;

/**
 * The two numbers that judge a shadow method (the paper's section 3.2 names both troubles: Z-fighting flicker and
 * the margin that trades it against missing shadows), computed from what {@link ShadowProbe} reads back of a frame.
 * GL-free, so the measures themselves are unit tested.
 *
 * <p>The buffer: four floats per pixel, {@code (visibility, x, y, z)}: the sun's visibility as the lit shaders see it
 * ({@code sunVisibility}, 1 lit, 0 shadowed) at the pixel's world point, in metres; a pixel showing the sky holds
 * {@link #SKY} as its visibility. Any pixel order, as long as rows are {@code width} pixels long.
 * <ul>
 *   <li><b>Flicker</b>: the mean absolute change of the visibility from one frame to the next, at the same world
 *       points ({@link #flicker}): the probe asks this frame's maps about the last frame's points, so the camera's
 *       motion is taken out, and what a moving camera leaves is the maps' refitting, the flicker the eye sees.</li>
 *   <li><b>Acne</b>: among ground points that the sun truly reaches, found by marching a ray through the height
 *       field towards the sun, the fraction that the maps shadow anyway ({@link #acne}): a surface shadowing
 *       itself, the artefact too small a margin or bias gives.</li>
 * </ul>
 */
final class ShadowStatistics {

    /** The visibility a sky pixel holds: no world point, measured by neither number. */
    static final float SKY = -1;
    /** Floats per pixel: visibility, x, y, z. */
    static final int CHANNELS = 4;

    /** Acne is tested at every 4th pixel in x and y: a sixteenth of the ray marches, still thousands of points. */
    static final int ACNE_STRIDE = 4;
    /**
     * A point lies on the ground when the height field there is within this many metres of it, plus
     * {@link #GROUND_PER_METRE}: half a metre covers the terrain mesh's own departure from the bilinear height
     * field; water and anything else standing apart from the ground is left out.
     */
    static final double GROUND_METRES = 0.5;
    /** ... plus this many metres per metre of distance: coarser terrain patches far away, and the depth rounding. */
    static final double GROUND_PER_METRE = 0.002;
    /** Distance between the two height samples of each central difference for the ground's normal, metres. */
    static final double NORMAL_SPAN = 1;
    /**
     * A ground point faces the sun when the cosine of the sun's angle to its normal exceeds this (about 73°): at more
     * grazing light a lit shader's sunlight is faint, and every bias is meant to give way there.
     */
    static final double SUN_FACING = 0.3;
    /** The visibility below which a point counts as shadowed: more than half of the filter's taps in shadow. */
    static final double SHADOWED = 0.5;
    /** The march starts this many metres off the ground along its normal, clear of the point's own bilinear cell. */
    static final double MARCH_LIFT = 0.3;
    /** The march's first step, metres: finer than the finest terrain spacing in use (1–2 m). */
    static final double MARCH_FIRST_STEP = 1;
    /** Each step is this much longer than the one before: far ground needs no metre steps; 150 steps reach 30 km. */
    static final double MARCH_GROWTH = 1.05;
    /** The march gives up after this many metres: beyond the largest world's shadow distance. */
    static final double MARCH_REACH = 30_000;

    /** Flicker over one pair of frames: the mean absolute change of the visibility, over {@code pixels} still ones. */
    record Flicker(double mean, int pixels) {
    }

    /** Acne in one frame: the fraction of {@code pixels} truly lit, sun-facing ground points the maps shadow. */
    record Acne(double fraction, int pixels) {
    }

    /** Both measures of a frame; no flicker on the first frame, or the first after the picture's size changed. */
    record Measures(Optional<Flicker> flicker, Acne acne) {
    }

    private float[] previous;
    private int previousWidth;

    /**
     * Measures one frame against the one before, then keeps a copy of it for the next.
     *
     * @param now       this frame's buffer (see the class documentation)
     * @param lastPointsNow the last frame's world points with this frame's visibility there (the probe asks this
     *                  frame's maps about them), or null on a first frame: compared with the last frame's buffer,
     *                  the change is the maps' alone, none of it the camera's motion
     * @param width     pixels per row
     * @param eye       the viewer's eye, world space
     * @param toSun     unit vector towards the sun
     * @param ground    the ground's height field
     * @param maxHeight metres: no ground is higher, so the sun's ray is free once above it
     */
    Measures measure(float[] now, float[] lastPointsNow, int width, Vector3fc eye, Vector3fc toSun,
                     HeightField ground, double maxHeight) {
        Optional<Flicker> flicker = lastPointsNow != null && previous != null && previous.length == now.length
                && previousWidth == width ? Optional.of(flicker(lastPointsNow, previous)) : Optional.empty();
        Acne acne = acne(now, width, eye, toSun, ground, maxHeight);
        if (previous == null || previous.length != now.length) {
            previous = new float[now.length];
        }
        System.arraycopy(now, 0, previous, 0, now.length);
        previousWidth = width;
        return new Measures(flicker, acne);
    }

    /**
     * The mean absolute change of the visibility at the same world points: {@code previous} is the last frame's
     * buffer, {@code now} this frame's maps asked about its points. Over the pixels that show ground in both; a mean
     * over no pixels is 0.
     */
    static Flicker flicker(float[] now, float[] previous) {
        if (now.length != previous.length) {
            throw new IllegalArgumentException("frames of " + now.length / CHANNELS + " and "
                    + previous.length / CHANNELS + " pixels");
        }
        double sum = 0;
        int pixels = 0;
        for (int i = 0; i < now.length; i += CHANNELS) {
            if (now[i] == SKY || previous[i] == SKY) {
                continue;
            }
            sum += Math.abs(now[i] - previous[i]);
            pixels++;
        }
        return new Flicker(pixels == 0 ? 0 : sum / pixels, pixels);
    }

    /**
     * The fraction of truly lit, sun-facing ground points that the maps shadow (visibility below {@link #SHADOWED}),
     * over every {@link #ACNE_STRIDE}-th pixel in x and y. A point is ground when the height field is within
     * {@link #GROUND_METRES} + {@link #GROUND_PER_METRE} × its distance of it; its normal is the height field's
     * (central differences {@link #NORMAL_SPAN} apart); it faces the sun when the cosine exceeds {@link #SUN_FACING};
     * it is truly lit when {@link #trulyLit} says so. A fraction of no points is 0.
     */
    static Acne acne(float[] now, int width, Vector3fc eye, Vector3fc toSun, HeightField ground, double maxHeight) {
        int height = now.length / CHANNELS / width;
        int shadowed = 0;
        int pixels = 0;
        for (int y = 0; y < height; y += ACNE_STRIDE) {
            for (int x = 0; x < width; x += ACNE_STRIDE) {
                int i = (y * width + x) * CHANNELS;
                if (now[i] == SKY) {
                    continue;
                }
                double px = now[i + 1];
                double py = now[i + 2];
                double pz = now[i + 3];
                double fromEye = distance(now, i, eye.x(), eye.y(), eye.z());
                if (Math.abs(ground.heightAt(px, pz) - py) >= GROUND_METRES + GROUND_PER_METRE * fromEye) {
                    continue;
                }
                double[] n = groundNormal(ground, px, pz);
                double facing = n[0] * toSun.x() + n[1] * toSun.y() + n[2] * toSun.z();
                if (facing <= SUN_FACING || !trulyLit(ground, px + n[0] * MARCH_LIFT, py + n[1] * MARCH_LIFT,
                        pz + n[2] * MARCH_LIFT, toSun, maxHeight)) {
                    continue;
                }
                pixels++;
                if (now[i] < SHADOWED) {
                    shadowed++;
                }
            }
        }
        return new Acne(pixels == 0 ? 0 : (double) shadowed / pixels, pixels);
    }

    /** The height field's unit normal at (x, z), from central differences {@link #NORMAL_SPAN} apart. */
    static double[] groundNormal(HeightField ground, double x, double z) {
        double half = NORMAL_SPAN / 2;
        double dx = (ground.heightAt(x + half, z) - ground.heightAt(x - half, z)) / NORMAL_SPAN;
        double dz = (ground.heightAt(x, z + half) - ground.heightAt(x, z - half)) / NORMAL_SPAN;
        double length = Math.sqrt(dx * dx + 1 + dz * dz);
        return new double[] {-dx / length, 1 / length, -dz / length};
    }

    /**
     * Whether the ray from (x, y, z) towards the sun stays above the ground: steps from {@link #MARCH_FIRST_STEP},
     * each {@link #MARCH_GROWTH} times the last, until the ray is above {@code maxHeight} (free) or
     * {@link #MARCH_REACH} away (taken as free), or below the height field (blocked).
     */
    static boolean trulyLit(HeightField ground, double x, double y, double z, Vector3fc toSun, double maxHeight) {
        double step = MARCH_FIRST_STEP;
        for (double t = step; t <= MARCH_REACH; step *= MARCH_GROWTH, t += step) {
            double ry = y + toSun.y() * t;
            if (ry > maxHeight) {
                return true;
            }
            if (ground.heightAt(x + toSun.x() * t, z + toSun.z() * t) > ry) {
                return false;
            }
        }
        return true;
    }

    private static double distance(float[] buffer, int i, double x, double y, double z) {
        double dx = buffer[i + 1] - x;
        double dy = buffer[i + 2] - y;
        double dz = buffer[i + 3] - z;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
