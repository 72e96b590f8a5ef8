package org.openworld.engine.core;

import java.util.List;

/**
 * A system that owns a pass (docs/design.md, "Passes"): the shadow system owns {@link Pass#SHADOW} (the sun's cameras, one
 * per cascade, and their depth maps), the water system {@link Pass#REFLECTION} (the mirrored camera, its reflection
 * texture). Once per frame, before the pass, the engine asks the owner for the pass's {@link PassView}s and runs the
 * pass once for each, in order: every system that draws in the pass then draws with that view's camera into its
 * target, without knowing who owns it. A pass with no enabled owner, or whose owner answers with no view (the camera
 * is under the water, so there is nothing to mirror), is skipped. A view's target is cleared before it is drawn and
 * left alone when no view names it, so an owner can keep what a target holds by leaving its view out (the shadow
 * system keeps the cascades that nothing moved): the engine still binds the sun's shadow maps for the later passes.
 */
public interface PassOwner {

    /** The pass this system owns; at most one system owns each pass. */
    Pass ownedPass();

    /**
     * This frame's cameras and targets for the owned pass.
     *
     * @param world  the shared world
     * @param viewer MAIN's view this frame: the viewer's camera, from which a mirror's or the sun's cameras are made,
     *               and the scene target, whose size a screen-aligned target follows. The camera is made anew each
     *               frame and is the very object MAIN's systems get in their {@link RenderContext}, so an owner can
     *               tell in MAIN whether its pass ran for this frame (the water's reflection)
     * @return the views the pass is drawn with, in order; none to skip the pass this frame
     */
    List<PassView> passViews(World world, PassView viewer);
}
