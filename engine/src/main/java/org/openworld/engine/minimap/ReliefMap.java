package org.openworld.engine.minimap;

import org.openworld.engine.core.HeightField;

/**
 * The minimap's picture of the ground: a square around a centre, sampled from the world's {@link HeightField} on a
 * grid of {@link #TEXELS}² points, shaded under a fixed light (a hillshade) and coloured, as RGBA bytes in display
 * (sRGB) values for an RGBA8 texture. Row 0 is the north edge, column 0 the west edge, as GL's texture coordinates
 * s (east) and t (south) run.
 *
 * <p>The square is {@link #SPAN_PER_RANGE} times the range shown: the range, plus the distance the camera may move
 * off the centre before the map is built again ({@link #REBUILD_SHARE} of the range) on each side, so the shown
 * part never leaves the texture. The centre is snapped to the grid, so a map built again samples the same points
 * where the two overlap and the picture does not swim.
 */
final class ReliefMap {

    /** Samples a side: 341 across the default 4 km shown, about one a pixel for the default 324 px map at 1080p. */
    static final int TEXELS = 512;
    /** The camera may move this share of the range off the centre before the map is built again. */
    static final double REBUILD_SHARE = 0.25;
    /** The map's side over the range shown: the range plus {@link #REBUILD_SHARE} of it on either side. */
    static final double SPAN_PER_RANGE = 1 + 2 * REBUILD_SHARE;
    /**
     * The light, degrees: from the north-west (azimuth 315°, clockwise from north), 45° above the horizon. The
     * cartographers' choice: lit from the top of the map, hills read as hills and not as hollows.
     */
    static final double LIGHT_AZIMUTH = 315;
    static final double LIGHT_ALTITUDE = 45;
    /** The share of the light that reaches slopes turned away from the sun (sky light), so they keep a colour. */
    static final double AMBIENT = 0.3;
    /** Land, display RGB 0–1: a pale sand, on which the shading reads as on paper. */
    static final double[] LAND = {0.93, 0.89, 0.80};
    /** Water, display RGB 0–1: a flat mid blue, unshaded, so shorelines stand out. */
    static final double[] WATER = {0.29, 0.51, 0.78};

    /** Unit vector towards the light: x east, y up, z south. */
    private static final double[] LIGHT = {
        Math.cos(Math.toRadians(LIGHT_ALTITUDE)) * Math.sin(Math.toRadians(LIGHT_AZIMUTH)),
        Math.sin(Math.toRadians(LIGHT_ALTITUDE)),
        -Math.cos(Math.toRadians(LIGHT_ALTITUDE)) * Math.cos(Math.toRadians(LIGHT_AZIMUTH))};

    private final HeightField field;
    private final double centreX;
    private final double centreZ;
    private final double range;
    private final double waterLevel;
    private final double spacing;
    private final byte[] rgba;

    private ReliefMap(HeightField field, double centreX, double centreZ, double range, double waterLevel,
                      double spacing, byte[] rgba) {
        this.field = field;
        this.centreX = centreX;
        this.centreZ = centreZ;
        this.range = range;
        this.waterLevel = waterLevel;
        this.spacing = spacing;
        this.rgba = rgba;
    }

    /**
     * Samples, shades and colours the map around (x, z).
     *
     * @param range      metres shown across the minimap
     * @param waterLevel height of the water plane, metres; ground below it is drawn as water ({@code -∞}: none)
     */
    static ReliefMap build(HeightField field, double x, double z, double range, double waterLevel) {
        double spacing = SPAN_PER_RANGE * range / TEXELS;
        double centreX = Math.round(x / spacing) * spacing;
        double centreZ = Math.round(z / spacing) * spacing;
        // 1. heights at the texel centres, with one more sample all round for the slopes at the edges
        int n = TEXELS + 2;
        double west = centreX - (TEXELS / 2 + 0.5) * spacing;
        double north = centreZ - (TEXELS / 2 + 0.5) * spacing;
        double[] h = new double[n * n];
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                h[j * n + i] = field.heightAt(west + i * spacing, north + j * spacing);
            }
        }
        // 2. each texel: water below the level, else the land colour under the hillshade of its central differences
        byte[] rgba = new byte[TEXELS * TEXELS * 4];
        for (int j = 0; j < TEXELS; j++) {
            for (int i = 0; i < TEXELS; i++) {
                int c = (j + 1) * n + i + 1;
                double[] color = WATER;
                double light = 1;
                if (h[c] >= waterLevel) {
                    double dhdx = (h[c + 1] - h[c - 1]) / (2 * spacing);
                    double dhdz = (h[c + n] - h[c - n]) / (2 * spacing);
                    color = LAND;
                    light = AMBIENT + (1 - AMBIENT) * hillshade(dhdx, dhdz);
                }
                int at = (j * TEXELS + i) * 4;
                for (int k = 0; k < 3; k++) {
                    rgba[at + k] = (byte) Math.round(255 * color[k] * light);
                }
                rgba[at + 3] = (byte) 255;
            }
        }
        return new ReliefMap(field, centreX, centreZ, range, waterLevel, spacing, rgba);
    }

    /**
     * The hillshade of a slope: the cosine between the ground's normal and the direction to the light, 0 for a
     * slope turned away. The normal of a height field h(x, z) is (−∂h/∂x, 1, −∂h/∂z), normalised; flat ground gets
     * sin(45°) ≈ 0.71.
     *
     * @param dhdx the ground's rise per metre eastwards
     * @param dhdz the ground's rise per metre southwards
     */
    static double hillshade(double dhdx, double dhdz) {
        double length = Math.sqrt(dhdx * dhdx + 1 + dhdz * dhdz);
        return Math.max(0, (-dhdx * LIGHT[0] + LIGHT[1] - dhdz * LIGHT[2]) / length);
    }

    /**
     * Whether this map still serves a camera at (x, z): it was built from the same field, range and water level,
     * and the camera is at most {@link #REBUILD_SHARE} of the range east, west, north or south of its centre, so
     * the range around the camera lies on it.
     */
    boolean covers(HeightField field, double x, double z, double range, double waterLevel) {
        double reach = REBUILD_SHARE * range;
        return field == this.field && range == this.range && waterLevel == this.waterLevel
                && Math.abs(x - centreX) <= reach && Math.abs(z - centreZ) <= reach;
    }

    /** Texture coordinate s (0 the west edge, 1 the east edge) of a world x, metres. */
    double s(double x) {
        return 0.5 + (x - centreX) / (TEXELS * spacing);
    }

    /** Texture coordinate t (0 the north edge, 1 the south edge) of a world z, metres. */
    double t(double z) {
        return 0.5 + (z - centreZ) / (TEXELS * spacing);
    }

    /** The range shown over the map's whole side: the step in s or t from one edge of the minimap to the other. */
    double shownShare() {
        return range / (TEXELS * spacing);
    }

    /** The texels, row by row from the north edge, 4 bytes each; the array itself, for the upload. */
    byte[] rgba() {
        return rgba;
    }

    /** Channel c (0 r, 1 g, 2 b) of the texel in column i (from the west) and row j (from the north), 0–255. */
    int channel(int i, int j, int c) {
        return rgba[(j * TEXELS + i) * 4 + c] & 0xFF;
    }
}
