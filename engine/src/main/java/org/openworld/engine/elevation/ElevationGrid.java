package org.openworld.engine.elevation;

import java.util.Locale;

/**
 * An elevation model as its file holds it: {@code width × height} heights in metres, row by row from the north-west
 * corner, {@code spacingX} metres apart along a row (east) and {@code spacingZ} metres between rows (south). Any side
 * lengths; no-data samples are NaN until {@link #fillNoData} fills them.
 *
 * @param width    samples per row
 * @param height   rows
 * @param spacingX metres between neighbouring samples of a row
 * @param spacingZ metres between neighbouring rows
 * @param heights  {@code width · height} heights, metres; kept, not copied
 * @param latitude degrees north of the map's centre for a geographic model, NaN for a projected or unknown one
 * @param scaled   whether the file gave the spacing and metres (georeference or sidecar): false when the settings'
 *                 spacing stands in and the heights are to be normalised
 */
public record ElevationGrid(int width, int height, double spacingX, double spacingZ, float[] heights,
                            double latitude, boolean scaled) {

    public ElevationGrid {
        if (width < 2 || height < 2 || heights.length != (long) width * height) {
            throw new IllegalArgumentException("an elevation grid needs at least 2×2 samples and width·height of "
                    + "them, got " + width + "×" + height + " and " + heights.length);
        }
        if (!(spacingX > 0 && spacingZ > 0)) {
            throw new IllegalArgumentException("spacings must be positive, got " + spacingX + ", " + spacingZ);
        }
    }

    /** The sample at column x, row z. */
    public float at(int x, int z) {
        return heights[z * width + x];
    }

    /** West to east, metres: from the first sample's centre to the last's. */
    public double extentX() {
        return (width - 1) * spacingX;
    }

    /** North to south, metres. */
    public double extentZ() {
        return (height - 1) * spacingZ;
    }

    /** Lowest and highest height, metres, ignoring no-data. */
    public double[] range() {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (float h : heights) {
            if (!Float.isNaN(h)) {
                lo = Math.min(lo, h);
                hi = Math.max(hi, h);
            }
        }
        return new double[] {lo, hi};
    }

    /**
     * Fills no-data samples (NaN) from their known neighbours: each pass gives every hole touching known ground the
     * mean of its known 4-neighbours, until none is left, so a hole fills from its rim inwards (a lake's flat surface,
     * a radar shadow's gap). Cost: one pass per sample of the widest hole's half width.
     *
     * @return how many samples were filled
     */
    public int fillNoData() {
        int filled = 0;
        int[] holes = holes();
        while (holes.length > 0) {
            float[] next = new float[holes.length];
            int progress = 0;
            for (int i = 0; i < holes.length; i++) {
                next[i] = neighbourMean(holes[i]);
                progress += Float.isNaN(next[i]) ? 0 : 1;
            }
            if (progress == 0) {
                throw new IllegalStateException("every sample is no-data");
            }
            for (int i = 0; i < holes.length; i++) {
                heights[holes[i]] = next[i];
            }
            filled += progress;
            holes = holes();
        }
        return filled;
    }

    private int[] holes() {
        return java.util.stream.IntStream.range(0, heights.length).filter(i -> Float.isNaN(heights[i])).toArray();
    }

    private float neighbourMean(int i) {
        int x = i % width;
        int z = i / width;
        double sum = 0;
        int n = 0;
        int[][] steps = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
        for (int[] s : steps) {
            int nx = x + s[0];
            int nz = z + s[1];
            if (nx >= 0 && nx < width && nz >= 0 && nz < height && !Float.isNaN(heights[nz * width + nx])) {
                sum += heights[nz * width + nx];
                n++;
            }
        }
        return n == 0 ? Float.NaN : (float) (sum / n);
    }

    /** One line: samples, spacing, extent, range, and where on the globe for a geographic model. */
    public String summary() {
        double[] r = range();
        return String.format(Locale.ROOT,
                "%d×%d samples, %.2f × %.2f m apart, %.2f × %.2f km, heights %.1f .. %.1f m%s", width, height, spacingX,
                spacingZ, extentX() / 1000, extentZ() / 1000, r[0], r[1],
                Double.isNaN(latitude) ? "" : String.format(Locale.ROOT, " (geographic, spacing at %.3f° N)",
                        latitude));
    }
}
