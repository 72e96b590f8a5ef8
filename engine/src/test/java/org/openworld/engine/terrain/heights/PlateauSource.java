package org.openworld.engine.terrain.heights;

/**
 * A flat-topped mountain: {@code top} metres high within {@code radius} of the origin, falling to 0 over a rim
 * {@code rim} metres wide by a smoothstep, flat beyond. Every level is the same function sampled at its own spacing:
 * it has no detail finer than the rim, which is wider than the coarsest spacing the terrain draws it at.
 */
public final class PlateauSource implements HeightSource {

    private final double spacing;
    private final int levels;
    private final double top;
    private final double radius;
    private final double rim;

    public PlateauSource(double spacing, int levels, double top, double radius, double rim) {
        this.spacing = spacing;
        this.levels = levels;
        this.top = top;
        this.radius = radius;
        this.rim = rim;
    }

    @Override
    public int levels() {
        return levels;
    }

    @Override
    public double spacing(int level) {
        return Math.scalb(spacing, level);
    }

    @Override
    public double height(int level, double x, double z) {
        double t = Math.min(1, Math.max(0, (Math.hypot(x, z) - radius) / rim)); // 0 on the top, 1 off the rim
        return top * (1 - t * t * (3 - 2 * t));
    }

    @Override
    public double lowest() {
        return 0;
    }

    @Override
    public double highest() {
        return top;
    }
}
