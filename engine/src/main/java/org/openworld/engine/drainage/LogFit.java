package org.openworld.engine.drainage;

import java.util.function.IntToDoubleFunction;

/**
 * A straight line through log₁₀ y against log₁₀ x, fitted to binned means: the cells whose x lies in
 * {@code [xMin, xMax]} are put in bins a tenth of a decade wide, each bin gives the means of log₁₀ x and log₁₀ y of
 * its cells (their geometric means), and the line is the least-squares fit through those points, each bin
 * weighing the same. So the many small cells do not outweigh the few large ones, as in the slope–area plots of
 * the literature (Tucker and Whipple 2002; TopoToolbox's {@code slopearea}).
 *
 * @param slope     the fitted exponent: y ∝ x^slope
 * @param intercept log₁₀ y at x = 1
 * @param r2        the share of the bins' variance the line explains (1 on a perfect line)
 * @param bins      the bins that held a cell
 */
public record LogFit(double slope, double intercept, double r2, int bins) {

    /** Bins per decade of x. */
    static final int BINS_PER_DECADE = 10;

    /**
     * Fits the cells {@code 0 .. cells − 1} whose x lies in {@code [xMin, xMax]} and whose y is positive.
     *
     * @param x the abscissa of each cell
     * @param y the ordinate of each cell; cells where it is not positive are left out (no logarithm)
     */
    static LogFit of(int cells, IntToDoubleFunction x, IntToDoubleFunction y, double xMin, double xMax) {
        double lo = Math.log10(xMin);
        int count = Math.max(1, (int) Math.ceil((Math.log10(xMax) - lo) * BINS_PER_DECADE - 1e-9));
        double[] sumX = new double[count];
        double[] sum = new double[count];
        int[] n = new int[count];
        for (int c = 0; c < cells; c++) {
            double xc = x.applyAsDouble(c);
            double yc = y.applyAsDouble(c);
            if (xc < xMin || xc > xMax || !(yc > 0)) {
                continue;
            }
            int b = Math.min(count - 1, (int) ((Math.log10(xc) - lo) * BINS_PER_DECADE));
            sumX[b] += Math.log10(xc);
            sum[b] += Math.log10(yc);
            n[b]++;
        }
        double sx = 0;
        double sy = 0;
        double sxx = 0;
        double sxy = 0;
        double syy = 0;
        int m = 0;
        for (int b = 0; b < count; b++) {
            if (n[b] == 0) {
                continue;
            }
            double bx = sumX[b] / n[b];
            double by = sum[b] / n[b];
            sx += bx;
            sy += by;
            sxx += bx * bx;
            sxy += bx * by;
            syy += by * by;
            m++;
        }
        double vx = sxx - sx * sx / m;
        double vy = syy - sy * sy / m;
        double cxy = sxy - sx * sy / m;
        double slope = m < 2 ? Double.NaN : cxy / vx;
        double r2 = vy > 0 ? cxy * cxy / (vx * vy) : 1;
        return new LogFit(slope, m == 0 ? Double.NaN : (sy - slope * sx) / m, r2, m);
    }
}
