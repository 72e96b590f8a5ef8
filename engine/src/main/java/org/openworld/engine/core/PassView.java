package org.openworld.engine.core;

import org.openworld.engine.gl.Framebuffer;

/**
 * Where one pass draws this frame and with which camera. The engine makes MAIN's and OVERLAY's from the viewer's
 * camera and its scene target; a {@link PassOwner} makes its own pass's.
 *
 * @param camera the camera every system in the pass draws with (written into the frame block)
 * @param target the framebuffer the pass draws into; the engine binds it and clears it before the pass
 * @param number which of its owner's views this is, for the time spans' labels ({@code shadow2.terrain} is the third
 *               cascade's, also on a frame that draws no other); −1 for a pass that has only one view (no number)
 */
public record PassView(ViewCamera camera, Framebuffer target, int number) {

    /** The only view of its pass: labelled by the pass alone ({@code reflection.terrain}). */
    public PassView(ViewCamera camera, Framebuffer target) {
        this(camera, target, -1);
    }
}
