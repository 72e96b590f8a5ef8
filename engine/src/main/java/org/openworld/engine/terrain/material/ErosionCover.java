package org.openworld.engine.terrain.material;

import org.openworld.engine.terrain.heights.HeightMap;

/**
 * What the hydraulic erosion left, as the materials read it: per texel of the snow map's grid, how much of the ground
 * its sediment covers and how much bed it bared, from the change it made ({@code TerrainData.sediment}, the
 * {@code org.openworld.engine.erosion.hydraulic} package). The snow texture carries them in b and a
 * ({@link TerrainMaps}); the material shows sediment on gentle ground as alluvium and on steep ground as scree (the
 * talus's foot), the bared bed as rock, and lets snow gather on the sediment and slide off the bared faces
 * ({@code shaders/terrain/material/material.glsl}, step 2).
 *
 * <p>Both are smoothsteps of the change in metres: a layer thinner than {@value #THIN_M} m lets the ground below show
 * (the 8 m grid's smoothing spreads a few centimetres over every slope), one of {@value #FULL_M} m or more covers it.
 * The bed bared uses the same thresholds: the slopes' sheet wash takes off 0.3–0.5 m everywhere, so only the flow
 * paths and the faces the talus slide cut back (metres to tens of metres) read as bare rock.
 */
public final class ErosionCover {

    /** Metres of change below which nothing shows. */
    static final double THIN_M = 0.5;
    /** Metres of change from which the cover is full. */
    static final double FULL_M = 3;

    private ErosionCover() {
    }

    /**
     * The cover on an {@code n²} grid of the change's extent ({@code n} a power-of-two multiple of its size, or equal):
     * b the sediment's cover, a 255 − the bared bed's, each 0..255; with no change (null) b = 0 and a = 255, as the
     * unbounded world's snow texture (two channels) reads.
     */
    public static byte[][] of(HeightMap change, int n) {
        byte[] sediment = new byte[n * n];
        byte[] kept = new byte[n * n];
        double step = change == null ? 0 : (double) change.size() / n;
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                double c = 0;
                if (change != null) {
                    double gx = x * step;
                    double gz = z * step;
                    int x0 = (int) Math.floor(gx);
                    int z0 = (int) Math.floor(gz);
                    double fx = gx - x0;
                    double fz = gz - z0;
                    c = (change.sample(x0, z0) * (1 - fx) + change.sample(x0 + 1, z0) * fx) * (1 - fz)
                            + (change.sample(x0, z0 + 1) * (1 - fx) + change.sample(x0 + 1, z0 + 1) * fx) * fz;
                }
                sediment[z * n + x] = (byte) Math.round(255 * smoothstep(c));
                kept[z * n + x] = (byte) Math.round(255 * (1 - smoothstep(-c)));
            }
        }
        return new byte[][] {sediment, kept};
    }

    private static double smoothstep(double metres) {
        double t = Math.max(0, Math.min(1, (metres - THIN_M) / (FULL_M - THIN_M)));
        return t * t * (3 - 2 * t);
    }
}
