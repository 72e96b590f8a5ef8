package org.openworld.engine.vegetation;

import java.util.ArrayList;
import java.util.List;

/**
 * The plants' shapes, made in code: for each {@link TreeKind} a full shape for the near plants and a simplified one
 * for those beyond {@code vegetation.lod-distance}, each 1 unit tall standing on the origin (the shader scales it by
 * the plant's height). Each vertex has a position, a normal and a part ({@link #TRUNK} or {@link #FOLIAGE}),
 * {@link #FLOATS} floats in all, triangles counter-clockwise seen from outside.
 *
 * <ul>
 *   <li>Conifer: a six-sided trunk under five stacked cones of eight sides with ragged rims (92 triangles); far, one
 *       five-sided cone over a three-sided trunk (16).</li>
 *   <li>Broadleaf: a trunk under four overlapping lumpy spheres of leaves (268); far, one sphere of 6 × 4 facets and
 *       the trunk (42).</li>
 *   <li>Bush: two lumpy spheres on the ground (128); far, one of 5 × 3 facets (20).</li>
 * </ul>
 * A cone's sides and a sphere are lit as round (smooth normals) and their silhouettes stay low-poly; the lumps (a
 * hashed ±{@link #LUMP} of the radius per vertex) break the spheres' regular outline.
 */
final class TreeShape {

    static final int FLOATS = 7;
    static final float TRUNK = 0;
    static final float FOLIAGE = 1;
    /** The trunk goes this far (a share of the height) into the ground, so a plant on a slope does not float. */
    static final float SINK = 0.04f;
    /** How far a sphere's vertices move in or out, as a share of its radius: clumps of leaves. */
    static final double LUMP = 0.14;
    /** The conifer's cones, bottom up: base height, tip height, base radius (shares of the height), as a spruce's. */
    static final float[][] CONES = {{0.10f, 0.45f, 0.26f}, {0.25f, 0.60f, 0.22f}, {0.40f, 0.75f, 0.18f},
        {0.55f, 0.88f, 0.13f}, {0.70f, 1.0f, 0.08f}};
    /** The broadleaf crown's spheres: centre (x, y, z) and radius, shares of the height. */
    static final float[][] CROWN = {{0, 0.62f, 0, 0.30f}, {0.17f, 0.55f, 0.10f, 0.22f}, {-0.15f, 0.57f, -0.10f, 0.23f},
        {0.02f, 0.80f, -0.04f, 0.19f}};
    /** The bush's mounds. */
    static final float[][] MOUNDS = {{0, 0.45f, 0, 0.55f}, {0.3f, 0.35f, 0.15f, 0.4f}};

    private TreeShape() {
    }

    /** Interleaved vertices (position, normal, part) and triangles. */
    record Geometry(float[] vertices, int[] triangles) {

        int triangleCount() {
            return triangles.length / 3;
        }
    }

    /** The full shape of a kind ({@code far} false) or its simplified one. */
    static Geometry of(TreeKind kind, boolean far) {
        Builder b = new Builder();
        switch (kind) {
            case CONIFER -> {
                b.trunk(far ? 3 : 6, 0.03, far ? 0.2 : 0.3);
                if (far) {
                    b.cone(5, 0.1, 1.0, 0.24, 0);
                } else {
                    for (float[] c : CONES) {
                        b.cone(8, c[0], c[1], c[2], LUMP);
                    }
                }
            }
            case BROADLEAF -> {
                b.trunk(far ? 3 : 6, 0.035, 0.5);
                if (far) {
                    b.sphere(6, 4, 0.01, 0.62, 0, 0.36, 0);
                } else {
                    for (float[] s : CROWN) {
                        b.sphere(8, 5, s[0], s[1], s[2], s[3], LUMP);
                    }
                }
            }
            case BUSH -> {
                if (far) {
                    b.sphere(5, 3, 0.08, 0.42, 0.04, 0.58, 0);
                } else {
                    for (float[] s : MOUNDS) {
                        b.sphere(8, 5, s[0], s[1], s[2], s[3], LUMP);
                    }
                }
            }
            default -> throw new IllegalArgumentException(kind.toString());
        }
        return b.geometry();
    }

    /** Vertices and triangles as they are added. */
    private static final class Builder {
        private final List<float[]> v = new ArrayList<>();
        private final List<Integer> t = new ArrayList<>();

