package org.openworld.engine.terrain.heights;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Locale;
import org.lwjgl.stb.STBImage;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;

/**
 * Height maps from files, instead of synthesis ({@link TerrainSettings#importFile()}): a 16-bit grayscale PNG (read
 * with LWJGL's stb_image, {@link STBImage#stbi_load_16_from_memory}) or raw little-endian float32 samples
 * ({@code .raw}, {@code .r32}, {@code .f32}; the side follows from the file length), row by row from the north-west
 * corner, as terrain tools export them.
 *
 * <p>A map must be square with 2^n or 2^n + 1 samples per side, 2^n from {@value #MIN_SIZE} to {@value #MAX_SIZE}.
 * Many tools write 2^n + 1 samples (2^n cells with a vertex at each corner); the pyramid halves 2^n samples down to
 * one, so the last row and column are dropped: one sample at the south and east edge, instead of resampling and
 * blurring the whole map. 8-bit PNGs are refused: 256 levels over hundreds of metres of relief make visible terraces.
 *
 * <p>Imported heights are normalised like generated ones ({@code relief}, {@code seaFraction}); the spacing comes from
 * the settings and the map is not periodic: lookups clamp at its edges. Every problem is a
 * {@link HeightImportException} naming the file.
 */
public final class HeightImport {

    /** Smallest accepted side (2^n part), samples: the smallest generated map. */
    public static final int MIN_SIZE = 256;
    /** Largest accepted side (2^n part), samples: the largest generated map. */
    public static final int MAX_SIZE = 8192;

    private HeightImport() {
    }

    /** Reads and normalises a height map file. */
    public static HeightMap read(Path file, TerrainSettings s) {
        if (!Files.isRegularFile(file)) {
            throw new HeightImportException(file + ": " + (Files.exists(file) ? "is not a file"
                    : Files.isSymbolicLink(file) ? "a link that leads to no file (its target is missing, or it loops)"
                    : "no such file"));
        }
        String name = file.getFileName().toString();
        String extension = name.substring(name.lastIndexOf('.') + 1).toLowerCase(Locale.ROOT);
        try {
            Grid grid = switch (extension) {
                case "png" -> readPng(file);
                case "raw", "r32", "f32" -> readRaw(file);
                default -> throw new HeightImportException(file + ": unknown extension"
                        + (name.contains(".") ? " '." + extension + "'" : " (none)")
                        + "; expected .png (16-bit grayscale) or .raw, .r32, .f32 (little-endian float32)");
            };
            return normalise(file, grid, s);
        } catch (IOException e) {
            throw new HeightImportException(file + ": cannot be read: " + e.getMessage());
        }
    }

    /** Samples of a map, side already cut to 2^n. */
    private record Grid(int size, float[] samples) {
    }

    private static Grid readPng(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        ByteBuffer encoded = MemoryUtil.memAlloc(bytes.length).put(bytes).flip();
        try (MemoryStack stack = MemoryStack.stackPush()) {
            var w = stack.mallocInt(1);
            var h = stack.mallocInt(1);
            var channels = stack.mallocInt(1);
            if (!STBImage.stbi_info_from_memory(encoded, w, h, channels)) {
                throw new HeightImportException(file + ": not a readable PNG: " + STBImage.stbi_failure_reason());
            }
            if (!STBImage.stbi_is_16_bit_from_memory(encoded)) {
                throw new HeightImportException(file + ": is an 8-bit image; height maps need 16 bits per sample "
                        + "(256 levels make visible terraces): save it as a 16-bit grayscale PNG");
            }
            int side = checkSide(file, w.get(0), h.get(0));
            ShortBuffer decoded = STBImage.stbi_load_16_from_memory(encoded, w, h, channels, 1);
            if (decoded == null) {
                throw new HeightImportException(file + ": not a readable PNG: " + STBImage.stbi_failure_reason());
            }
            try {
                int n = cut(side);
                float[] samples = new float[n * n];
                for (int z = 0; z < n; z++) {
                    for (int x = 0; x < n; x++) {
                        samples[z * n + x] = Short.toUnsignedInt(decoded.get(z * side + x));
                    }
                }
                return new Grid(n, samples);
            } finally {
                STBImage.stbi_image_free(decoded);
            }
        } finally {
            MemoryUtil.memFree(encoded);
        }
    }

