package org.openworld.engine.erosion;

import org.openworld.engine.drainage.FlowNetwork;

/**
 * The steady state of the stream-power law with uplift on a flow network: where uplift U and fluvial incision
 * {@code K A^m S^n} balance, {@code S = (U / K)^{1/n} A^{−m/n}}, Flint's law with θ = m/n. With n = 1 the heights
 * follow from the outlets up in one pass over the network (Braun and Willett 2013's ordering, taken to its limit of
 * an infinite time step): each cell lies {@code k_s · A^−θ · d} above its receiver, d metres away, the channel
 * steepness {@code k_s = U / K} its own. Hillslopes, where the area is small and the law would make walls, are held
 * at the threshold slope (Cordonnier et al. 2016 do the same), which is thermal erosion's talus limit.
 */
public final class StreamPower {

    private StreamPower() {
    }

    /**
     * Heights in equilibrium on the network: outlets keep their heights, every other cell lies
     * {@code min(k_s A^−θ, maxSlope) · d} above its receiver.
     *
     * @param steepness channel steepness k_s of each cell, m^(2θ) (U/K with n = 1)
     * @param heights   the heights the outlets keep, row-major
     * @param theta     concavity m/n
     * @param maxSlope  the threshold hillslope gradient, m/m
     */
    public static float[] equilibrium(FlowNetwork net, float[] heights, float[] steepness, double theta,
            double maxSlope) {
        return equilibrium(net, heights, steepness, new float[heights.length], theta, maxSlope);
    }

    /**
     * As {@link #equilibrium(FlowNetwork, float[], float[], double, double)}, each cell's drainage area at least
     * {@code inflow}: the area of a river routed on a coarser grid that the network's own cells do not reach.
     *
     * @param inflow drainage area of each cell from beyond the network, m² (0 where none)
     */
    public static float[] equilibrium(FlowNetwork net, float[] heights, float[] steepness, float[] inflow,
            double theta, double maxSlope) {
        int[] order = net.order();
        float[] z = new float[heights.length];
        for (int k = order.length - 1; k >= 0; k--) { // receivers first
            int c = order[k];
            int r = net.receiver(c);
            if (r == FlowNetwork.OUTLET) {
                z[c] = heights[c];
                continue;
            }
            double slope = Math.min(steepness[c] * Math.pow(Math.max(net.area(c), inflow[c]), -theta), maxSlope);
            z[c] = (float) (z[r] + slope * net.distance(c, r));
        }
        return z;
    }
}
