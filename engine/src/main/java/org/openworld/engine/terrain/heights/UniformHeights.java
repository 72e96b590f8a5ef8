package org.openworld.engine.terrain.heights;

/**
 * Heights of a world statistically the same everywhere, the unbounded world's ({@link BandedHeights}, plain or
 * eroded): one error figure per level stands for every node of that level, since no node of a world without end
 * can be measured in full.
 */
public interface UniformHeights extends HeightSource {

    /**
     * How far the surface drawn from each level's samples lies from the finest heights, metres, for levels
     * 0 .. count − 1 (0 for level 0): an estimate measured at sample places, not a bound.
     *
     * @param count 1 .. {@link #levels()}
     */
    float[] levelErrors(int count);

    /**
     * The surface a patch of this level draws at (x, z), metres: its samples joined by triangles, each cell cut along
     * its (−,−) to (+,+) diagonal as {@link org.openworld.engine.terrain.mesh.PatchPatterns} cuts them.
     */
    default double surface(int level, double x, double z) {
        double d = spacing(level);
        double fx = Math.floor(x / d);
        double fz = Math.floor(z / d);
        double tx = x / d - fx;
        double tz = z / d - fz;
        double h00 = height(level, fx * d, fz * d);
        double h11 = height(level, (fx + 1) * d, (fz + 1) * d);
        if (tx >= tz) { // the triangle (0,0) (1,0) (1,1)
            double h10 = height(level, (fx + 1) * d, fz * d);
            return h00 + tx * (h10 - h00) + tz * (h11 - h10);
        }
        double h01 = height(level, fx * d, (fz + 1) * d); // the triangle (0,0) (0,1) (1,1)
        return h00 + tz * (h01 - h00) + tx * (h11 - h01);
    }
}
