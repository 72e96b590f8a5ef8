package org.openworld.engine.terrain;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Consumer;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.TextureArray;
import org.openworld.engine.settings.SettingsException;

/**
 * The unbounded world ({@code terrain.world=UNBOUNDED}, issue 20) as the terrain draws it: the heights of
 * {@link BandedHeights}, streamed level by level around the camera by a {@link HeightClipmap} into three texture
 * arrays (heights; slopes and snow for the shading), and a {@link TerrainQuadtree} over one root whose copies, laid on a
 * lattice of the root's side around the camera, are each a different piece of the world.
 *
 * <p><b>Roots.</b> A root is a node of level R: N · 2^R level-0 samples a side, about {@value #ROOT_METRES} m. The
 * quadtree is the same for every root; only where the vertex shader reads the heights differs (the root's offset,
 * in samples, added to its sample index: {@code shaders/terrain/terrain.vert} with {@code TERRAIN_CLIPMAP}). The
 * world being statistically the same everywhere, a level's error is one figure ({@link BandedHeights#levelErrors})
 * and every box spans the world's height bounds ({@link BandedHeights#lowest}, {@link BandedHeights#highest}),
 * narrowed for the level rule where the node's blocks are resident ({@link #heightRange}).
 *
 * <p><b>Streaming.</b> The clipmap keeps levels 0 .. R, each a window of {@code size²} samples (from
 * {@code terrain.memory-budget}), and makes the blocks a moving camera lacks on worker threads, ahead of it by its
 * velocity; each frame up to {@value #UPLOADS_PER_FRAME} finished blocks are uploaded. A node is split only when its
 * children are {@linkplain #drawable resident} at every level they read, so a block not yet made shows as the
 * coarser ground that covers it, never a hole. At start, and after a jump of the camera, the terrain waits until
 * the middle of every window is full: a first frame is the same whatever the machine's speed.
 *
 * <p><b>Memory.</b> Heights R32F, slopes RG16F, snow RG8: {@value #TEXEL_BYTES} · levels · size² bytes on the
 * GPU, fixed whatever the distance flown; on the Java side the bands' tiles (a MiB each) and the blocks in flight,
 * bounded by the clipmap.
 */
final class UnboundedWorld implements Residency, AutoCloseable {

    /** The side a root aims at, metres: a few roots around the camera reach beyond the fog. */
    static final double ROOT_METRES = 8192;
    /** Samples per side of a streamed block. */
    static final int BLOCK = 64;
    /** Blocks uploaded per frame at most: 64 · 64 · 10 bytes each, 320 KiB a frame. */
    static final int UPLOADS_PER_FRAME = 8;
    /** GPU bytes per sample of a level: height R32F, slopes RG16F, snow and sky RG8. */
    static final int TEXEL_BYTES = 4 + 4 + 2;

    private final BandedHeights heights;
    private final HeightClipmap clipmap;
    private final TerrainQuadtree tree;
    private final ExecutorService workers;
    final TextureArray heightTexture;
    final TextureArray slopeTexture;
    /** r: the snow's coverage ({@link StreamedSnow}); g: the share of the sky seen, 1 everywhere for now. */
    final TextureArray snowTexture;
    private final StreamedSnow snow;
    private final FloatBuffer staging;
    private final ByteBuffer snowStaging;
    private final float[] levelRange = new float[2];
    private final int levels;
    private final int rootRadius;
    private final Consumer<String> progress;
    /** Where the camera was at the last step; null before the first. */
    private CameraPose last;

