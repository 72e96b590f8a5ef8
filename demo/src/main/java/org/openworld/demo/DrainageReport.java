package org.openworld.demo;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.openworld.engine.drainage.DrainageStats;
import org.openworld.engine.drainage.FlowNetwork;
import org.openworld.engine.files.AtomicFiles;

/**
 * {@code openworld heightmap --stats}: the drainage measures of a grid of heights, whose water leaves at its border
 * and into the sea (heights at or below 0 m, where the generated worlds put sea level) ({@link DrainageStats}: Flint's
 * concavity θ, Hack's h, the hypsometric integral, slope percentiles, drainage density), printed, and
 * {@code drainage.png}: the channels (cells draining at least the fit range's lower end, blue, darker and wider
 * where they drain more) over the shaded relief in grey, the sea flat grey-blue.
 */
final class DrainageReport {

    static final String DRAINAGE_PNG = "drainage.png";
    /** Fit range of the slope–area and length–area fits, m²: 0.1 to 10 km², the channels of hills and valleys. */
    static final double AREA_MIN_M2 = 1e5;
    static final double AREA_MAX_M2 = 1e7;
    /** Ground at or below this height is sea: rivers end there, as at the grid's border. */
    private static final double SEA_LEVEL_M = 0;
    /** The channels' colour at the threshold and at the range's top, display RGB. */
    private static final int[] THIN = {120, 170, 230};
    private static final int[] THICK = {10, 40, 150};
    /** The sea, where the rivers end, display RGB. */
    private static final int SEA = 0x5c7ca0;
    /** Grey of the relief: ambient and lit share, out of 255. */
    private static final double AMBIENT = 90;
    private static final double LIT = 165;

    private DrainageReport() {
    }

    /**
     * Measures the heights, prints the figures under {@code title} and writes {@code drainage.png} into {@code out}.
     *
     * @param heights {@code n × n} heights, row-major, {@code spacing} metres apart
     */
    static void write(String title, float[] heights, int n, double spacing, Path out) throws IOException {
        long start = System.nanoTime();
        boolean[] sea = new boolean[heights.length];
        for (int i = 0; i < sea.length; i++) {
            sea[i] = heights[i] <= SEA_LEVEL_M;
        }
        FlowNetwork net = FlowNetwork.open(heights, n, n, spacing, spacing, sea);
        DrainageStats s = DrainageStats.of(net, heights, AREA_MIN_M2, AREA_MAX_M2);
        double ms = (System.nanoTime() - start) / 1e6;
        System.out.printf(Locale.ROOT, "drainage of %s: %d² cells %.0f m apart, routed and measured in %.0f ms%n",
                title, n, spacing, ms);
        System.out.printf(Locale.ROOT, "  concavity theta  %.3f  (S ~ A^-theta over %.0e..%.0e m², R² %.2f, %d "
                + "bins)%s%n", s.concavity(), s.areaMin(), s.areaMax(), s.concavityR2(), s.concavityBins(),
                s.fitted() ? "" : ": too few channel bins to fit");
        System.out.printf(Locale.ROOT, "  Hack exponent h  %.3f  (L ~ A^h, R² %.2f)%n", s.hack(), s.hackR2());
        System.out.printf(Locale.ROOT, "  hypsometric integral %.3f%n", s.hypsometric());
        System.out.printf(Locale.ROOT, "  slope percentiles 10/50/90: %.1f / %.1f / %.1f°%n", s.slopeDegrees()[0],
                s.slopeDegrees()[1], s.slopeDegrees()[2]);
        System.out.printf(Locale.ROOT, "  drainage density %.2f km/km² (channels from %.0e m²); pits filled on "
                + "%.1f %% of the cells%n", s.drainageDensity(), s.areaMin(), 100 * s.filledShare());
        BufferedImage picture = picture(net, heights, n, spacing);
        AtomicFiles.write(out.resolve(DRAINAGE_PNG), file -> ImageIO.write(picture, "png", file.toFile()));
        System.out.println("wrote " + out.resolve(DRAINAGE_PNG));
    }

    /** Grey hillshade, light from the north-west, with the channels drawn over it. */
    private static BufferedImage picture(FlowNetwork net, float[] h, int n, double spacing) {
        BufferedImage image = new BufferedImage(n, n, BufferedImage.TYPE_INT_RGB);
        double span = Math.log10(AREA_MAX_M2 / AREA_MIN_M2);
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                double gx = (h[z * n + Math.min(x + 1, n - 1)] - h[z * n + Math.max(x - 1, 0)]) / (2 * spacing);
                double gz = (h[Math.min(z + 1, n - 1) * n + x] - h[Math.max(z - 1, 0) * n + x]) / (2 * spacing);
                // n · l for the light (-0.5, √0.5, -0.5): level ground 0.71
                double lit = Math.max(0, (0.5 * gx + Math.sqrt(0.5) + 0.5 * gz) / Math.sqrt(gx * gx + 1 + gz * gz));
                int grey = (int) Math.min(255, AMBIENT + LIT * lit);
                image.setRGB(x, z, h[z * n + x] <= SEA_LEVEL_M ? SEA : grey << 16 | grey << 8 | grey);
            }
        }
        for (int c = 0; c < n * n; c++) {
            double a = net.area(c);
            if (net.outlet(c) || a < AREA_MIN_M2) {
                continue;
            }
            double t = Math.min(1, Math.log10(a / AREA_MIN_M2) / span);
            int rgb = 0;
            for (int k = 0; k < 3; k++) {
                rgb = rgb << 8 | (int) Math.round(THIN[k] + t * (THICK[k] - THIN[k]));
            }
            int brush = t > 0.5 ? 3 : 2; // the channels two pixels wide, the trunks three
            for (int dz = 0; dz < brush; dz++) {
                for (int dx = 0; dx < brush; dx++) {
                    image.setRGB(Math.min(c % n + dx, n - 1), Math.min(c / n + dz, n - 1), rgb);
                }
            }
        }
        return image;
    }
}
