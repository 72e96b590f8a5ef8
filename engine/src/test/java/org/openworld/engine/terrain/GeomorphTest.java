package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TestPyramids;
import org.openworld.engine.terrain.heights.TestTerrain;
import org.openworld.engine.terrain.lod.CopyLattice;
import org.openworld.engine.terrain.lod.Corner;
import org.openworld.engine.terrain.lod.DetailLimit;
import org.openworld.engine.terrain.lod.LodMode;
import org.openworld.engine.terrain.lod.LodRule;
import org.openworld.engine.terrain.lod.LodSettings;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.lod.PatchSelection;
import org.openworld.engine.terrain.lod.QuadtreeLod;
import org.openworld.engine.terrain.lod.Side;
import org.openworld.engine.terrain.lod.TerrainQuadtree;
import org.openworld.engine.terrain.stream.StreamedWorld;

/**
 * Geomorphing (no popping), GL-free: the morph ranges the quadtree cut gives its patches, and the surface
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

    /**
     * A patch's morph factor k runs from 0 to 1, by its box distance, over the last {@link QuadtreeLod#MORPH_SHARE}
     * of the distances from where it appears (its own merge distance, {@link DetailLimit#fineFrom}) to where its
     * parent becomes fine enough: under the paper's rule, of B · 2^L to B · 2^(L+1). The root never morphs.
     */
    @Test
    void paperMorphFactorsRunFromTheLevelsDistanceToTheParents() {
        PatchSelection selection = new PatchSelection(tree);
        PatchList patches = new PatchList();
        double b = 64;
        Vector3f eye = new Vector3f(37, 90, 11);
        selection.select(eye, offsets, DetailLimit.paper(b), LodMode.QUADTREE, null, patches);
        int between = 0;
        for (int i = 0; i < patches.size(); i++) {
            int level = patches.level(i);
            float k = patches.morph(i);
            if (level == tree.rootLevel() || level == 0) {
                assertEquals(0, k, level == 0 ? 1 : 0, "level " + level);
                continue;
            }
            double copyX = offsets[2 * patches.copy(i)];
            double copyZ = offsets[2 * patches.copy(i) + 1];
            double distance = tree.bounds().distance(patches.node(i), (float) copyX, (float) copyZ, eye);
            double end = b * Math.pow(2, level + 1);
            double band = QuadtreeLod.MORPH_SHARE * (end - b * Math.pow(2, level));
            // float distances (24-bit mantissa) over hundreds of metres: k to 1e-5
            assertEquals(Math.max(0, Math.min(1, (distance - end + band) / band)), k, 1e-5, "k of a level-" + level
                    + " patch " + distance + " m away");
            between += k > 0 && k < 1 ? 1 : 0;
        }
        // a handful of patches in their morph bands shows the bands are exercised; 10 is a count chosen, not measured
        assertTrue(between > 10, "patches part way through their morph: " + between);
    }

    /** The flat grid (figure 6) never morphs, and {@code lod.morph=off} clears every factor. */
    @Test
    void theFlatGridAndMorphOffNeverMorph() {
        PatchSelection selection = new PatchSelection(tree);
        PatchList patches = new PatchList();
        selection.select(new Vector3f(0, 80, 0), offsets, DetailLimit.paper(32), LodMode.FLAT_GRID, null, patches);
        assertNeverMorphs(patches);
        selection.select(new Vector3f(0, 80, 0), offsets, DetailLimit.paper(32), LodMode.QUADTREE, null, patches);
        boolean morphs = false;
        for (int i = 0; i < patches.size(); i++) {
            morphs |= patches.morph(i) > 0;
        }
        assertTrue(morphs, "some of the quadtree cut's patches have morphed part of the way");
        patches.withoutMorph();
        assertNeverMorphs(patches);
    }

    private static void assertNeverMorphs(PatchList patches) {
        for (int i = 0; i < patches.size(); i++) {
            assertEquals(0, patches.morph(i));
            for (Side side : SIDES) {
                assertEquals(0, patches.sideMorph(i, side));
            }
            for (Corner corner : CORNERS) {
                assertEquals(0, patches.cornerMorph(i, corner));
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
        Ground tile = new TileGround();
        Approach on = approach(tile, limit(rule), true, new Vector3f(-340, 70, 23), 0.75f, -25, 400);
        Approach off = approach(tile, limit(rule), false, new Vector3f(-340, 70, 23), 0.75f, -25, 400);
        assertSmooth(rule.toString(), on, off);
    }

    /**
     * The same on the unbounded world along {@code crossing.path}'s start (400 m above the ground, heading east,
     * 8° down, the default 6 px screen-error rule and 33-vertex patches), streamed by the very {@link StreamedWorld}
     * the engine draws, its blocks kept in memory as the texture arrays keep them: its boxes span the world's 2.4 km
     * of heights, so only the heights the clipmap knows give the morph bands their width.
     */
    @Test
    void aLevelChangeMovesNoVertexAbruptlyOnTheUnboundedWorld() {
        try (StreamedGround on = new StreamedGround(); StreamedGround off = new StreamedGround()) {
            DetailLimit limit = DetailLimit.projected(projection, WIDTH, HEIGHT, LodSettings.DEFAULTS.pixelError());
            float y = (float) on.world.heights().heightAt(-9000, 0) + 400;
            Vector3f start = new Vector3f(-9000, y, 0);
            float down = (float) (-100 * Math.tan(Math.toRadians(8)));
            assertSmooth("unbounded world", approach(on, limit, true, start, 0.9f, down, 300),
                    approach(off, limit, false, start, 0.9f, down, 300));
        }
    }

    private static void assertSmooth(String world, Approach on, Approach off) {
        assertTrue(on.levelChanges > 20 && off.levelChanges > 20, "level changes seen: " + on.levelChanges);
        // half a pixel: a vertex that moves less than that between frames lands on the same or the next pixel, no
        // visible pop; over 20 level changes make sure the approach saw some
        assertTrue(on.largestJump <= 0.5, world + ": largest jump with morphing " + on.largestJump + " px");
        assertTrue(off.largestJump > 0.5, world + ": largest jump without morphing " + off.largestJump + " px");
        System.out.printf("geomorph %s: largest jump %.3f px with morphing, %.3f px without (%d level changes)%n",
                world, on.largestJump, off.largestJump, on.levelChanges);
    }

    private record Approach(double largestJump, int levelChanges) {
    }

    /** What the vertex shader reads: a quadtree, its roots around the camera and level L's height at a sample. */
    private interface Ground {
        PatchSelection selection();

        TerrainQuadtree tree();

        /** The roots' (copies') offsets, metres, with the camera here. */
        float[] offsets(Vector3f eye);

        /** The world's level-0 sample index of a root's first sample, on either axis. */
        long origin(float offset);

        /** terrain.vert's heightAt: level L's height at the world's level-0 sample (gx, gz). */
        float height(int level, long gx, long gz);
    }

    /** The hills' periodic tile, as three by three copies. */
    private final class TileGround implements Ground {
        private final PatchSelection selection = new PatchSelection(tree);

        public PatchSelection selection() {
            return selection;
        }

        public TerrainQuadtree tree() {
            return tree;
        }

        public float[] offsets(Vector3f eye) {
            return offsets;
        }

        public long origin(float offset) {
            return Math.round(offset / pyramid.base().spacing()) - tree.size() / 2;
        }

        /** The tile's sample index is the position's shifted by half the tile (its centre lies at the offset). */
        public float height(int level, long gx, long gz) {
            long half = tree.size() / 2;
            return pyramid.level(level).sample((int) ((gx + half) >> level), (int) ((gz + half) >> level));
        }
    }

    /** The unbounded world streamed around the camera into arrays laid out as the clipmap's texture layers. */
    private static final class StreamedGround implements Ground, AutoCloseable {
        final StreamedWorld world = new StreamedWorld(TestTerrain.settings("terrain.world=unbounded"), 1,
                LodSettings.DEFAULTS.patchVertices() - 1, new StageTimes(), line -> { });
        private final PatchSelection selection = new PatchSelection(world.tree(), world);
        private final int size = world.clipSize();
        private final float[][] layers = new float[world.levels()][size * size];
        private final Vector3f last = new Vector3f(Float.NaN, 0, 0);

        public PatchSelection selection() {
            return selection;
        }

        public TerrainQuadtree tree() {
            return world.tree();
        }

        /** Follows the camera as TerrainSystem does each step (at 60 a second), and lays the roots around it as it does. */
        public float[] offsets(Vector3f eye) {
            world.follow(new CameraPose(eye.x, eye.y, eye.z, 90, -8, 45), last.isFinite() ? 1 / 60.0 : 0,
                    (level, ix0, iz0, texelX, texelZ, block, bordered) -> {
                        int border = world.border();
                        int side = block + 2 * border;
                        for (int j = 0; j < block; j++) {
                            System.arraycopy(bordered, (j + border) * side + border, layers[level],
                                    (texelZ + j) * size + texelX, block);
                        }
                    });
            last.set(eye);
            double extent = world.tree().extent();
            return CopyLattice.copies(Math.round(eye.x / extent), Math.round(eye.z / extent), world.rootRadius(),
                    extent);
        }

        public long origin(float offset) {
            return world.rootOrigin(offset);
        }

        public float height(int level, long gx, long gz) {
            int mask = size - 1;
            return layers[level][(int) ((gz >> level) & mask) * size + (int) ((gx >> level) & mask)];
        }

        @Override
        public void close() {
            world.close();
        }
    }

    /** One vertex's last drawn height, the frame it was drawn in and the levels it was drawn at. */
    private static final class Drawn {
        int frame = -1;
        float height;
        long levels;
    }

    /**
     * Moves the camera {@code frames} times by {@code stride} metres along x, looking 100 m ahead and {@code drop}
     * metres down, and measures the largest on-screen move of a vertex between consecutive frames.
     */
    private Approach approach(Ground ground, DetailLimit limit, boolean morph, Vector3f start, float stride,
            float drop, int frames) {
        PatchList patches = new PatchList();
        TerrainQuadtree quadtree = ground.tree();
        int cells = quadtree.cells();
        double spacing = quadtree.extent() / quadtree.size();
        Map<Long, Drawn> drawn = new HashMap<>();
        double largest = 0;
        int levelChanges = 0;
        Vector3f eye = new Vector3f();
        Matrix4f viewProjection = new Matrix4f();
        Vector4f a = new Vector4f();
        Vector4f b = new Vector4f();
        for (int frame = 1; frame <= frames; frame++) {
            eye.set(start.x + stride * frame, start.y, start.z);
            viewProjection.set(projection).lookAt(eye, new Vector3f(eye.x + 100, eye.y + drop, eye.z),
                    new Vector3f(0, 1, 0));
            float[] roots = ground.offsets(eye);
            ground.selection().select(eye, roots, limit, LodMode.QUADTREE, null, patches);
            if (!morph) {
                patches.withoutMorph();
            }
            for (int i = 0; i < patches.size(); i++) {
                float offsetX = roots[2 * patches.copy(i)];
                float offsetZ = roots[2 * patches.copy(i) + 1];
                long originX = ground.origin(offsetX) + patches.originSampleX(i);
                long originZ = ground.origin(offsetZ) + patches.originSampleZ(i);
                for (int row = 0; row <= cells; row++) {
                    for (int column = 0; column <= cells; column++) {
                        if (!drawn(patches, i, cells, column, row)) {
                            continue;
                        }
                        long gx = originX + (long) column * patches.sampleStep(i);
                        long gz = originZ + (long) row * patches.sampleStep(i);
                        float x = (float) (gx * spacing);
                        float z = (float) (gz * spacing);
                        int level = vertexLevel(patches, i, cells, column, row);
                        float h = displayedHeight(ground, patches, i, cells, column, row, gx, gz, level);
                        viewProjection.transform(b.set(x, h, z, 1));
                        if (!(b.w > 1 && onScreen(b))) {
                            continue; // only what is seen can be seen to jump
                        }
                        Drawn vertex = drawn.computeIfAbsent(gx << 32 ^ (gz & 0xFFFF_FFFFL), key -> new Drawn());
                        if (vertex.frame == frame) {
                            // 1e-3 m: float heights of a few hundred metres round at ~3e-5 m; a crack would be metres
                            assertEquals(vertex.height, h, 1e-3, "patches sharing a vertex agree (no crack)");
                            continue;
                        }
                        long levelCode = ((long) patches.level(i) << 8) | level;
                        if (vertex.frame == frame - 1) {
                            if (vertex.levels != levelCode) {
                                levelChanges++;
                            }
                            viewProjection.transform(a.set(x, vertex.height, z, 1));
                            if (a.w > 1 && onScreen(a)) {
                                double dx = (a.x / a.w - b.x / b.w) * WIDTH / 2;
                                double dy = (a.y / a.w - b.y / b.w) * HEIGHT / 2;
                                largest = Math.max(largest, Math.hypot(dx, dy));
                            }
                        }
                        vertex.height = h;
                        vertex.levels = levelCode;
                        vertex.frame = frame;
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
    private static boolean drawn(PatchList patches, int i, int cells, int column, int row) {
        int last = cells;
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
    private static int vertexLevel(PatchList p, int i, int cells, int column, int row) {
        boolean north = row == 0, south = row == cells, west = column == 0, east = column == cells;
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

    /** terrain.vert's main, for the height: the level's sample moved towards the coarser surface by k. */
    private static float displayedHeight(Ground ground, PatchList p, int i, int cells, int column, int row, long gx,
            long gz, int level) {
        float h = ground.height(level, gx, gz);
        double k = morphFactor(p, i, cells, column, row, level);
        if (k <= 0) {
            return h;
        }
        long ox = ((gx >> level) & 1) << level;
        long oz = ((gz >> level) & 1) << level;
        float coarser = 0.5f * (ground.height(level + 1, gx - ox, gz - oz)
                + ground.height(level + 1, gx + ox, gz + oz));
        return (float) (h + (coarser - h) * k);
    }

    private static double sideK(PatchList p, int i, Side side, int level) {
        return p.sideLevel(i, side) == level ? p.sideMorph(i, side) : 0;
    }

    private static double cornerK(PatchList p, int i, Corner c, int level) {
        return Math.max(Math.max(sideK(p, i, c.northSouth(), level), sideK(p, i, c.eastWest(), level)),
                p.cornerMorph(i, c));
    }

    /** terrain.vert's morphFactor. */
    private static double morphFactor(PatchList p, int i, int cells, int column, int row, int level) {
        boolean north = row == 0, south = row == cells, west = column == 0, east = column == cells;
        double k = level == p.level(i) ? p.morph(i) : 0;
        if (north && west) return Math.max(k, cornerK(p, i, Corner.NORTH_WEST, level));
        if (north && east) return Math.max(k, cornerK(p, i, Corner.NORTH_EAST, level));
        if (south && east) return Math.max(k, cornerK(p, i, Corner.SOUTH_EAST, level));
        if (south && west) return Math.max(k, cornerK(p, i, Corner.SOUTH_WEST, level));
        if (north) return Math.max(k, sideK(p, i, Side.NORTH, level));
        if (east) return Math.max(k, sideK(p, i, Side.EAST, level));
        if (south) return Math.max(k, sideK(p, i, Side.SOUTH, level));
        if (west) return Math.max(k, sideK(p, i, Side.WEST, level));
        return k;
    }
}