    /**
     * Makes the bands, the quadtree and the textures (handed to the context's owner as {@code terrain.clipmap...});
     * the first {@link #follow} fills them around the camera, wherever its direction put it.
     *
     * @param cells N, the cells per patch side
     */
    UnboundedWorld(EngineContext context, TerrainSettings s, int seed, int cells, StageTimes times,
                   Consumer<String> progress) {
        heights = times.time("bands", () -> new BandedHeights(s, seed));
        int cellsLog2 = Integer.numberOfTrailingZeros(cells);
        int root = (int) Math.max(1, Math.round(Math.log(ROOT_METRES / (cells * s.spacing())) / Math.log(2)));
        levels = Math.max(root, cellsLog2) + 1;
        if (levels > heights.levels()) {
            throw new SettingsException("the unbounded world needs " + levels + " levels for " + cells
                    + "-cell patches at " + s.spacing() + " m, but its wavelengths (up to " + s.maxWavelength()
                    + " m) make only " + heights.levels() + ": raise terrain.max-wavelength");
        }
        float[] errors = times.time("errors", () -> heights.levelErrors(levels));
        tree = TerrainQuadtree.uniform(cells << root, s.spacing(), cells, errors, (float) heights.lowest(),
                (float) heights.highest());
        rootRadius = (int) Math.ceil(TerrainSystem.COPY_DISTANCE / tree.extent());
        int size = clipSize(s, levels, heights.spacing(levels - 1), tree.extent(), rootRadius);
        // half the cores, at low priority: the frame's own thread (and a software rasteriser's) come first
        workers = Executors.newFixedThreadPool(Math.max(1, Runtime.getRuntime().availableProcessors() / 2), r -> {
            Thread t = new Thread(r, "terrain-blocks");
            t.setDaemon(true);
            t.setPriority(Thread.MIN_PRIORITY);
            return t;
        });
        snow = times.time("snow table", () -> new StreamedSnow(s, seed));
        clipmap = new HeightClipmap(heights, levels, size, BLOCK, StreamedSnow.border(s), workers);
        heightTexture = context.own("clipmap.heights",
                TextureArray.empty(context.gl(), size, size, levels, Format.R32F, Sampling.NEAREST_CLAMP));
        slopeTexture = context.own("clipmap.slopes",
                TextureArray.empty(context.gl(), size, size, levels, Format.RG16F, Sampling.LINEAR_REPEAT));
        snowTexture = context.own("clipmap.snow",
                TextureArray.empty(context.gl(), size, size, levels, Format.RG8, Sampling.LINEAR_REPEAT));
        staging = MemoryUtil.memAllocFloat(2 * BLOCK * BLOCK);
        snowStaging = MemoryUtil.memAlloc(2 * BLOCK * BLOCK);
        markUnwritten(size);
        this.progress = progress;
        progress.accept(String.format(Locale.ROOT, "terrain: %d levels of %d² samples stream around the camera "
                + "(%.0f MiB of %d MiB)", levels, size, textureBytes() / (double) (1 << 20), s.memoryBudget()));
    }

    /**
     * Samples per side of each level's window: the most {@code terrain.memory-budget} holds at
     * {@value #TEXEL_BYTES} bytes a sample (heights, slopes, snow). The coarsest window must hold every root drawn:
     * they reach (radius + 1) root sides from the camera, and the camera may lie as little as a quarter of the window
     * inside it (the clipmap's lead).
     */
    private static int clipSize(TerrainSettings s, int levels, double coarsestSpacing, double rootSide, int radius) {
        long budget = (long) s.memoryBudget() << 20;
        int least = Integer.highestOneBit((int) Math.ceil(4 * (radius + 1) * rootSide / coarsestSpacing) - 1) << 1;
        long leastBytes = (long) TEXEL_BYTES * levels * least * least;
        long leastMib = (leastBytes + (1 << 20) - 1) >> 20;
        if (leastBytes > budget) {
            throw new SettingsException("terrain.memory-budget=" + s.memoryBudget() + " MiB is too little for the "
                    + "unbounded world: its " + levels + " levels need " + least + "² samples each to reach "
                    + (int) ((radius + 1) * rootSide / 1000) + " km, " + leastMib + " MiB or more");
        }
        return HeightClipmap.sizeFor(budget * Float.BYTES / TEXEL_BYTES, levels, BLOCK);
    }

    /**
     * Fills every height texel with NaN before any block arrives: a vertex that read a texel not yet written
     * would not be drawn (a triangle with a NaN corner is dropped), so a read before the upload shows as a hole,
     * which the tests look for, rather than as plausible ground at height 0.
     */
    private void markUnwritten(int size) {
        FloatBuffer nan = MemoryUtil.memAllocFloat(size * BLOCK);
        try {
            while (nan.hasRemaining()) {
                nan.put(Float.NaN);
            }
            nan.flip();
            for (int level = 0; level < levels; level++) {
                for (int z = 0; z < size; z += BLOCK) {
                    heightTexture.upload(level, 0, z, size, BLOCK, nan);
                }
            }
        } finally {
            MemoryUtil.memFree(nan);
        }
    }

    /** Follows the camera, waiting until every level's window around it is resident. */
    private void fill(CameraPose pose) {
        long start = System.nanoTime();
        clipmap.follow(pose.x(), pose.z(), 0, 0);
        last = pose;
        while (!settled(pose)) {
            if (clipmap.drain(Integer.MAX_VALUE, this::upload) == 0) {
                try {
                    Thread.sleep(1);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IllegalStateException("interrupted while streaming the terrain", e);
                }
            }
        }
        progress.accept(String.format(Locale.ROOT, "terrain: %-10s %7.0f ms", "streaming",
                (System.nanoTime() - start) / 1e6));
    }

