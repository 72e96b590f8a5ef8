package org.openworld.engine.terrain.stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.NodeHeights;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TestTerrain;
import org.openworld.engine.terrain.lod.CopyLattice;
import org.openworld.engine.terrain.lod.LodSettings;
import org.openworld.engine.terrain.lod.TerrainQuadtree;
import org.openworld.engine.water.MirrorCamera;

/**
 * The culling of the unbounded world with the heights its streamed blocks span, GL-free: the very
 * {@link StreamedWorld} the engine draws, streamed around {@code crossing.path}'s first pose (400 m above the ground,
 * heading east, 8° down), and the culling system walking its roots as the terrain attaches them.
 */
class StreamedCullingTest {

    /** crossing.path's first pose: x, yaw, pitch; the height is 400 m above the ground there. */
    private static final double START_X = -9000;
    private static final float WATER = 0;

    private static StreamedWorld world;
    private static final List<Block> BLOCKS = new ArrayList<>();
    private static CameraPose pose;

    @BeforeAll
    static void stream() {
        world = new StreamedWorld(TestTerrain.settings("terrain.world=unbounded"), 1,
                LodSettings.DEFAULTS.patchVertices() - 1, new StageTimes(), line -> { });
        pose = new CameraPose(START_X, world.heights().heightAt(START_X, 0) + 400, 0, 90, -8, 60);
        // a first follow waits until every level's window is whole; each block is kept with its own samples' range
        world.follow(pose, 0, (level, ix0, iz0, texelX, texelZ, block, bordered) -> {
            int border = world.border();
            int side = block + 2 * border;
            float[] samples = new float[block * block];
            for (int j = 0; j < block; j++) {
                System.arraycopy(bordered, (j + border) * side + border, samples, j * block, block);
            }
            BLOCKS.add(new Block(level, ix0 / block, iz0 / block, samples));
        });
    }

    @AfterAll
    static void close() {
        world.close();
    }

    /** A streamed block: its level, its position in that level's blocks, its samples (row-major). */
    private record Block(int level, long bx, long bz, float[] samples) {
    }

    /**
     * Every node the residency gives heights for spans every streamed sample that it or any node below it may draw:
     * those of the levels 0 .. L + log2 N (a descendant reads its own level up to log2 N coarser) over the node's
     * samples and the row and column beyond. A node settled by the culling settles its subtree, so a range that
     * missed a finer level's peak would cull a patch that shows it.
     */
    @Test
    void theHeightsTheCullingTestsBoundEveryStreamedSampleBelow() {
        TerrainQuadtree tree = world.tree();
        float[] offsets = offsets();
        float[] range = new float[2];
        int known = 0;
        int checked = 0;
        for (int copy = 0; copy < offsets.length / 2; copy++) {
            float ox = offsets[2 * copy];
            float oz = offsets[2 * copy + 1];
            long originX = world.rootOrigin(ox);
            long originZ = world.rootOrigin(oz);
            for (int node = 0; node < tree.nodeCount(); node++) {
                if (!world.cullRange(node, ox, oz, range)) {
                    continue;
                }
                known++;
                long x = originX + tree.sampleX(node);
                long z = originZ + tree.sampleZ(node);
                long span = (long) tree.cells() << tree.level(node);
                int coarsest = Math.min(world.levels() - 1, tree.level(node) + tree.cellsLog2());
                for (Block b : BLOCKS) {
                    int l = b.level();
                    if (l > coarsest || !world.holds(l, b.bx(), b.bz())) {
                        continue;
                    }
                    // the block's samples within the node's rectangle of level l: [x >> l, ((x + span) >> l) + 1)
                    int n = StreamedWorld.BLOCK;
                    long i0 = Math.max(x >> l, b.bx() * n);
                    long i1 = Math.min(((x + span) >> l) + 1, (b.bx() + 1) * n);
                    long j0 = Math.max(z >> l, b.bz() * n);
                    long j1 = Math.min(((z + span) >> l) + 1, (b.bz() + 1) * n);
                    for (long j = j0; j < j1; j++) {
                        for (long i = i0; i < i1; i++) {
                            float h = b.samples()[(int) ((j - b.bz() * n) * n + (i - b.bx() * n))];
                            checked++;
                            if (h < range[0] || h > range[1]) {
                                fail("node " + node + " of copy " + copy + " (level " + tree.level(node)
                                        + ") is tested with " + range[0] + " .. " + range[1] + " m, but level " + l
                                        + "'s sample (" + i + ", " + j + ") below it is " + h + " m");
                            }
                        }
                    }
                }
            }
        }
        assertTrue(known > tree.nodeCount() / 16 && checked > known, known + " nodes known, " + checked + " checked");
    }

