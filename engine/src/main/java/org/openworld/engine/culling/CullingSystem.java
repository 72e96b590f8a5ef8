package org.openworld.engine.culling;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import java.util.function.Predicate;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.culling.Visibility.Containment;
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
 * rejected) and {@code culling.main.inside} (subtrees accepted whole).
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

    private static final Pass[] CULLED = {Pass.SHADOW, Pass.REFLECTION, Pass.MAIN};

    /** Per pass, by ordinal: the frustum last culled with, and whether it was captured by a freeze. */
    private final Frustum[] frustums = new Frustum[Pass.values().length];
    private final boolean[] frozen = new boolean[Pass.values().length];
    /** Per pass, by ordinal: the counter names, built once. */
    private final String[] testedName = new String[Pass.values().length];
    private final String[] outsideName = new String[Pass.values().length];
    private final String[] insideName = new String[Pass.values().length];
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

    public CullingSystem() {
        for (Pass pass : Pass.values()) {
            frustums[pass.ordinal()] = new Frustum();
            testedName[pass.ordinal()] = "culling." + pass.label() + ".tested";
            outsideName[pass.ordinal()] = "culling." + pass.label() + ".outside";
            insideName[pass.ordinal()] = "culling." + pass.label() + ".inside";
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
                outline.draw(context.stats());
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
                outline.setFrustum(context.camera().viewProjection());
            }
        }
        // 2. every cullable, every copy, top-down
        world = context.world();
        frustum = frustums[p];
        tested = 0;
        outside = 0;
        inside = 0;
        world.each(Cullable.class, cullEntity);
        // 3. what it cost and what it found
        Counters counters = world.resource(Counters.class);
        counters.put(testedName[p], tested);
        counters.put(outsideName[p], outside);
        counters.put(insideName[p], inside);
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
            visit(tree, visibility, copy, 0, offsets[2 * copy], offsets[2 * copy + 1]);
        }
    }

    /** Takes an entity's answers off it; forgets them too when it is no longer cullable. */
    private boolean withdraw(Integer entity) {
        world.remove(entity, Visibility.class);
        return world.get(entity, Cullable.class).isEmpty();
    }

    /** Tests one node and, only when it straddles the frustum, its children. */
    private void visit(BoundsTree tree, Visibility visibility, int copy, int node, float offsetX, float offsetZ) {
        Containment containment = frustum.test(tree.boxes(), node, offsetX, offsetZ);
        visibility.set(copy, node, containment);
        tested++;
        switch (containment) {
            case OUTSIDE -> outside++;
            case INSIDE -> inside++;
            case PARTIAL -> {
                int first = tree.firstChild(node);
                for (int child = first; child < first + tree.childCount(node); child++) {
                    visit(tree, visibility, copy, child, offsetX, offsetZ);
                }
            }
        }
    }
}
