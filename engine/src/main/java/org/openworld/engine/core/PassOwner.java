package org.openworld.engine.core;

import java.util.Optional;

/**
 * A system that owns a pass (DESIGN.md, "Passes"): the shadow system owns {@link Pass#SHADOW} (the sun's camera, its
 * depth map), the water system {@link Pass#REFLECTION} (the mirrored camera, its reflection texture). Once per
 * frame, before the pass, the engine asks the owner for the pass's {@link PassView}; every system that draws in the
 * pass then draws with that camera into that target, without knowing who owns it. A pass with no enabled owner, or
 * whose owner answers empty (the camera is under the water, so there is nothing to mirror), is skipped.
 */
public interface PassOwner {

    /** The pass this system owns; at most one system owns each pass. */
    Pass ownedPass();

    /**
     * This frame's camera and target for the owned pass.
     *
     * @param world  the shared world
     * @param viewer MAIN's view this frame: the viewer's camera, from which a mirror's camera is made, and the scene
     *               target, whose size a screen-aligned target follows
     * @return the view, or empty to skip the pass this frame
     */
    Optional<PassView> passView(World world, PassView viewer);
}
