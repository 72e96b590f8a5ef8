package org.openworld.engine.gl;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.lwjgl.stb.STBIWriteCallback;
import org.lwjgl.stb.STBImage;
import org.lwjgl.stb.STBImageWrite;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.files.AtomicFiles;

/**
 * An 8-bit RGBA image in memory, top row first: what a render reads back, and what {@code shot} writes as PNG or
 * JPEG (through LWJGL's stb_image_write). Pixel accessors let tests check what was drawn.
 *
 * <p>stb_image_write encodes into memory ({@code stbi_write_png_to_func}) and the bytes are written by
 * {@link AtomicFiles#write(Path, byte[])}: its own file writer ignores what {@code fwrite} and {@code fclose}
 * return, so on a full disk it reports success for an empty file.
 */
public final class Image {

    /**
     * JPEG quality, stb's 1–100 scale: at 90 the blocks of an 8×8 DCT are not seen on a rendered landscape, and the
     * file is about a fifth of the PNG's.
     */
    public static final int JPEG_QUALITY = 90;

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

    /** Whether {@link #write} writes {@code file} as a JPEG: its name ends in {@code .jpg} or {@code .jpeg}. */
    public static boolean isJpegName(Path file) {
        String name = String.valueOf(file.getFileName()).toLowerCase(Locale.ROOT);
        return name.endsWith(".jpg") || name.endsWith(".jpeg");
    }

    /** Writes a JPEG if the name says so ({@link #isJpegName}), else a PNG. */
    public void write(Path file) throws IOException {
        if (isJpegName(file)) {
            writeJpeg(file);
        } else {
            writePng(file);
        }
    }

    /**
     * Writes a PNG, creating parent folders: into a temporary file beside {@code file}, renamed over it
     * ({@link AtomicFiles#write}), so a reader never sees half a picture and a failed write keeps the old one.
     */
    public void writePng(Path file) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        AtomicFiles.write(file, encodePng(file, width, height, 4, rgba));
    }

    /** Writes a JPEG at {@link #JPEG_QUALITY} (alpha dropped), as {@link #writePng} writes a PNG. */
    public void writeJpeg(Path file) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        AtomicFiles.write(file, encode(file, rgba, (sink, pixels) -> STBImageWrite.stbi_write_jpg_to_func(sink, 0,
                width, height, 4, pixels, JPEG_QUALITY) != 0));
    }

    /**
     * A PNG file's bytes, encoded in memory by stb_image_write: 8-bit {@code pixels}, {@code channels} per pixel
     * (1 grey, 2 grey and alpha, 3 RGB, 4 RGBA), top row first; {@code file} only names it in an error.
     */
    public static byte[] encodePng(Path file, int width, int height, int channels, byte[] pixels) throws IOException {
        return encode(file, pixels, (sink, data) -> STBImageWrite.stbi_write_png_to_func(sink, 0, width, height,
                channels, data, width * channels));
    }

    /** One of stb_image_write's {@code *_to_func} calls, handed the sink and the pixels. */
    @FunctionalInterface
    private interface Encoder {
        boolean encode(STBIWriteCallback sink, ByteBuffer pixels);
    }

    /** The encoded file in memory: stb hands its output to the sink in chunks. */
    private static byte[] encode(Path file, byte[] data, Encoder encoder) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ByteBuffer pixels = MemoryUtil.memAlloc(data.length).put(data).flip();
        try (STBIWriteCallback sink = STBIWriteCallback.create((context, chunk, size) -> {
            byte[] copy = new byte[size];
            STBIWriteCallback.getData(chunk, size).get(copy);
            bytes.write(copy, 0, size);
        })) {
            if (!encoder.encode(sink, pixels)) {
                throw new IOException(file + ": stb_image_write could not encode the picture");
            }
        } finally {
            MemoryUtil.memFree(pixels);
        }
        return bytes.toByteArray();
    }
}
