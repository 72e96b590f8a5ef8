package org.openworld.engine.drainage;

import java.util.Arrays;

/**
 * The measures of a landscape that water shaped, from its {@link FlowNetwork} (formulas and references in the
 * package comment).
 *
 * @param concavity        θ of Flint's law S ∝ A^−θ, fitted over the channels ({@code areaMin ≤ A ≤ areaMax})
 * @param concavityR2      how well the slope–area line fits its bins (R²)
 * @param concavityBins    the area bins of a tenth of a decade that held a channel cell
 * @param hack             h of Hack's law L ∝ A^h, L the longest flow path to a cell, over the same channels (the
 *                         outlets, where rivers meet the sea, left out)
 * @param hackR2           how well the length–area line fits its bins (R²)
 * @param areaMin          lower end of the fit range, m²: also the channel threshold for the drainage density
 * @param areaMax          upper end of the fit range, m²
 * @param hypsometric      hypsometric integral (mean − min) / (max − min) of the heights (Strahler 1952)
 * @param slopeDegrees     the 10th, 50th and 90th percentiles of the slope by central differences, degrees
 * @param drainageDensity  length of the channels (cells draining at least {@code areaMin}) per area, km per km²
 * @param filledShare      share of the cells the pit filling raised
 */
public record DrainageStats(double concavity, double concavityR2, int concavityBins, double hack, double hackR2,
        double areaMin, double areaMax, double hypsometric, double[] slopeDegrees, double drainageDensity,
        double filledShare) {

    /** The percentiles of {@link #slopeDegrees}. */
    public static final double[] SLOPE_PERCENTILES = {10, 50, 90};
    private static final double M2_PER_KM2 = 1e6;
    private static final double M_PER_KM = 1e3;

    /**
     * Measures the network and the heights it was made from.
     *
     * @param heights the heights the network was made from (not filled), row-major
     * @param areaMin lower end of the fit range and channel threshold, m²
     * @param areaMax upper end of the fit range, m²
     */
    public static DrainageStats of(FlowNetwork net, float[] heights, double areaMin, double areaMax) {
        if (!(areaMin > 0 && areaMax > areaMin)) {
            throw new IllegalArgumentException("the fit range must be 0 < min < max, got " + areaMin + " .. "
                    + areaMax + " m²");
        }
        int cells = heights.length;
        // a raised cell's slope is the fill's ε, not the land's: it is left out of the slope–area fit
        LogFit sa = LogFit.of(cells, net::area, c -> net.raised(c) ? 0 : net.slope(c), areaMin, areaMax);
        LogFit hl = LogFit.of(cells, net::area, c -> net.outlet(c) ? 0 : net.length(c), areaMin, areaMax);

        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        double sum = 0;
        int raised = 0;
        double channels = 0;
        for (int c = 0; c < cells; c++) {
            min = Math.min(min, heights[c]);
            max = Math.max(max, heights[c]);
            sum += heights[c];
            raised += net.raised(c) ? 1 : 0;
            int r = net.receiver(c);
            if (r != FlowNetwork.OUTLET && net.area(c) >= areaMin) {
                channels += net.distance(c, r);
            }
        }
        double hi = max > min ? (sum / cells - min) / (max - min) : Double.NaN;
        double landKm2 = cells * net.dx() * net.dz() / M2_PER_KM2;
        return new DrainageStats(-sa.slope(), sa.r2(), sa.bins(), hl.slope(), hl.r2(), areaMin, areaMax, hi,
                slopePercentiles(heights, net), channels / M_PER_KM / landKm2, raised / (double) cells);
    }

    /** Whether the slope–area fit rests on enough bins (three) to give a concavity. */
    public boolean fitted() {
        return concavityBins >= 3 && Double.isFinite(concavity);
    }

    /** Slope by central differences at every interior cell, degrees, at {@link #SLOPE_PERCENTILES}. */
    private static double[] slopePercentiles(float[] h, FlowNetwork net) {
        int w = net.width();
        int d = net.depth();
        double[] slopes = new double[(w - 2) * (d - 2)];
        int k = 0;
        for (int z = 1; z < d - 1; z++) {
            for (int x = 1; x < w - 1; x++) {
                double gx = (h[z * w + x + 1] - h[z * w + x - 1]) / (2 * net.dx());
                double gz = (h[(z + 1) * w + x] - h[(z - 1) * w + x]) / (2 * net.dz());
                slopes[k++] = Math.toDegrees(Math.atan(Math.hypot(gx, gz)));
            }
        }
        Arrays.sort(slopes);
        return Arrays.stream(SLOPE_PERCENTILES)
                .map(p -> slopes[(int) Math.min(slopes.length - 1, Math.round(p / 100 * (slopes.length - 1)))])
                .toArray();
    }
}
