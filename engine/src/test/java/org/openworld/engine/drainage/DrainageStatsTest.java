package org.openworld.engine.drainage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.SplittableRandom;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.openworld.engine.erosion.StreamPower;

class DrainageStatsTest {

    /**
     * A surface built to Flint's law with θ = 0.5: the flow network of a random surface, then heights rebuilt from
     * the outlets up, each cell {@code k · A^−0.5} per metre above its receiver. Routed again, the network can
     * differ where a diagonal and a side neighbour fall almost alike, so the measured θ is held within 0.05 (the
     * issue's tolerance), not exactly.
     */
    @Test
    void surfaceBuiltToFlintsLawGivesItsConcavity() {
        int n = 256;
        double dx = 10;
        float[] noise = new float[n * n];
        SplittableRandom random = new SplittableRandom(7);
        for (int c = 0; c < noise.length; c++) {
            noise[c] = (float) random.nextDouble();
        }
        FlowNetwork first = FlowNetwork.open(noise, n, n, dx, dx);
        float[] steepness = new float[n * n];
        java.util.Arrays.fill(steepness, 50); // k_s: a slope of 0.5 where A = 10^4 m², far below any hillslope cap
        float[] h = StreamPower.equilibrium(first, noise, steepness, 0.5, Double.POSITIVE_INFINITY);
        FlowNetwork net = FlowNetwork.open(h, n, n, dx, dx);
        // channels from 100 cells to a hundredth of the grid: a decade and a half of areas, 15 bins
        DrainageStats stats = DrainageStats.of(net, h, 100 * dx * dx, n * n * dx * dx / 100);
        assertTrue(stats.fitted());
        // built with θ = 0.5 exactly; ± 0.05 for the log-log regression over 15 bins of a D8 network on a grid (the D8
        // slopes are quantised to cell steps)
        assertEquals(0.5, stats.concavity(), 0.05);
    }

    /**
     * The real DEM: 3-arc-second elevations of the Jacksboro fault, Tennessee (a ridge-and-valley region of the
     * Appalachians: 344 × 403 cells, 36.45–36.73° N, 84.08–84.41° W; US Geological Survey data, public domain, as
     * shipped in matplotlib's sample data). A cell is 3″ of latitude, 92.6 m, by 3″ of longitude at 36.6° N,
     * 74.3 m. Real landscapes have θ of 0.35–0.6 in their channels (Whipple 2004; Tucker and Whipple 2002 quote
     * 0.3–0.7) and Hack's h of 0.5–0.6 (Hack 1957; Rigon et al. 1996: 0.57 ± 0.03); the test holds the DEM within
     * the wider quoted ranges, a check that the measure reads a real landscape as one.
     */
    @Test
    void realDemReadsAsALandscapeShapedByWater() throws IOException {
        Dem dem = jacksboro();
        FlowNetwork net = FlowNetwork.open(dem.heights, dem.width, dem.depth, dem.dx, dem.dz);
        DrainageStats stats = DrainageStats.of(net, dem.heights, 1e5, 1e7);
        System.out.printf("Jacksboro fault DEM: theta %.3f (R2 %.2f, %d bins), Hack %.3f (R2 %.2f), HI %.3f, "
                        + "slopes %.1f/%.1f/%.1f deg, density %.2f km/km2, filled %.3f%n", stats.concavity(),
                stats.concavityR2(), stats.concavityBins(), stats.hack(), stats.hackR2(), stats.hypsometric(),
                stats.slopeDegrees()[0], stats.slopeDegrees()[1], stats.slopeDegrees()[2], stats.drainageDensity(),
                stats.filledShare());
        // the literature's ranges quoted above: θ 0.3–0.7 (Tucker and Whipple), Hack's h widened a little from 0.5–0.6
        assertTrue(stats.concavity() > 0.3 && stats.concavity() < 0.7, "theta " + stats.concavity());
        assertTrue(stats.hack() > 0.45 && stats.hack() < 0.7, "Hack " + stats.hack());
    }

    /** A DEM: heights row-major, cell sizes in metres. */
    record Dem(float[] heights, int width, int depth, double dx, double dz) {
    }

    /** Reads the test resource, a gzipped NumPy {@code .npy} of little-endian 16-bit heights in metres. */
    static Dem jacksboro() throws IOException {
        try (InputStream raw = DrainageStatsTest.class.getResourceAsStream("/drainage/jacksboro_fault_dem.npy.gz");
                DataInputStream in = new DataInputStream(new GZIPInputStream(raw))) {
            byte[] magic = new byte[8];
            in.readFully(magic);
            int headerLength = Short.toUnsignedInt(Short.reverseBytes(in.readShort()));
            byte[] header = new byte[headerLength];
            in.readFully(header);
            String text = new String(header, StandardCharsets.US_ASCII);
            assertTrue(text.contains("'<i2'") && text.contains("(344, 403)"), text);
            int depth = 344;
            int width = 403;
            byte[] data = in.readAllBytes();
            ByteBuffer buffer = ByteBuffer.wrap(data).order(ByteOrder.LITTLE_ENDIAN);
            float[] h = new float[width * depth];
            for (int i = 0; i < h.length; i++) {
                h[i] = buffer.getShort();
            }
            double arcSecond = 6_371_000 * Math.PI / 180 / 3600; // metres of a great circle's arc second
            double latitude = Math.toRadians((36.73291666666667 + 36.44625) / 2);
            return new Dem(h, width, depth, 3 * arcSecond * Math.cos(latitude), 3 * arcSecond);
        }
    }
}
