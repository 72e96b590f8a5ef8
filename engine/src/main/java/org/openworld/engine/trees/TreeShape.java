package org.openworld.engine.trees;

import java.util.ArrayList;
import java.util.List;

/**
 * One conifer, made in code: a trunk and a stack of three cones, {@link #SIDES} sides each, for a tree 1 unit tall
 * standing on the origin (the shader scales it by each tree's height). Each vertex has a position, a normal and a
 * part ({@link #TRUNK} or {@link #NEEDLES}), {@link #FLOATS} floats in all. Cones get smooth normals round their
 * sides (a low-poly outline, lit as round) and a flat underside, which the reflection and a viewer under a branch
 * see. 48 triangles.
 */
final class TreeShape {

    /** Sides of the trunk and of each cone: six reads as round from a few metres away. */
    static final int SIDES = 6;
    static final int FLOATS = 7;
    static final float TRUNK = 0;
    static final float NEEDLES = 1;
    /** The trunk goes this far (a share of the height) into the ground, so a tree on a slope does not float. */
    static final float SINK = 0.04f;
    static final float TRUNK_RADIUS = 0.03f;
    static final float TRUNK_TOP = 0.3f;
    /**
     * The cones, bottom up: base height, tip height and base radius, shares of the tree's height. They overlap, as a
     * spruce's whorls do, and narrow upwards: the tree is half as wide as it is tall at its widest.
     */
    static final float[][] CONES = {{0.12f, 0.62f, 0.25f}, {0.36f, 0.84f, 0.19f}, {0.58f, 1.0f, 0.12f}};

    private TreeShape() {
    }

    /** Interleaved vertices (position, normal, part) and triangles, counter-clockwise from outside. */
    record Geometry(float[] vertices, int[] triangles) {
    }

    static Geometry coneStack() {
        List<float[]> v = new ArrayList<>();
        List<Integer> t = new ArrayList<>();
        for (int i = 0; i < SIDES; i++) {
            double a0 = angle(i);
            double a1 = angle(i + 1);
            int base = v.size();
            v.add(vertex(TRUNK_RADIUS, a0, -SINK, Math.cos(a0), 0, Math.sin(a0), TRUNK));
            v.add(vertex(TRUNK_RADIUS, a1, -SINK, Math.cos(a1), 0, Math.sin(a1), TRUNK));
            v.add(vertex(TRUNK_RADIUS, a1, TRUNK_TOP, Math.cos(a1), 0, Math.sin(a1), TRUNK));
            v.add(vertex(TRUNK_RADIUS, a0, TRUNK_TOP, Math.cos(a0), 0, Math.sin(a0), TRUNK));
            quad(t, base);
        }
        for (float[] cone : CONES) {
            addCone(v, t, cone[0], cone[1], cone[2]);
        }
        float[] vertices = new float[v.size() * FLOATS];
        for (int i = 0; i < v.size(); i++) {
            System.arraycopy(v.get(i), 0, vertices, i * FLOATS, FLOATS);
        }
        return new Geometry(vertices, t.stream().mapToInt(Integer::intValue).toArray());
    }

    /**
     * A cone's sides and its flat underside. A side's normal leans out by the cone's slope: for base radius r and
     * height h, (h cos a, r, h sin a) normalised, perpendicular to the slanted side at angle a.
     */
    private static void addCone(List<float[]> v, List<Integer> t, float bottom, float top, float radius) {
        float h = top - bottom;
        for (int i = 0; i < SIDES; i++) {
            double a0 = angle(i);
            double a1 = angle(i + 1);
            double mid = 0.5 * (a0 + a1);
            int side = v.size();
            v.add(vertex(radius, a0, bottom, h * Math.cos(a0), radius, h * Math.sin(a0), NEEDLES));
            v.add(vertex(0, 0, top, h * Math.cos(mid), radius, h * Math.sin(mid), NEEDLES));
            v.add(vertex(radius, a1, bottom, h * Math.cos(a1), radius, h * Math.sin(a1), NEEDLES));
            t.addAll(List.of(side, side + 1, side + 2));
            int under = v.size();
            v.add(vertex(radius, a0, bottom, 0, -1, 0, NEEDLES));
            v.add(vertex(radius, a1, bottom, 0, -1, 0, NEEDLES));
            v.add(vertex(0, 0, bottom, 0, -1, 0, NEEDLES));
            t.addAll(List.of(under, under + 1, under + 2));
        }
    }

    /** Angle of side i, radians, turning from +X towards +Z. */
    private static double angle(int i) {
        return 2 * Math.PI * i / SIDES;
    }

    private static void quad(List<Integer> t, int first) {
        t.addAll(List.of(first, first + 3, first + 2, first, first + 2, first + 1));
    }

    private static float[] vertex(double radius, double angle, double y, double nx, double ny, double nz, float part) {
        double n = Math.sqrt(nx * nx + ny * ny + nz * nz);
        return new float[] {(float) (radius * Math.cos(angle)), (float) y, (float) (radius * Math.sin(angle)),
            (float) (nx / n), (float) (ny / n), (float) (nz / n), part};
    }
}
