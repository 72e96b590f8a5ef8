package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL11C.GL_TEXTURE;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_MAG_FILTER;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_MIN_FILTER;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_WRAP_S;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_WRAP_T;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glTexParameteri;
import static org.lwjgl.opengl.GL12C.GL_TEXTURE_MAX_LEVEL;
import static org.lwjgl.opengl.GL12C.GL_TEXTURE_WRAP_R;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE_CUBE_MAP;
import static org.lwjgl.opengl.GL13C.glActiveTexture;

import org.lwjgl.opengl.GL11C;

/**
 * What every texture shares: one GL name of one target ({@code GL_TEXTURE_2D}, {@code GL_TEXTURE_3D},
 * {@code GL_TEXTURE_2D_ARRAY}, {@code GL_TEXTURE_CUBE_MAP}), its size and {@link Format}, its {@link Sampling}
 * written once at creation, counted in the context's {@link GlObjects}, bound to a unit for sampling, labelled for
 * GPU debuggers and deleted once on {@link #close()}. The subclasses add how their storage is made and filled, and
 * say how many mip levels they made ({@link #stored}); the bytes are counted here, in the context's
 * {@link TextureMemory}, and given back on {@link #close()}.
 *
 * <p>The size is three numbers for every kind: width × height × depth, where depth is 1 for a 2D texture and a cube
 * map's face, the layers of an array and the slices of a volume.
 */
public abstract class GlTexture implements Labelled {

    protected final GlContext gl;
    private final int target;
    private final int width;
    private final int height;
    private final int depth;
    private final Format format;
    private int id;
    /** What {@link #stored} counted in the context's {@link TextureMemory}; 0 before and after. */
    private long storageBytes;

    /**
     * Creates the name, leaves it bound to {@code target} on the active unit for the subclass to fill, and sets the
     * sampling.
     */
    protected GlTexture(GlContext gl, int target, int width, int height, int depth, Format format,
                        Sampling sampling) {
        if (width <= 0 || height <= 0 || depth <= 0) {
            throw new IllegalArgumentException("texture size must be positive, got " + width + "x" + height
                    + (depth == 1 ? "" : "x" + depth));
        }
        this.gl = gl;
        this.target = target;
        this.width = width;
        this.height = height;
        this.depth = depth;
        this.format = format;
        this.id = gl.objects().create(GlObjects.Kind.TEXTURE, GL11C::glGenTextures);
        glBindTexture(target, id);
        glTexParameteri(target, GL_TEXTURE_MIN_FILTER, sampling.minFilter());
        glTexParameteri(target, GL_TEXTURE_MAG_FILTER, sampling.magFilter());
        glTexParameteri(target, GL_TEXTURE_WRAP_S, sampling.wrap());
        glTexParameteri(target, GL_TEXTURE_WRAP_T, sampling.wrap());
        glTexParameteri(target, GL_TEXTURE_WRAP_R, sampling.wrap());
    }

    /** Mip levels in a full chain for a {@code width × height} level 0: 1 + log2(max(width, height)). */
    protected static int fullChain(int width, int height) {
        return 32 - Integer.numberOfLeadingZeros(Math.max(width, height));
    }

    /** Tells GL how many mip levels the storage has, so a texture with fewer than the full chain is complete. */
    protected final void setLevels(int levels) {
        glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, levels - 1);
    }

    /**
     * Counts the storage just made, mip levels 0 .. {@code levels} − 1 of every layer or face, in the context's
     * {@link TextureMemory}: called by each subclass once its {@code glTexImage} calls (and {@code glGenerateMipmap},
     * which makes the levels below 0) are done. Storage made again replaces what was counted before.
     */
    protected final void stored(int levels) {
        gl.textureMemory().released(storageBytes);
        storageBytes = TextureMemory.bytes(format, width, height, target == GL_TEXTURE_CUBE_MAP ? 6 : depth, levels);
        gl.textureMemory().allocated(storageBytes);
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

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** 1 for a 2D texture or a cube map, the layers of an array, the slices of a volume. */
    public int depth() {
        return depth;
    }

    public Format format() {
        return format;
    }

    @Override
    public void label(String name) {
        gl.debug().label(GL_TEXTURE, id, name);
    }

    @Override
    public void close() {
        id = gl.objects().delete(GlObjects.Kind.TEXTURE, id, GL11C::glDeleteTextures);
        gl.textureMemory().released(storageBytes);
        storageBytes = 0;
    }
}
