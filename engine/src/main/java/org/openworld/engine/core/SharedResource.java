package org.openworld.engine.core;

/**
 * A world resource that every shader of a pass may read without its system binding it (docs/design.md, "Passes"):
 * textures on their {@link org.openworld.engine.gl.SharedTexture} units, blocks at their
 * {@link org.openworld.engine.gl.SharedBlock} points. A system shares one by putting it in the world; before each
 * pass the engine binds the stand-in of every shared texture and block, then every shared resource of the world over
 * them. A resource written by the owner of a pass (the shadow maps, by the owner of SHADOW) is bound only in the
 * passes after that pass has had its turn this frame, never while it is drawn; a system asks
 * {@link RenderContext#shares} whether it is bound, to pick a program that skips the lookup when only the stand-in is.
 */
public interface SharedResource {

    /** Binds its textures to their shared units and its blocks to their shared points. */
    void bindShared();
}