    /**
     * The reflection's walk settles subtrees. Its near plane is the water (an oblique projection), and with the
     * world's height bounds every box straddles it: the walk finds no node wholly inside and descends to every leaf
     * it does not reject. With the streamed heights a node wholly above the water and inside the other planes is
     * accepted whole, one wholly below it rejected, and a node the level choice cannot split (a child's heights
     * have not arrived) is kept whole: the walk tests the roots and the children of splittable nodes only, at
     * most copies + 4 · (splittable nodes), whatever the frustum.
     */
    @Test
    void theReflectionsWalkSettlesSubtreesWithTheStreamedHeights() {
        ViewCamera reflection = reflection(ViewCamera.perspective(pose, 16 / 9f, 0.5f, 40_000));
        double[] bounds = walk(reflection, NodeHeights.NONE);
        double[] streamed = walk(reflection, world.cullHeights());
        assertEquals(0, bounds[2], "with the world's bounds no box lies above the water");
        assertTrue(streamed[2] > 0, "nothing accepted whole with the streamed heights");
        float[] offsets = offsets();
        NodeHeights heights = world.cullHeights();
        int splittable = 0;
        for (int copy = 0; copy < offsets.length / 2; copy++) {
            for (int node = 0; node < world.tree().nodeCount(); node++) {
                if (world.tree().level(node) > 0 && heights.splits(node, offsets[2 * copy], offsets[2 * copy + 1])) {
                    splittable++;
                }
            }
        }
        int most = offsets.length / 2 + 4 * splittable;
        assertTrue(streamed[0] <= most && most < bounds[0] / 4, "tested " + streamed[0] + " nodes with the streamed "
                + "heights (at most " + most + "), " + bounds[0] + " with the world's bounds");
        System.out.printf("reflection culling at crossing.path's start: %.0f nodes tested with the world's bounds "
                + "(%.0f inside), %.0f with the streamed heights (%.0f inside); %d copies of %d nodes%n",
                bounds[0], bounds[2], streamed[0], streamed[2], offsets().length / 2, world.tree().nodeCount());
    }

    /** Culls the roots around the camera with a reflection camera; the counters tested, outside, inside. */
    private static double[] walk(ViewCamera camera, NodeHeights heights) {
        CullingSystem culling = new CullingSystem();
        World w = new World();
        w.setResource(Engine.settingsFor(List.of(culling)));
        w.setResource(new Counters());
        w.add(w.spawn(), new Cullable(world.tree().bounds(), offsets(), heights));
        culling.render(Pass.REFLECTION, new RenderContext(w, camera, new DrawStats(), null, Set.of()));
        Counters counters = w.resource(Counters.class);
        return new double[] {counters.snapshot().get("culling.reflection.tested"),
            counters.snapshot().get("culling.reflection.outside"), counters.snapshot().get("culling.reflection.inside")};
    }

    /** The roots around the camera, as the terrain lays them. */
    private static float[] offsets() {
        double extent = world.tree().extent();
        return CopyLattice.copies(Math.round(pose.x() / extent), Math.round(pose.z() / extent), world.rootRadius(),
                extent);
    }

    /** The viewer mirrored in the water, its near plane the water: as the water's reflection pass draws it. */
    private static ViewCamera reflection(ViewCamera viewer) {
        Matrix4f mirror = MirrorCamera.reflection(WATER);
        Matrix4f view = new Matrix4f(viewer.view()).mul(mirror);
        Vector3f eye = mirror.transformPosition(new Vector3f(viewer.position()));
        Vector4f plane = new Matrix4f(view).invert().transpose().transform(new Vector4f(0, 1, 0, -WATER));
        return new ViewCamera(view, MirrorCamera.obliqueNearPlane(viewer.projection(), plane), eye, viewer.near(),
                viewer.far());
    }
}
