package org.openworld.engine.culling;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import java.util.function.Predicate;
import org.joml.Matrix4f;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.NodeHeights;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.culling.Visibility.Containment;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Conservative hierarchical frustum culling (paper 2.4) for the camera of whichever pass is being drawn.
 *
 * <p>In each pass it prepares ({@link Pass#SHADOW}, {@link Pass#REFLECTION}, {@link Pass#MAIN}), before the systems
 * that draw and read {@link Visibility}: for every entity with a {@link Cullable}, and for every copy of its
 * {@link BoundsTree}, the tree is walked from the root with the pass camera's {@link Frustum}. A node found
 * {@code OUTSIDE} or {@code INSIDE} is not descended: its whole subtree shares the answer, so a frustum that sees a
 * corner of a quadtree tests a few dozen boxes, not thousands. Only {@code PARTIAL} nodes test their children. The
 * answers go into the entity's {@link Visibility}, read top-down with {@link Visibility#of}.
 *
 * <p>Counters per pass, e.g. {@code culling.main.tested} (boxes tested), {@code culling.main.outside} (subtrees
 * rejected), {@code culling.main.inside} (subtrees accepted whole) and {@code culling.main.kept} (partial nodes not
 * descended into, because their owner draws nothing below them on its own: {@link NodeHeights#splits}).
 *
 * <p>With {@link CullingSettings#freeze} on, each pass keeps the frustum it had when freezing began, and the frozen
 * main frustum is outlined in {@link Pass#OVERLAY}: after every drawer, so nothing paints over it (the culling
 * system must come before the drawers in the main pass), and depth-tested against the scene they left.
 *
 * <p>At the end of each frame (in its {@link Pass#OVERLAY} turn) the answers are taken off the entities again, so
 * that once this system is switched off ({@code Engine.setEnabled}) the drawers find no {@code Visibility} rather
 * than a stale one from another pass or frame; a drawer treats a missing {@code Visibility} as everything visible.
 * The {@code Visibility} objects are kept and reattached, made anew only when a tree's size or copy count changes,
 * and the traversal allocates nothing.
 */
public final class CullingSystem implements EngineSystem {
    /** The counters, per pass: boxes tested, subtrees rejected, subtrees accepted whole, partial nodes kept. */
    private static final Counter TESTED = Counter.of("culling", "tested");
    private static final Counter OUTSIDE = Counter.of("culling", "outside");
    private static final Counter INSIDE = Counter.of("culling", "inside");
    private static final Counter KEPT = Counter.of("culling", "kept");

    private static final Pass[] CULLED = {Pass.SHADOW, Pass.REFLECTION, Pass.MAIN};

    /** Per pass, by ordinal: the frustum last culled with, and whether it was captured by a freeze. */
    private final Frustum[] frustums = new Frustum[Pass.values().length];
    private final boolean[] frozen = new boolean[Pass.values().length];
    /** Per pass, by ordinal: the counter names, built once. */
    /** Made once, so iterating the world does not allocate a lambda per pass. */
    private final BiConsumer<Integer, Cullable> cullEntity = this::cullEntity;
    private final Predicate<Integer> withdraw = this::withdraw;
    /** Each cullable entity's answers, kept between passes and frames while their size fits. */
    private final Map<Integer, Visibility> answers = new HashMap<>();

    private FrustumOutline outline;
    /** The traversal's state, set before {@link #cullEntity} is called for each entity of one pass. */
    private World world;
    private Frustum frustum;
    private int tested;
    private int outside;
    private int inside;
    private int kept;
    /** The heights of the node being tested, when its cullable knows them. */
    private final float[] range = new float[2];

    public CullingSystem() {
        for (Pass pass : Pass.values()) {
            frustums[pass.ordinal()] = new Frustum();
        }
    }

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("culling").reads(Cullable.class, Settings.class).writes(Visibility.class)
                .prepares(CULLED).draws(Pass.OVERLAY);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(CullingSettings.SETTINGS);
    }

    @Override
    public void init(EngineContext context) {
        outline = new FrustumOutline(context);
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        boolean freeze = context.world().resource(Settings.class).get(CullingSettings.class).freeze();
        if (!freeze) {
            // every capture ends, also of passes not drawn now, so the next freeze captures afresh
            Arrays.fill(frozen, false);
        }
        if (pass == Pass.OVERLAY) {
            // the debug view: the frozen main frustum's edges, over the finished picture
            if (freeze && frozen[Pass.MAIN.ordinal()]) {
                RenderOrigin origin = context.world().resource(RenderOrigin.class);
                outline.draw(context.stats(), origin.x(), origin.z());
            }
            // the frame's answers are used up: no drawer may find them next frame if culling is switched off
            world = context.world();
            answers.keySet().removeIf(withdraw);
            return;
        }
        // 1. this pass's frustum: the camera's, or the one captured when freezing began
        int p = pass.ordinal();
        if (!frozen[p]) {
            frustums[p].set(context.camera());
            frozen[p] = freeze;
            if (freeze && pass == Pass.MAIN) {
                RenderOrigin origin = context.world().resource(RenderOrigin.class);
                outline.setFrustum(new Matrix4f(context.camera().projection())
                        .mul(context.camera().viewFrom(origin.x(), origin.z())), origin.x(), origin.z());
            }
        }
        // 2. every cullable, every copy, top-down
        world = context.world();
        frustum = frustums[p];
        tested = 0;
        outside = 0;
        inside = 0;
        kept = 0;
        world.each(Cullable.class, cullEntity);
        // 3. what it cost and what it found
        Counters counters = world.resource(Counters.class);
        counters.put(TESTED.in(pass), tested);
        counters.put(OUTSIDE.in(pass), outside);
        counters.put(INSIDE.in(pass), inside);
        counters.put(KEPT.in(pass), kept);
    }

    private void cullEntity(Integer entity, Cullable cullable) {
        BoundsTree tree = cullable.tree();
        Visibility visibility = answers.get(entity);
        if (visibility == null || visibility.copies() != cullable.copies()
                || visibility.nodeCount() != tree.nodeCount()) {
            visibility = new Visibility(cullable.copies(), tree.nodeCount());
            answers.put(entity, visibility);
        }
        world.add(entity, visibility);
        float[] offsets = cullable.offsets();
        for (int copy = 0; copy < cullable.copies(); copy++) {
            visit(tree, cullable.heights(), visibility, copy, 0, offsets[2 * copy], offsets[2 * copy + 1],
                    Float.NEGATIVE_INFINITY, Float.POSITIVE_INFINITY);
        }
    }

    /** Takes an entity's answers off it; forgets them too when it is no longer cullable. */
    private boolean withdraw(Integer entity) {
        world.remove(entity, Visibility.class);
        return world.get(entity, Cullable.class).isEmpty();
    }

    /**
     * Tests one node and, only when it straddles the frustum, its children. Its heights are its box's, narrowed to
     * those its cullable knows it spans in this copy and to its parent's ({@code lowest .. highest}): whatever the
     * node draws lies within its parent's range, so a node whose heights are not known (the streamed world's, where
     * its levels have not arrived) keeps its parent's rather than falling back to the whole world's.
     */
    private void visit(BoundsTree tree, NodeHeights heights, Visibility visibility, int copy, int node,
                       float offsetX, float offsetZ, float lowest, float highest) {
        float[] boxes = tree.boxes();
        float minY = Math.max(lowest, boxes[6 * node + 1]);
        float maxY = Math.min(highest, boxes[6 * node + 4]);
        if (heights.range(node, offsetX, offsetZ, range)) {
            minY = Math.max(minY, range[0]);
            maxY = Math.min(maxY, range[1]);
        }
        Containment containment = frustum.test(boxes, node, offsetX, offsetZ, minY, maxY);
        visibility.set(copy, node, containment);
        tested++;
        switch (containment) {
            case OUTSIDE -> outside++;
            case INSIDE -> inside++;
            case KEPT -> throw new IllegalStateException("a box test answers outside, partial or inside");
            case PARTIAL -> {
                if (tree.childCount(node) > 0 && !heights.splits(node, offsetX, offsetZ)) {
                    visibility.set(copy, node, Containment.KEPT);
                    kept++;
                    return;
                }
                int first = tree.firstChild(node);
                for (int child = first; child < first + tree.childCount(node); child++) {
                    visit(tree, heights, visibility, copy, child, offsetX, offsetZ, minY, maxY);
                }
            }
        }
    }
}
