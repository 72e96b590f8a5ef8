package org.openworld.engine.gl;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import org.lwjgl.stb.STBImage;
import org.lwjgl.stb.STBImageWrite;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.files.AtomicFiles;

/**
 * An 8-bit RGBA image in memory, top row first: what a render reads back, and what {@code shot} writes as PNG
 * (through LWJGL's stb_image_write). Pixel accessors let tests check what was drawn.
 */
public final class Image {

    private final int width;
    private final int height;
    private final byte[] rgba;

    public Image(int width, int height, byte[] rgba) {
        if (rgba.length != width * height * 4) {
            throw new IllegalArgumentException("expected " + width * height * 4 + " bytes, got " + rgba.length);
        }
        this.width = width;
        this.height = height;
        this.rgba = rgba;
    }

    /** From GL's bottom-up rows. */
    static Image fromBottomUp(int width, int height, ByteBuffer pixels) {
        byte[] out = new byte[width * height * 4];
        int row = width * 4;
        for (int y = 0; y < height; y++) {
            pixels.get((height - 1 - y) * row, out, y * row, row);
        }
        return new Image(width, height, out);
    }

    /** Reads a PNG (or any format stb_image reads) as RGBA. */
    public static Image read(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        ByteBuffer encoded = MemoryUtil.memAlloc(bytes.length).put(bytes).flip();
        try (MemoryStack stack = MemoryStack.stackPush()) {
            var w = stack.mallocInt(1);
            var h = stack.mallocInt(1);
            var channels = stack.mallocInt(1);
            ByteBuffer decoded = STBImage.stbi_load_from_memory(encoded, w, h, channels, 4);
            if (decoded == null) {
                throw new IOException(file + ": not a readable image: " + STBImage.stbi_failure_reason());
            }
            byte[] rgba = new byte[w.get(0) * h.get(0) * 4];
            decoded.get(0, rgba); // absolute: stbi_image_free needs the buffer's position at 0
            STBImage.stbi_image_free(decoded);
            return new Image(w.get(0), h.get(0), rgba);
        } finally {
            MemoryUtil.memFree(encoded);
        }
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Channel c (0 r, 1 g, 2 b, 3 a) at (x, y), 0–255; y = 0 is the top row. */
    public int channel(int x, int y, int c) {
        return rgba[(y * width + x) * 4 + c] & 0xFF;
    }

    /** Rec. 709 luma of the stored (sRGB-encoded) values, 0–255. */
    public double luma(int x, int y) {
        return 0.2126 * channel(x, y, 0) + 0.7152 * channel(x, y, 1) + 0.0722 * channel(x, y, 2);
    }

    /** Mean luma over a rectangle. */
    public double meanLuma(int x0, int y0, int x1, int y1) {
        double sum = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                sum += luma(x, y);
            }
        }
        return sum / Math.max(1, (x1 - x0) * (y1 - y0));
    }

    /**
     * Writes a PNG, creating parent folders: into a temporary file beside {@code file}, renamed over it
     * ({@link AtomicFiles#write}), so a reader never sees half a picture.
     */
    public void writePng(Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        Files.createDirectories(parent);
        ByteBuffer pixels = MemoryUtil.memAlloc(rgba.length).put(rgba).flip();
        try {
            AtomicFiles.write(file, temp -> {
                if (!STBImageWrite.stbi_write_png(temp.toString(), width, height, 4, pixels, width * 4)) {
                    throw new IOException(file + ": could not write the PNG (stb_image_write failed)");
                }
            });
        } finally {
            MemoryUtil.memFree(pixels);
        }
    }
}
