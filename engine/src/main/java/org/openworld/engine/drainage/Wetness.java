package org.openworld.engine.drainage;

import java.util.function.DoubleBinaryOperator;

/**
 * Where water gathers on the ground: a world resource, published by the terrain on the tile and on the eroded
 * unbounded world (read it with {@code world.findResource(Wetness.class)}; absent on the plain unbounded world,
 * which routes no rivers). For each place, the drainage area A that reaches it and the topographic wetness index
 * (Beven and Kirkby 1979)
 * <pre>
 *   TWI = ln(a / tan β),    a = A / w  (the catchment per metre of contour, w the cell's width)
 * </pre>
 * with β the slope to the receiver (at least {@link #MIN_SLOPE}, so flats stay finite), mapped to a wetness of 0 on
 * steep divides (TWI ≤ {@link #TWI_DRY}) to 1 on valley floors and river beds (TWI ≥ {@link #TWI_WET}): what grows
 * there, how dark the soil is. Made from the heights routed on an 8 m level ({@link FlowNetwork}); read nearest
 * cell, wrapping like the tile. Cost: 0.5–0.8 s at start for a 512² level (the terrain's {@code wetness} stage,
 * shared two-core machine), 2 MiB.
 */
public final class Wetness {

    /** TWI of a steep divide: 8 m of catchment per metre on a 45° slope gives ln 8 ≈ 2; drier still is 0. */
    static final double TWI_DRY = 2;
    /** TWI of a wet valley floor: 10⁵ m² on 8 m cells (a small stream) at 2 % gives ln(12500 / 0.02) ≈ 13.3. */
    static final double TWI_WET = 13;
    /** Gentlest slope counted, m/m: a filled lake's ε is no slope, and the index would be infinite. */
    static final double MIN_SLOPE = 1e-3;

    private final DoubleBinaryOperator area;
    private final DoubleBinaryOperator wetness;

    private Wetness(DoubleBinaryOperator area, DoubleBinaryOperator wetness) {
        this.area = area;
        this.wetness = wetness;
    }

    /**
     * The wetness of a ground whose drainage area and wetness at each place (x, z) other code knows (the eroded
     * unbounded world's, read from the regions its blocks are made of).
     */
    public static Wetness of(DoubleBinaryOperator area, DoubleBinaryOperator wetness) {
        return new Wetness(area, wetness);
    }

    /**
     * The wetness of a cell {@code width} metres wide that drains {@code area} m² and falls {@code slope} m/m to
     * its receiver: the wetness index mapped from {@link #TWI_DRY} (0) to {@link #TWI_WET} (1).
     */
    public static double index(double area, double width, double slope) {
        double twi = Math.log(area / width / Math.max(MIN_SLOPE, slope));
        return Math.max(0, Math.min(1, (twi - TWI_DRY) / (TWI_WET - TWI_DRY)));
    }

    /**
     * The wetness of a square periodic tile of {@code size²} heights {@code spacing} apart, centred on the origin,
     * whose sea (heights at or below 0 m) takes the rivers.
     */
    public static Wetness ofTile(float[] heights, int size, double spacing) {
        boolean[] sea = new boolean[heights.length];
        for (int i = 0; i < sea.length; i++) {
            sea[i] = heights[i] <= 0;
        }
        FlowNetwork net = FlowNetwork.periodic(heights, size, size, spacing, spacing, sea);
        float[] area = new float[heights.length];
        float[] wet = new float[heights.length];
        for (int c = 0; c < heights.length; c++) {
            area[c] = (float) net.area(c);
            wet[c] = net.outlet(c) ? 1 : (float) index(net.area(c), spacing, net.slope(c));
        }
        return new Wetness((x, z) -> area[cell(x, z, size, spacing)], (x, z) -> wet[cell(x, z, size, spacing)]);
    }

    /** Drainage area reaching world position (x, z), m². */
    public double drainageArea(double x, double z) {
        return area.applyAsDouble(x, z);
    }

    /** Wetness at world position (x, z): 0 on dry divides, 1 in valley floors, rivers and the sea. */
    public double wetness(double x, double z) {
        return wetness.applyAsDouble(x, z);
    }

    /** The tile's cell under (x, z), wrapping. */
    private static int cell(double x, double z, int size, double spacing) {
        int gx = Math.floorMod((int) Math.floor(x / spacing + size / 2.0), size);
        int gz = Math.floorMod((int) Math.floor(z / spacing + size / 2.0), size);
        return gz * size + gx;
    }
}
