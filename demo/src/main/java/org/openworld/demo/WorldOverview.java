package org.openworld.demo;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.lang.management.MemoryPoolMXBean;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.openworld.engine.files.AtomicFiles;
import org.openworld.engine.erosion.ErodedWorld;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.UniformHeights;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.PowerSpectrum;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * {@code openworld heightmap --overview}: a picture of the unbounded world ({@link BandedHeights}), 64 km × 64 km
 * centred on the origin at 32 m between samples (2000² samples of the pyramid level whose spacing is 32 m, made
 * directly at that level: no finer sample is made). Writes {@code height.png} (16-bit, as {@code heightmap} does)
 * and {@code relief.png}: the heights tinted from sea blue through green and brown to snow white and shaded under a
 * light from the north-west, the cartographers' hillshade. Made in strips, each reported as it is done.
 */
final class WorldOverview {

    static final String RELIEF_PNG = "relief.png";
    /** Side of the overview, samples, and metres between them: 64 km. */
    static final int SAMPLES = 2000;
    static final double SPACING_M = 32;
    /** Strips made and reported one after the other. */
    private static final int STRIPS = 8;
    /** Side of the central square whose spectrum is fitted: the largest power of two inside the overview. */
    private static final int SPECTRUM_SAMPLES = 1024;
    /** Light from the north-west, 45° up: x east, y up, z south (as the minimap's hillshade). */
    private static final double[] LIGHT = {-0.5, Math.sqrt(0.5), -0.5};
    /** Slopes are drawn this many times steeper: at 32 m a sample, 2 km mountains are gentle. */
    private static final double EXAGGERATION = 2;
    /** Share of the light on slopes turned from the sun, so they keep their colour. */
    private static final double AMBIENT = 0.35;
    /** Tints, display RGB: the sea, then from the shore to the highest sample, evenly spread over the heights. */
    private static final int[][] TINTS = {{52, 92, 150}, {96, 140, 84}, {150, 150, 96}, {130, 104, 80}, {236, 236, 240}};
    private static final double BYTES_PER_MIB = 1024.0 * 1024.0;

    private WorldOverview() {
    }

    /** Makes the overview and writes its two pictures into {@code out}; exit code 0. */
    static int write(TerrainSettings terrain, int seed, Path out) throws IOException {
        int level = (int) Math.round(Math.log(SPACING_M / terrain.spacing()) / Math.log(2));
        if (level < 0 || Math.scalb(terrain.spacing(), level) != SPACING_M) {
            throw new UserError("--overview samples the world " + (int) SPACING_M + " m apart, a power of two times "
                    + "terrain.spacing: give a spacing of 32 m / 2^k (1, 2, 4, 8, 16 or 32 m), not "
                    + terrain.spacing() + " m");
        }
        List<MemoryPoolMXBean> heapPools = HeightmapCommand.resetHeapPeaks();
        long start = System.nanoTime();
        UniformHeights world = ErodedWorld.unbounded(terrain, seed);
        if (level >= world.levels()) {
            throw new UserError("--overview: terrain.max-wavelength (" + terrain.maxWavelength() + " m) leaves no "
                    + "wavelength longer than two samples of " + (int) SPACING_M + " m; the overview would be flat");
        }
        System.out.printf(Locale.ROOT, "overview: %d² samples %.0f m apart (pyramid level %d, bands %d to %d), "
                + "%.0f km across, beta %s, seed %d%n", SAMPLES, SPACING_M, level, level, world.levels() - 1,
                SAMPLES * SPACING_M / 1000, terrain.beta(), seed);
        float[] heights = new float[SAMPLES * SAMPLES];
        int strip = SAMPLES / STRIPS;
        for (int s = 0; s < STRIPS; s++) {
            // a strip is STRIPS square windows side by side, each made directly at the level
            for (int w = 0; w < STRIPS; w++) {
                float[] window = world.level(level, -SAMPLES / 2 + w * strip, -SAMPLES / 2 + s * strip, strip);
                for (int j = 0; j < strip; j++) {
                    System.arraycopy(window, j * strip, heights, (s * strip + j) * SAMPLES + w * strip, strip);
                }
            }
            System.out.printf(Locale.ROOT, "overview: %5.1f of %.0f km made (%3d %%), %.1f s%n",
                    (s + 1) * strip * SPACING_M / 1000, SAMPLES * SPACING_M / 1000, 100 * (s + 1) / STRIPS,
                    (System.nanoTime() - start) / 1e9);
        }
        long peakHeap = heapPools.stream().mapToLong(p -> p.getPeakUsage().getUsed()).sum();
        System.out.printf(Locale.ROOT, "overview made in %.2f s, peak heap %.0f MiB%n",
                (System.nanoTime() - start) / 1e9, peakHeap / BYTES_PER_MIB);

        PowerSpectrum.Fit fit = PowerSpectrum.tapered(centre(heights)).fit(1 / terrain.maxWavelength(),
                1 / (2 * SPACING_M));
        System.out.printf(Locale.ROOT, "spectrum slope of the central %d²: %.2f (expected -2 beta = %.2f)%n",
                SPECTRUM_SAMPLES, fit.slope(), -2 * terrain.beta());

        HeightmapCommand.writeHeight(SAMPLES, heights, out.resolve(HeightmapCommand.HEIGHT_PNG));
        BufferedImage relief = relief(heights, SAMPLES);
        AtomicFiles.write(out.resolve(RELIEF_PNG), file -> ImageIO.write(relief, "png", file.toFile()));
        System.out.println("wrote " + out.resolve(HeightmapCommand.HEIGHT_PNG) + ", " + out.resolve(RELIEF_PNG));
        return 0;
    }