    private static Grid readRaw(Path file) throws IOException {
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            long bytes = channel.size();
            if (bytes % Float.BYTES != 0) {
                throw new HeightImportException(file + ": is " + bytes + " bytes, not a whole number of 4-byte float32 "
                        + "samples");
            }
            long count = bytes / Float.BYTES;
            long side = Math.round(Math.sqrt((double) count));
            if (side * side != count || !valid(side)) {
                throw new HeightImportException(file + ": holds " + count + " float32 samples; expected (2^n)² or "
                        + "(2^n + 1)² with 2^n from " + MIN_SIZE + " to " + MAX_SIZE + "; nearest: "
                        + nearest(Math.sqrt((double) count), true));
            }
            int s = (int) side;
            int n = cut(s);
            FloatBuffer values = channel.map(FileChannel.MapMode.READ_ONLY, 0, bytes)
                    .order(ByteOrder.LITTLE_ENDIAN).asFloatBuffer();
            float[] samples = new float[n * n];
            for (int z = 0; z < n; z++) {
                values.get(z * s, samples, z * n, n);
            }
            for (int i = 0; i < samples.length; i++) {
                if (!Float.isFinite(samples[i])) {
                    throw new HeightImportException(file + ": sample (" + i % n + ", " + i / n + ") is " + samples[i]
                            + "; heights must be finite numbers");
                }
            }
            return new Grid(n, samples);
        }
    }

    /** The side of a w×h map if it is square and valid. */
    private static int checkSide(Path file, int w, int h) {
        if (w != h) {
            throw new HeightImportException(file + ": is " + w + "×" + h + " pixels; height maps must be square");
        }
        if (!valid(w)) {
            throw new HeightImportException(file + ": is " + w + "×" + h + " pixels; expected 2^n or 2^n + 1 per side "
                    + "with 2^n from " + MIN_SIZE + " to " + MAX_SIZE + "; nearest: " + nearest(w, false));
        }
        return w;
    }

    /** Whether a side is 2^n or 2^n + 1 with 2^n in range. */
    private static boolean valid(long side) {
        long n = cut(side);
        return n >= MIN_SIZE && n <= MAX_SIZE && Long.bitCount(n) == 1 && (side == n || side == n + 1);
    }

    /** The 2^n part of a valid side: a 2^n + 1 side loses its last row and column. */
    private static int cut(long side) {
        return (int) (Long.bitCount(side) == 1 ? side : side - 1);
    }

    /** The valid sides just below and just above {@code side}, as sizes or as sample counts. */
    private static String nearest(double side, boolean counts) {
        long below = -1;
        long above = -1;
        for (long p = MIN_SIZE; p <= MAX_SIZE; p *= 2) {
            for (long v : new long[] {p, p + 1}) {
                if (v <= side) {
                    below = v;
                }
                if (v >= side && above < 0) {
                    above = v;
                }
            }
        }
        StringBuilder text = new StringBuilder();
        for (long v : below == above ? new long[] {below} : new long[] {below, above}) {
            if (v > 0) {
                text.append(text.length() > 0 ? " or " : "").append(counts ? v * v + " (" + v + "²)" : v + "×" + v);
            }
        }
        return text.toString();
    }

    /** Scales the samples to the relief with seaFraction of it below 0, as synthesis does. */
    private static HeightMap normalise(Path file, Grid grid, TerrainSettings s) {
        float[] a = grid.samples();
        float lo = Float.POSITIVE_INFINITY;
        float hi = Float.NEGATIVE_INFINITY;
        for (float v : a) {
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
        }
        if (!(hi > lo)) {
            throw new HeightImportException(file + ": every sample is " + lo + "; a flat map has no heights to scale");
        }
        SpectralSynthesis.normalise(a, grid.size(), s.relief(), s.seaFraction());
        return new HeightMap(grid.size(), s.spacing(), a, false);
    }
}
