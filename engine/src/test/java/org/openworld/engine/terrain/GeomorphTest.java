package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Geomorphing (issue 20, "No popping"), GL-free: the morph ranges the quadtree cut gives its patches, and the surface
 * the vertex shader draws from them, computed here by the same formulas as {@code shaders/terrain/terrain.vert}
 * (ramp, morph factor over sides and corners, the coarser level's surface).
 */
class GeomorphTest {

    private static final int WIDTH = 1280;
    private static final int HEIGHT = 720;
    private static final int CELLS = 8;

    private static final Side[] SIDES = Side.values();
    private static final Corner[] CORNERS = Corner.values();

    private final HeightPyramid pyramid = TestPyramids.hills(256, 2);
    private final TerrainQuadtree tree = new TerrainQuadtree(pyramid, CELLS);
    private final float[] offsets = TestPyramids.threeByThree(pyramid.base().extent());
    private final Matrix4f projection = new Matrix4f().perspective((float) Math.toRadians(45), (float) WIDTH / HEIGHT,
            0.5f, 40_000);

    private DetailLimit limit(LodRule rule) {
        return switch (rule) {
            case PAPER -> DetailLimit.paper(LodSettings.DEFAULTS.baseResolution());
            case SCREEN_ERROR -> DetailLimit.projected(projection, WIDTH, HEIGHT, 2);
        };
    }

    /** The shader's ramp: 0 at start, 1 at end, a step where they meet. */
    static double ramp(float start, float end, double d) {
        if (end > start) {
            return Math.max(0, Math.min(1, (d - start) / (end - start)));
        }
        return d >= end ? 1 : 0;
    }

    /**
     * Under the paper's rule a node merges into its parent where the parent's level is chosen, B · 2^(L+1): k is 1
     * there and 0 at the start, which lies no nearer than where the node itself appears (B · 2^L); the ranges nest,
     * each level's start at or beyond the end of the level below.
     */
    @Test
    void paperRangesEndAtTheMergeDistanceAndNest() {
        PatchSelection selection = new PatchSelection(tree);
        PatchList patches = new PatchList();
        double b = 64;
        float[] lowestStart = new float[tree.rootLevel() + 2];
        float[] highestEnd = new float[tree.rootLevel() + 2];
        Arrays.fill(lowestStart, Float.MAX_VALUE);
        for (float x = -300; x <= 300; x += 37) {
            selection.select(new Vector3f(x, 90, 0.3f * x), offsets, DetailLimit.paper(b), LodMode.QUADTREE, null,
                    patches);
            for (int i = 0; i < patches.size(); i++) {
                int level = patches.level(i);
                float start = patches.morphStart(i);
                float end = patches.morphEnd(i);
                if (level == tree.rootLevel()) {
                    assertEquals(PatchList.NEVER, end, "the root never merges");
                    continue;
                }
                assertEquals(b * Math.pow(2, level + 1), end, 1e-3, "merge distance of level " + level);
                assertTrue(start <= end && (level == 0 || start >= b * Math.pow(2, level)), "start " + start);
                assertEquals(0, ramp(start, end, start), 1e-9);
                assertEquals(1, ramp(start, end, end), 1e-6);
                lowestStart[level] = Math.min(lowestStart[level], start);
                highestEnd[level] = Math.max(highestEnd[level], end);
            }
        }
        for (int level = 1; level < tree.rootLevel(); level++) {
            if (lowestStart[level] < Float.MAX_VALUE && highestEnd[level - 1] > 0) {
                assertTrue(lowestStart[level] >= highestEnd[level - 1], "level " + level + " starts at "
                        + lowestStart[level] + ", before level " + (level - 1) + " ends at " + highestEnd[level - 1]);
            }
        }
    }

    /** Under the screen-error rule a node's end is where its parent's error covers the allowed pixels. */
    @Test
    void screenErrorRangesEndWhereTheParentsErrorCoversThePixels() {
        PatchSelection selection = new PatchSelection(tree);
        PatchList patches = new PatchList();
        DetailLimit limit = limit(LodRule.SCREEN_ERROR);
        selection.select(new Vector3f(-200, 70, 10), offsets, limit, LodMode.QUADTREE, null, patches);
        int checked = 0;
        for (int i = 0; i < patches.size(); i++) {
            int node = patches.node(i);
            int level = tree.level(node);
            if (level == tree.rootLevel()) {
                continue;
            }
            int parent = tree.node(level + 1, tree.column(node) >> 1, tree.row(node) >> 1);
            double merge = tree.error(parent) * (HEIGHT / 2.0) / Math.tan(Math.toRadians(22.5)) / 2;
            assertEquals(merge, patches.morphEnd(i), 1e-3 * merge + 1e-3);
            assertTrue(patches.morphStart(i) <= patches.morphEnd(i));
            checked++;
        }
        assertTrue(checked > 10, "patches below the root: " + checked);
    }

    /** The flat grid (figure 6) never morphs, and {@code lod.morph=off} clears every range. */
    @Test
    void theFlatGridAndMorphOffNeverMorph() {
        PatchSelection selection = new PatchSelection(tree);
        PatchList patches = new PatchList();
        selection.select(new Vector3f(0, 80, 0), offsets, DetailLimit.paper(32), LodMode.FLAT_GRID, null, patches);
        assertNeverMorphs(patches);
        selection.select(new Vector3f(0, 80, 0), offsets, DetailLimit.paper(32), LodMode.QUADTREE, null, patches);
        boolean morphs = false;
        for (int i = 0; i < patches.size(); i++) {
            morphs |= patches.morphEnd(i) < PatchList.NEVER;
        }
        assertTrue(morphs, "the quadtree cut's patches below the root have ranges");
        patches.withoutMorph();
        assertNeverMorphs(patches);
    }

    private static void assertNeverMorphs(PatchList patches) {
        for (int i = 0; i < patches.size(); i++) {
            assertEquals(PatchList.NEVER, patches.morphEnd(i));
            for (Side side : SIDES) {
                assertEquals(PatchList.NEVER, patches.sideMorphEnd(i, side));
            }
            for (Corner corner : CORNERS) {
                assertEquals(PatchList.NEVER, patches.cornerMorphEnd(i, corner));
            }
        }
    }

    /**
     * The check: along a scripted approach to a ridge, the camera moving 0.75 m a frame, no vertex drawn in two
     * consecutive frames moves more than 0.5 px between them at 1280 × 720 (both positions seen through the later
     * frame's camera, so the camera's own motion is left out), and every patch sharing a vertex draws it at the same
     * height (no crack). With morphing off, level changes move vertices by more than that.
     */
    @ParameterizedTest
    @EnumSource(LodRule.class)
    void aLevelChangeMovesNoVertexAbruptly(LodRule rule) {
        Approach on = approach(rule, true);
        Approach off = approach(rule, false);
        assertTrue(on.levelChanges > 20 && off.levelChanges > 20, "level changes seen: " + on.levelChanges);
        assertTrue(on.largestJump <= 0.5, rule + ": largest jump with morphing " + on.largestJump + " px");
        assertTrue(off.largestJump > 0.5, rule + ": largest jump without morphing " + off.largestJump + " px");
        System.out.printf("geomorph %s: largest jump %.3f px with morphing, %.3f px without (%d level changes)%n",
                rule, on.largestJump, off.largestJump, on.levelChanges);
    }

    private record Approach(double largestJump, int levelChanges) {
    }

    private Approach approach(LodRule rule, boolean morph) {
        PatchSelection selection = new PatchSelection(tree);
        PatchList patches = new PatchList();
        DetailLimit limit = limit(rule);
        int size = tree.size();
        int side = 3 * size;
        float[] height = new float[side * side];
        float[] previous = new float[side * side];
        int[] stamp = new int[side * side];
        long[] levels = new long[side * side];
        Arrays.fill(stamp, -1);
        double largest = 0;
        int levelChanges = 0;
        Vector3f eye = new Vector3f();
        Matrix4f viewProjection = new Matrix4f();
        Vector4f a = new Vector4f();
        Vector4f b = new Vector4f();
        for (int frame = 1; frame <= 400; frame++) {
            // towards the ridge along x, 0.75 m a frame, 70 m up, looking ahead and a little down
            eye.set(-340 + 0.75f * frame, 70, 23);
            viewProjection.set(projection).lookAt(eye, new Vector3f(eye.x + 100, eye.y - 25, eye.z),
                    new Vector3f(0, 1, 0));
            System.arraycopy(height, 0, previous, 0, height.length);
            selection.select(eye, offsets, limit, LodMode.QUADTREE, null, patches);
            if (!morph) {
                patches.withoutMorph();
            }
            for (int i = 0; i < patches.size(); i++) {
                int copy = patches.copy(i);
                int cx = Math.round(offsets[2 * copy] / (float) pyramid.base().extent()) + 1;
                int cz = Math.round(offsets[2 * copy + 1] / (float) pyramid.base().extent()) + 1;
                for (int row = 0; row <= CELLS; row++) {
                    for (int column = 0; column <= CELLS; column++) {
                        if (!drawn(patches, i, column, row)) {
                            continue;
                        }
                        int sx = patches.originSampleX(i) + column * patches.sampleStep(i);
                        int sz = patches.originSampleZ(i) + row * patches.sampleStep(i);
                        int gx = cx * size + sx;
                        int gz = cz * size + sz;
                        if (gx >= side || gz >= side) {
                            continue; // a vertex on the far edge of the outer copies
                        }
                        int key = gz * side + gx;
                        float x = (float) ((sx - size / 2.0) * pyramid.base().spacing() + offsets[2 * copy]);
                        float z = (float) ((sz - size / 2.0) * pyramid.base().spacing() + offsets[2 * copy + 1]);
                        int level = vertexLevel(patches, i, column, row);
                        float h = displayedHeight(patches, i, column, row, sx, sz, level, x, z, eye);
                        if (stamp[key] == frame) {
                            assertEquals(height[key], h, 1e-3, "patches sharing a vertex agree (no crack)");
                            continue;
                        }
                        long levelCode = ((long) patches.level(i) << 8) | level;
                        if (stamp[key] == frame - 1) {
                            if (levels[key] != levelCode) {
                                levelChanges++;
                            }
                            viewProjection.transform(a.set(x, previous[key], z, 1));
                            viewProjection.transform(b.set(x, h, z, 1));
                            if (a.w > 1 && b.w > 1 && onScreen(a) && onScreen(b)) {
                                double dx = (a.x / a.w - b.x / b.w) * WIDTH / 2;
                                double dy = (a.y / a.w - b.y / b.w) * HEIGHT / 2;
                                largest = Math.max(largest, Math.hypot(dx, dy));
                            }
                        }
                        height[key] = h;
                        levels[key] = levelCode;
                        stamp[key] = frame;
                    }
                }
            }
        }
        return new Approach(largest, levelChanges);
    }

    private static boolean onScreen(Vector4f clip) {
        return Math.abs(clip.x) <= clip.w && Math.abs(clip.y) <= clip.w;
    }

    /** Whether the patch's index patterns use a grid vertex: all inside, every 2^k-th on a side stitched k levels. */
    private static boolean drawn(PatchList patches, int i, int column, int row) {
        int last = CELLS;
        boolean north = row == 0, south = row == last, west = column == 0, east = column == last;
        if (north && !onStride(column, patches.sideStrideLog2(i, Side.NORTH))
                || south && !onStride(column, patches.sideStrideLog2(i, Side.SOUTH))
                || west && !onStride(row, patches.sideStrideLog2(i, Side.WEST))
                || east && !onStride(row, patches.sideStrideLog2(i, Side.EAST))) {
            return false;
        }
        return true;
    }

    private static boolean onStride(int index, int strideLog2) {
        return (index & ((1 << strideLog2) - 1)) == 0;
    }

    /** terrain.vert's vertexLevel. */
    private static int vertexLevel(PatchList p, int i, int column, int row) {
        boolean north = row == 0, south = row == CELLS, west = column == 0, east = column == CELLS;
        if (north && west) return p.cornerLevel(i, Corner.NORTH_WEST);
        if (north && east) return p.cornerLevel(i, Corner.NORTH_EAST);
        if (south && east) return p.cornerLevel(i, Corner.SOUTH_EAST);
        if (south && west) return p.cornerLevel(i, Corner.SOUTH_WEST);
        if (north) return p.sideLevel(i, Side.NORTH);
        if (east) return p.sideLevel(i, Side.EAST);
        if (south) return p.sideLevel(i, Side.SOUTH);
        if (west) return p.sideLevel(i, Side.WEST);
        return p.level(i);
    }

    /** terrain.vert's heightAt: pyramid level L at level-0 sample (x, z), wrapped. */
    private float heightAt(int sx, int sz, int level) {
        return pyramid.level(level).sample(sx >> level, sz >> level);
    }

    /** terrain.vert's main, for the height: the level's sample moved towards the coarser surface by k. */
    private float displayedHeight(PatchList p, int i, int column, int row, int sx, int sz, int level, float x,
            float z, Vector3f eye) {
        float h = heightAt(sx, sz, level);
        double k = morphFactor(p, i, column, row, level, eye.distance(x, h, z));
        if (k <= 0) {
            return h;
        }
        int ox = ((sx >> level) & 1) << level;
        int oz = ((sz >> level) & 1) << level;
        float coarser = 0.5f * (heightAt(sx - ox, sz - oz, level + 1) + heightAt(sx + ox, sz + oz, level + 1));
        return (float) (h + (coarser - h) * k);
    }

    private static double sideK(PatchList p, int i, Side side, int level, double d) {
        return p.sideLevel(i, side) == level ? ramp(p.sideMorphStart(i, side), p.sideMorphEnd(i, side), d) : 0;
    }

    private static double cornerK(PatchList p, int i, Corner c, int level, double d) {
        return Math.max(Math.max(sideK(p, i, c.northSouth(), level, d), sideK(p, i, c.eastWest(), level, d)),
                ramp(p.cornerMorphStart(i, c), p.cornerMorphEnd(i, c), d));
    }

    /** terrain.vert's morphFactor. */
    private static double morphFactor(PatchList p, int i, int column, int row, int level, double d) {
        boolean north = row == 0, south = row == CELLS, west = column == 0, east = column == CELLS;
        double k = level == p.level(i) ? ramp(p.morphStart(i), p.morphEnd(i), d) : 0;
        if (north && west) return Math.max(k, cornerK(p, i, Corner.NORTH_WEST, level, d));
        if (north && east) return Math.max(k, cornerK(p, i, Corner.NORTH_EAST, level, d));
        if (south && east) return Math.max(k, cornerK(p, i, Corner.SOUTH_EAST, level, d));
        if (south && west) return Math.max(k, cornerK(p, i, Corner.SOUTH_WEST, level, d));
        if (north) return Math.max(k, sideK(p, i, Side.NORTH, level, d));
        if (east) return Math.max(k, sideK(p, i, Side.EAST, level, d));
        if (south) return Math.max(k, sideK(p, i, Side.SOUTH, level, d));
        if (west) return Math.max(k, sideK(p, i, Side.WEST, level, d));
        return k;
    }
}
