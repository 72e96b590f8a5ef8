package org.openworld.engine.culling;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.culling.Visibility.Containment;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Framebuffer;

/**
 * The hierarchical traversal against the brute-force test of every node on its own, without GL: since a child's box
 * lies in its parent's, a parent wholly outside one plane (or inside all) has children that are too, so reading the
 * traversal's answers top-down must give exactly each node's own answer.
 */
class CullingTraversalTest {

    private static final long SEED = 24;
    /** Culling draws nothing in these passes (no frozen frustum to outline), so it needs no framebuffer. */
    private static final Framebuffer NO_TARGET = null;
    /** Side of the root box, metres: a terrain tile of a few kilometres. */
    private static final float WORLD = 4000;
    private static final int MAX_DEPTH = 6;
    private static final int CAMERAS = 40;
    /** Two copies of the tree: at the origin and one tile east and south, metres. */
    private static final float[] OFFSETS = {0, 0, WORLD, WORLD};

    @Test
    void readTopDownEqualsEveryNodeTestedAlone() {
        Random random = new Random(SEED);
        BoundsTree tree = randomTree(random);
        assertTrue(tree.nodeCount() > 200, "tree too small to say much: " + tree.nodeCount());
        CullingSystem culling = new CullingSystem();
        World world = worldFor(culling);
        int entity = world.spawn();
        world.add(entity, new Cullable(tree, OFFSETS));
        Visibility first = null;
        int[] totals = new int[3];
        for (int c = 0; c < CAMERAS; c++) {
            boolean shadow = c % 4 == 3;
            ViewCamera camera = shadow ? sunCamera(random) : randomViewer(random);
            Pass pass = shadow ? Pass.SHADOW : Pass.MAIN;
            culling.render(pass, new RenderContext(world, camera, new DrawStats(), NO_TARGET, Set.of()));

            Visibility visibility = world.get(entity, Visibility.class).orElseThrow();
            if (first == null) {
                first = visibility;
            }
            assertSame(first, visibility, "the Visibility is made again although its size did not change");
            Frustum alone = new Frustum().set(camera);
            int[] expected = new int[3]; // tested, outside, inside
            for (int copy = 0; copy < OFFSETS.length / 2; copy++) {
                compare(tree, visibility, alone, copy, 0, visibility.root(copy), true, expected);
            }
            Map<String, Double> counters = world.resource(Counters.class).snapshot();
            String prefix = "culling." + pass.label() + ".";
            assertEquals(expected[0], counters.get(prefix + "tested"), prefix + "tested");
            assertEquals(expected[1], counters.get(prefix + "outside"), prefix + "outside");
            assertEquals(expected[2], counters.get(prefix + "inside"), prefix + "inside");
            for (int i = 0; i < 3; i++) {
                totals[i] += expected[i];
            }
            world.resource(Counters.class).clear();
        }
        // rejected and accepted subtrees both occurred, and the hierarchy saved tests
        assertTrue(totals[1] > CAMERAS && totals[2] > CAMERAS, "outside " + totals[1] + ", inside " + totals[2]);
        assertTrue(totals[0] < CAMERAS * 2 * tree.nodeCount(), "no test was saved");
    }

    @Test
    void theFramesAnswersAreWithdrawnAfterOverlay() {
        CullingSystem culling = new CullingSystem();
        World world = worldFor(culling);
        int entity = world.spawn();
        world.add(entity, new Cullable(randomTree(new Random(SEED)), OFFSETS));
        ViewCamera camera = ViewCamera.perspective(new CameraPose(0, 100, 0, 0, 0, 60), 16 / 9f, 0.5f, 40_000);
        culling.render(Pass.MAIN, new RenderContext(world, camera, new DrawStats(), NO_TARGET, Set.of()));
        assertTrue(world.get(entity, Visibility.class).isPresent());
        culling.render(Pass.OVERLAY, new RenderContext(world, camera, new DrawStats(), NO_TARGET, Set.of()));
        assertTrue(world.get(entity, Visibility.class).isEmpty(),
                "a Visibility left after the frame would be read, stale, if culling were switched off");
    }

