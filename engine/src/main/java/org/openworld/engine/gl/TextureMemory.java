package org.openworld.engine.gl;

/**
 * The engine's own count of the texture memory one context holds: every {@link GlTexture} adds its storage's bytes
 * when the storage is made and takes them back when closed, so {@link #bytes()} is what the engine's textures hold
 * now and {@link #peakBytes()} the most they ever held at once. OpenGL has no query for it and most drivers report no
 * memory at all ({@link GpuMemoryInfo}), so this count is the figure every driver, llvmpipe included, has.
 *
 * <p>A texture's storage is {@link #bytes(Format, int, int, int, int) texels × bytes per texel}, summed over its mip
 * levels and its layers or cube faces. It is what the formats need, not what a driver allocates: drivers round rows
 * and levels up to their alignment and tiling, and some pad three-channel texels to four
 * ({@link Format#bytesPerTexel()}), so the GPU's own figure is somewhat larger. Framebuffers count through their
 * texture attachments; the engine makes no renderbuffers. Cost: one addition per texture made or closed.
 */
public final class TextureMemory {

    private long bytes;
    private long peakBytes;

    /**
     * Bytes of a texture's storage: {@code layers} images of {@code width × height} texels at level 0, each level
     * half the size of the one before in width and height (rounded down, at least 1), for {@code levels} levels.
     * A full chain of a square power of two adds a third to level 0 (1 + 1/4 + 1/16 + ... → 4/3); the sum here is
     * exact for any size.
     *
     * @param layers an array's layers or a cube map's 6 faces, which keep their count at every level; also a
     *               volume's slices, right for the one level a {@link Texture3D} has (a volume's mip levels would
     *               halve its slices too)
     */
    public static long bytes(Format format, int width, int height, int layers, int levels) {
        long texels = 0;
        for (int level = 0; level < levels; level++) {
            texels += (long) Math.max(1, width >> level) * Math.max(1, height >> level);
        }
        return texels * layers * format.bytesPerTexel();
    }

    /** Counts storage just made. */
    void allocated(long storageBytes) {
        bytes += storageBytes;
        peakBytes = Math.max(peakBytes, bytes);
    }

    /** Takes back the storage of a texture just deleted. */
    void released(long storageBytes) {
        if (storageBytes > bytes) {
            throw new IllegalStateException("texture memory released (" + storageBytes + " B) beyond what is held ("
                    + bytes + " B)");
        }
        bytes -= storageBytes;
    }

    /** Bytes the context's textures hold now. */
    public long bytes() {
        return bytes;
    }

    /** The most bytes its textures held at once since the context was made, start-up included. */
    public long peakBytes() {
        return peakBytes;
    }
}