    /** The central {@link #SPECTRUM_SAMPLES}² of the overview, for the power spectrum (which needs a power of two). */
    private static HeightMap centre(float[] heights) {
        int m = SPECTRUM_SAMPLES;
        int from = (SAMPLES - m) / 2;
        float[] c = new float[m * m];
        for (int j = 0; j < m; j++) {
            System.arraycopy(heights, (from + j) * SAMPLES + from, c, j * m, m);
        }
        return new HeightMap(m, SPACING_M, c, false);
    }

    /**
     * The shaded relief: below 0 m the sea's tint, above it the tints spread between 0 m and the highest sample,
     * times {@code AMBIENT + (1 − AMBIENT) · max(0, n · l)} for the normal n of the (exaggerated) central
     * differences and the light l.
     */
    static BufferedImage relief(float[] h, int n) {
        float top = Float.MIN_NORMAL; // the highest sample, above 0
        for (float v : h) {
            top = Math.max(top, v);
        }
        BufferedImage image = new BufferedImage(n, n, BufferedImage.TYPE_INT_RGB);
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                double dhdx = (h[z * n + Math.min(x + 1, n - 1)] - h[z * n + Math.max(x - 1, 0)]) / (2 * SPACING_M);
                double dhdz = (h[Math.min(z + 1, n - 1) * n + x] - h[Math.max(z - 1, 0) * n + x]) / (2 * SPACING_M);
                dhdx *= EXAGGERATION;
                dhdz *= EXAGGERATION;
                double length = Math.sqrt(dhdx * dhdx + 1 + dhdz * dhdz);
                double lit = Math.max(0, (-dhdx * LIGHT[0] + LIGHT[1] - dhdz * LIGHT[2]) / length);
                double light = AMBIENT + (1 - AMBIENT) * lit / LIGHT[1]; // flat ground at full colour
                float v = h[z * n + x];
                int rgb = 0;
                for (int c = 0; c < 3; c++) {
                    double colour = v < 0 ? TINTS[0][c] : land(v / top, c) * light; // the sea flat, unshaded
                    rgb = rgb << 8 | (int) Math.max(0, Math.min(255, Math.round(colour)));
                }
                image.setRGB(x, z, rgb);
            }
        }
        return image;
    }

    /** Channel c of the land's tint at a height t of the highest (0 .. 1), between the tints after the sea's. */
    private static double land(double t, int c) {
        double at = Math.max(0, Math.min(1, t)) * (TINTS.length - 2);
        int i = Math.min((int) at, TINTS.length - 3);
        double f = at - i;
        return (1 - f) * TINTS[i + 1][c] + f * TINTS[i + 2][c];
    }
}