    /**
     * Walks the tree as a drawer reads it, checking each node's top-down answer against its own test, and counts
     * the nodes the traversal must have tested: those whose ancestors were all PARTIAL.
     */
    private static void compare(BoundsTree tree, Visibility visibility, Frustum alone, int copy, int node,
                                Containment read, boolean tested, int[] counts) {
        Containment own = alone.test(tree.boxes(), node, OFFSETS[2 * copy], OFFSETS[2 * copy + 1]);
        assertEquals(own, read, "copy " + copy + ", node " + node);
        if (tested) {
            counts[0]++;
            counts[1] += own == Containment.OUTSIDE ? 1 : 0;
            counts[2] += own == Containment.INSIDE ? 1 : 0;
        }
        int first = tree.firstChild(node);
        for (int child = first; child < first + tree.childCount(node); child++) {
            compare(tree, visibility, alone, copy, child, visibility.of(copy, child, read),
                    tested && own == Containment.PARTIAL, counts);
        }
    }

    private static World worldFor(CullingSystem culling) {
        World world = new World();
        world.setResource(Engine.settingsFor(List.of(culling)));
        world.setResource(new Counters());
        return world;
    }

    /** A viewer somewhere over the tile, looking any way. */
    private static ViewCamera randomViewer(Random random) {
        CameraPose pose = new CameraPose(WORLD * (random.nextDouble() - 0.5), 50 + 1000 * random.nextDouble(),
                WORLD * (random.nextDouble() - 0.5), 360 * random.nextDouble(), -80 + 100 * random.nextDouble(),
                30 + 60 * random.nextDouble());
        return ViewCamera.perspective(pose, 16 / 9f, 0.5f, 500 + 5000 * random.nextFloat());
    }

    /** An orthographic light camera looking down at a slant on part of the tile, as a shadow pass has. */
    private static ViewCamera sunCamera(Random random) {
        Vector3f centre = new Vector3f(WORLD * (random.nextFloat() - 0.5f), 0, WORLD * (random.nextFloat() - 0.5f));
        Vector3f eye = new Vector3f(centre).add(new Vector3f(random.nextFloat() - 0.5f, 1, random.nextFloat() - 0.5f)
                .normalize(2000));
        Matrix4f view = new Matrix4f().lookAt(eye, centre, new Vector3f(0, 0, -1));
        float half = 200 + 1000 * random.nextFloat();
        Matrix4f projection = new Matrix4f().ortho(-half, half, -half, half, 0, 4000);
        return new ViewCamera(view, projection, eye, 0, 4000);
    }

    /**
     * A random tree, breadth first so each node's children are contiguous: 1 to 4 children per node (4 at the
     * root), each a random box inside its parent's, until {@link #MAX_DEPTH}.
     */
    private static BoundsTree randomTree(Random random) {
        List<float[]> boxes = new ArrayList<>();
        List<Integer> depth = new ArrayList<>();
        List<int[]> children = new ArrayList<>(); // firstChild, childCount
        boxes.add(new float[] {-WORLD / 2, 0, -WORLD / 2, WORLD / 2, 400, WORLD / 2});
        depth.add(0);
        for (int node = 0; node < boxes.size(); node++) {
            int count = depth.get(node) >= MAX_DEPTH ? 0 : node == 0 ? 4 : random.nextInt(5);
            children.add(new int[] {boxes.size(), count});
            for (int k = 0; k < count; k++) {
                boxes.add(insideOf(boxes.get(node), random));
                depth.add(depth.get(node) + 1);
            }
        }
        float[] flat = new float[6 * boxes.size()];
        int[] firstChild = new int[boxes.size()];
        int[] childCount = new int[boxes.size()];
        for (int i = 0; i < boxes.size(); i++) {
            System.arraycopy(boxes.get(i), 0, flat, 6 * i, 6);
            firstChild[i] = children.get(i)[0];
            childCount[i] = children.get(i)[1];
        }
        return new BoundsTree(flat, firstChild, childCount);
    }

    /** A box inside a parent box: each side a random interval of at least a third of the parent's. */
    private static float[] insideOf(float[] parent, Random random) {
        float[] box = new float[6];
        for (int axis = 0; axis < 3; axis++) {
            float lo = parent[axis];
            float size = parent[axis + 3] - lo;
            float length = size * (1 / 3f + 2 / 3f * random.nextFloat());
            box[axis] = lo + (size - length) * random.nextFloat();
            box[axis + 3] = Math.min(box[axis] + length, parent[axis + 3]);
        }
        return box;
    }
}