    /** Whether each level is resident over the middle half of its window around the camera. */
    private boolean settled(CameraPose pose) {
        int quarter = clipmap.size() / 4;
        for (int level = 0; level < levels; level++) {
            double d = heights.spacing(level);
            long x = (long) Math.floor(pose.x() / d);
            long z = (long) Math.floor(pose.z() / d);
            if (!clipmap.resident(level, x - quarter, z - quarter, x + quarter, z + quarter)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Once per simulation step: moves the windows with the camera (ahead of it by its velocity since the last step)
     * and uploads the blocks finished since, a few per frame. A jump (a shot's pose, a cut in a camera path: more
     * than a quarter of level 0's window in one step) is no flight to stream behind: it waits, as the start does,
     * until every window around the new place is full.
     */
    void follow(CameraPose pose, double step) {
        if (last == null) {
            fill(pose);
            return;
        }
        double dx = pose.x() - last.x();
        double dz = pose.z() - last.z();
        if (Math.hypot(dx, dz) > clipmap.size() / 4.0 * heights.spacing(0)) {
            fill(pose);
            return;
        }
        double vx = step > 0 ? dx / step : 0;
        double vz = step > 0 ? dz / step : 0;
        last = pose;
        clipmap.follow(pose.x(), pose.z(), vx, vz);
        clipmap.drain(UPLOADS_PER_FRAME, this::upload);
    }

    /** Uploads a block given with its border: its heights, its slopes by central differences, and its snow. */
    private void upload(int level, long ix0, long iz0, int texelX, int texelZ, int block, float[] bordered) {
        int border = clipmap.border();
        int side = block + 2 * border;
        staging.clear();
        for (int j = border; j < border + block; j++) {
            staging.put(bordered, j * side + border, block);
        }
        heightTexture.upload(level, texelX, texelZ, block, block, staging.flip());
        float inv2d = (float) (1 / (2 * heights.spacing(level)));
        staging.clear();
        for (int j = border; j < border + block; j++) {
            for (int i = border; i < border + block; i++) {
                int at = j * side + i;
                staging.put((bordered[at + 1] - bordered[at - 1]) * inv2d);
                staging.put((bordered[at + side] - bordered[at - side]) * inv2d);
            }
        }
        slopeTexture.upload(level, texelX, texelZ, block, block, staging.flip());
        snowStaging.clear();
        for (byte b : snow.block(level, ix0, iz0, block, bordered, border)) {
            snowStaging.put(b).put((byte) 255);
        }
        snowTexture.upload(level, texelX, texelZ, block, block, snowStaging.flip());
    }

    /**
     * Whether a node of the root at (offsetX, offsetZ) can be drawn: its own level and every coarser one it may read
     * (the next for morphing, up to log2 N coarser along a stitched side) are resident over its samples and the
     * row and column beyond its far sides, which its last vertices read.
     */
    @Override
    public boolean drawable(int node, float offsetX, float offsetZ) {
        return levelsOf(node, offsetX, offsetZ, null);
    }

    /**
     * The heights a resident node may draw: the range of the levels it reads over its samples, widened by its own
     * level's error (the finer levels its descendants draw lie within it of its surface), as a tile's box spans all
     * the levels below it; false when not resident.
     */
    @Override
    public boolean heightRange(int node, float offsetX, float offsetZ, float[] out) {
        out[0] = Float.POSITIVE_INFINITY;
        out[1] = Float.NEGATIVE_INFINITY;
        if (!levelsOf(node, offsetX, offsetZ, out)) {
            return false;
        }
        float error = tree.error(node);
        out[0] -= error;
        out[1] += error;
        return true;
    }

    /** Whether the node's levels are resident; with {@code range}, their heights' union widened into it. */
    private boolean levelsOf(int node, float offsetX, float offsetZ, float[] range) {
        int level = tree.level(node);
        double spacing = heights.spacing(0);
        long originX = Math.round(offsetX / spacing) - tree.size() / 2 + tree.sampleX(node);
        long originZ = Math.round(offsetZ / spacing) - tree.size() / 2 + tree.sampleZ(node);
        long span = (long) tree.cells() << level;
        int coarsest = Math.min(levels - 1, level + tree.cellsLog2());
        for (int l = level; l <= coarsest; l++) {
            long x0 = originX >> l;
            long z0 = originZ >> l;
            long x1 = ((originX + span) >> l) + 1;
            long z1 = ((originZ + span) >> l) + 1;
            if (range == null ? !clipmap.resident(l, x0, z0, x1, z1)
                    : !clipmap.heightRange(l, x0, z0, x1, z1, levelRange)) {
                return false;
            }
            if (range != null) {
                range[0] = Math.min(range[0], levelRange[0]);
                range[1] = Math.max(range[1], levelRange[1]);
            }
        }
        return true;
    }

    /** Roots drawn on each side of the camera's: enough to reach {@link TerrainSystem#COPY_DISTANCE}. */
    int rootRadius() {
        return rootRadius;
    }

    TerrainQuadtree tree() {
        return tree;
    }

    BandedHeights heights() {
        return heights;
    }

    /** Samples per side of every level's window. */
    int clipSize() {
        return clipmap.size();
    }

    /** Bytes the two texture arrays take on the GPU. */
    long textureBytes() {
        return clipmap.textureBytes() / Float.BYTES * TEXEL_BYTES;
    }

    @Override
    public void close() {
        clipmap.close();
        workers.shutdownNow();
        MemoryUtil.memFree(staging);
        MemoryUtil.memFree(snowStaging);
    }
}
