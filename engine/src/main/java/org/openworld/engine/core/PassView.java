package org.openworld.engine.core;

import org.openworld.engine.gl.Framebuffer;

/**
 * Where one pass draws this frame and with which camera. The engine makes MAIN's and OVERLAY's from the viewer's
 * camera and its scene target; a {@link PassOwner} makes its own pass's.
 *
 * @param camera the camera every system in the pass draws with (written into the frame block)
 * @param target the framebuffer the pass draws into; the engine binds it and clears it before the pass
 */
public record PassView(ViewCamera camera, Framebuffer target) {
}
