package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glDeleteTextures;
import static org.lwjgl.opengl.GL11C.glGenTextures;

/**
 * What every texture shares: one GL name of one target ({@code GL_TEXTURE_2D}, {@code GL_TEXTURE_3D}, ...), counted
 * in the context's {@link GlObjects}, bound to a unit for sampling and deleted once on {@link #close()}. The
 * subclasses add their storage, size and sampling.
 */
public abstract class GlTexture implements AutoCloseable {

    protected final GlContext gl;
    private final int target;
    private int id;

    /** Creates the name and leaves it bound to {@code target} on the active unit, for the subclass to fill. */
    protected GlTexture(GlContext gl, int target) {
        this.gl = gl;
        this.target = target;
        this.id = glGenTextures();
        gl.objects().created(GlObjects.Kind.TEXTURE);
        glBindTexture(target, id);
    }

    /** Binds to texture unit {@code unit}. */
    public void bind(int unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(target, id);
    }

    /** Binds to the active unit, to change the texture's storage or parameters. */
    protected void bindForUpdate() {
        glBindTexture(target, id);
    }

    public int id() {
        return id;
    }

    @Override
    public void close() {
        if (id != 0) {
            glDeleteTextures(id);
            gl.objects().deleted(GlObjects.Kind.TEXTURE);
            id = 0;
        }
    }
}