        /** A trunk of {@code sides} from {@link #SINK} below the ground to {@code top}. */
        void trunk(int sides, double radius, double top) {
            for (int i = 0; i < sides; i++) {
                double a0 = 2 * Math.PI * i / sides;
                double a1 = 2 * Math.PI * (i + 1) / sides;
                int base = v.size();
                add(radius, a0, -SINK, Math.cos(a0), 0, Math.sin(a0), TRUNK);
                add(radius, a1, -SINK, Math.cos(a1), 0, Math.sin(a1), TRUNK);
                add(radius, a1, top, Math.cos(a1), 0, Math.sin(a1), TRUNK);
                add(radius, a0, top, Math.cos(a0), 0, Math.sin(a0), TRUNK);
                t.addAll(List.of(base, base + 3, base + 2, base, base + 2, base + 1));
            }
        }

        /**
         * A cone's sides and its flat underside, its rim ragged by ±{@code lump} of the radius. A side's normal leans
         * out by the slope: for base radius r and height h, (h cos a, r, h sin a) normalised.
         */
        void cone(int sides, double bottom, double top, double radius, double lump) {
            double h = top - bottom;
            for (int i = 0; i < sides; i++) {
                double a0 = 2 * Math.PI * i / sides;
                double a1 = 2 * Math.PI * (i + 1) / sides;
                double mid = 0.5 * (a0 + a1);
                double r0 = radius * (1 + lump * wobble(i, bottom));
                double r1 = radius * (1 + lump * wobble((i + 1) % sides, bottom));
                int side = v.size();
                add(r0, a0, bottom, h * Math.cos(a0), radius, h * Math.sin(a0), FOLIAGE);
                add(0, 0, top, h * Math.cos(mid), radius, h * Math.sin(mid), FOLIAGE);
                add(r1, a1, bottom, h * Math.cos(a1), radius, h * Math.sin(a1), FOLIAGE);
                t.addAll(List.of(side, side + 1, side + 2));
                int under = v.size();
                add(r0, a0, bottom, 0, -1, 0, FOLIAGE);
                add(r1, a1, bottom, 0, -1, 0, FOLIAGE);
                add(0, 0, bottom, 0, -1, 0, FOLIAGE);
                t.addAll(List.of(under, under + 1, under + 2));
            }
        }

        /** A sphere of {@code segments} round and {@code rings} from pole to pole, its radius lumpy by ±{@code lump}. */
        void sphere(int segments, int rings, double cx, double cy, double cz, double radius, double lump) {
            int base = v.size();
            for (int j = 0; j <= rings; j++) {
                double lat = Math.PI * j / rings - Math.PI / 2;
                for (int i = 0; i <= segments; i++) {
                    double lon = 2 * Math.PI * i / segments;
                    double nx = Math.cos(lat) * Math.cos(lon);
                    double ny = Math.sin(lat);
                    double nz = Math.cos(lat) * Math.sin(lon);
                    // the poles are not moved, so each stays one point and the sphere within its height
                    double r = radius * (1 + (j == 0 || j == rings ? 0 : lump * wobble(i % segments, j + cy)));
                    v.add(new float[] {(float) (cx + r * nx), (float) (cy + r * ny), (float) (cz + r * nz),
                        (float) nx, (float) ny, (float) nz, FOLIAGE});
                }
            }
            int row = segments + 1;
            for (int j = 0; j < rings; j++) {
                for (int i = 0; i < segments; i++) {
                    int a = base + j * row + i;
                    if (j > 0) { // the bottom ring's first triangle would have both its lower corners on the pole
                        t.addAll(List.of(a, a + row, a + 1));
                    }
                    if (j < rings - 1) { // nor the top ring's second, on the top pole
                        t.addAll(List.of(a + 1, a + row, a + row + 1));
                    }
                }
            }
        }

        private void add(double radius, double angle, double y, double nx, double ny, double nz, float part) {
            double n = Math.sqrt(nx * nx + ny * ny + nz * nz);
            v.add(new float[] {(float) (radius * Math.cos(angle)), (float) y, (float) (radius * Math.sin(angle)),
                (float) (nx / n), (float) (ny / n), (float) (nz / n), part});
        }

        Geometry geometry() {
            float[] vertices = new float[v.size() * FLOATS];
            for (int i = 0; i < v.size(); i++) {
                System.arraycopy(v.get(i), 0, vertices, i * FLOATS, FLOATS);
            }
            return new Geometry(vertices, t.stream().mapToInt(Integer::intValue).toArray());
        }
    }

    /** A fixed pseudo-random number in [−1, 1] for a vertex index and a height: the same shape every run. */
    static double wobble(int i, double y) {
        long h = TreePlacement.mix(i * 0x9E3779B97F4A7C15L + Double.doubleToLongBits(y));
        return (h >>> 11) * 0x1.0p-52 - 1;
    }
}
