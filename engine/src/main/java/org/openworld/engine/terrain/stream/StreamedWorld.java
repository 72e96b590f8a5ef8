package org.openworld.engine.terrain.stream;

import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.function.Consumer;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.NodeHeights;
import org.openworld.engine.core.Workers;
import org.openworld.engine.erosion.ErodedWorld;
import org.openworld.engine.settings.SettingsException;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.heights.UniformHeights;
import org.openworld.engine.terrain.lod.CopyLattice;
import org.openworld.engine.terrain.lod.QuadtreeLod;
import org.openworld.engine.terrain.lod.Residency;
import org.openworld.engine.terrain.lod.TerrainQuadtree;
import org.openworld.engine.terrain.material.HorizonSearch;

/**
 * The unbounded world ({@code terrain.world=UNBOUNDED}) without its textures: the heights of
 * {@link BandedHeights}, streamed level by level around the camera by a {@link HeightClipmap}, and a
 * {@link TerrainQuadtree} over one root whose copies, laid on a lattice of the root's side around the camera, are each
 * a different piece of the world. It says which nodes can be drawn and which heights they span
 * ({@link Residency}); {@link UnboundedWorld} hands the blocks it makes to the GPU. Being GL-free, the tests run the
 * very same streaming and level choice against heights kept in memory.
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
 * velocity; each step up to {@value #UPLOADS_PER_FRAME} finished blocks are handed on. A node is split only when its
 * children are {@linkplain #drawable resident} at every level they read, so a block not yet made shows as the
 * coarser ground that covers it, never a hole. At start, and after a jump of the camera, it waits until every window
 * is whole: a first frame is the same whatever the machine's speed, and no far block arrives to split a node in view
 * (a split held back steps when it comes, see {@link QuadtreeLod}).
 */
public final class StreamedWorld implements Residency, AutoCloseable {

    /** The side a root aims at, metres: a few roots around the camera reach beyond the fog. */
    static final double ROOT_METRES = 8192;
    /** Samples per side of a streamed block. */
    static final int BLOCK = 64;
    /** Blocks handed on per step at most: 64 · 64 · 10 bytes each, 320 KiB a frame. */
    public static final int UPLOADS_PER_FRAME = 8;
    /** GPU bytes per sample of a level: height R32F, slopes RG16F, snow and sky RG8. */
    static final int TEXEL_BYTES = 4 + 4 + 2;

    private final UniformHeights heights;
    private final HeightClipmap clipmap;
    private final TerrainQuadtree tree;
    private final ThreadPoolExecutor workers;
    /** Workers in flight: half the cores, so the frame's own thread (and a software rasteriser's) come first. */
    private final int flightWorkers = Math.max(1, Runtime.getRuntime().availableProcessors() / 2);
    private final float[] levelRange = new float[2];
    private final int levels;
    private final int rootRadius;
    private final Consumer<String> progress;
    /** Per level L and level k: how far from a level-L block the sky's search reads level k, metres (0: not). */
    private final double[][] skyReach;
    /** Where the camera was at the last step; null before the first. */
    private CameraPose last;

    /**
     * Makes the bands and the quadtree, and the clipmap empty; the first {@link #follow} fills it around the camera,
     * wherever its direction put it.
     *
     * @param cells N, the cells per patch side
     */
    public StreamedWorld(TerrainSettings s, int seed, int cells, StageTimes times, Consumer<String> progress) {
        heights = times.time("bands", () -> ErodedWorld.unbounded(s, seed));
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
        rootRadius = (int) Math.ceil(CopyLattice.COPY_DISTANCE / tree.extent());
        int size = clipSize(s, levels, heights.spacing(levels - 1), tree.extent(), rootRadius);
        // at low priority: the frame's own thread comes first
        workers = (ThreadPoolExecutor) Executors.newFixedThreadPool(flightWorkers,
                Workers.named("terrain-blocks", Thread.MIN_PRIORITY));
        clipmap = new HeightClipmap(heights, levels, size, BLOCK, StreamedSnow.border(s), workers);
        this.progress = progress;
        skyReach = new double[levels][levels];
        for (int l = 0; l < levels; l++) {
            for (double r : HorizonSearch.distances(heights.spacing(l))) {
                int k = HorizonSearch.levelAt(r, l, levels, heights::spacing);
                skyReach[l][k] = Math.max(skyReach[l][k], r);
            }
        }
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
     * Once per simulation step: moves the windows with the camera (ahead of it by its velocity since the last step)
     * and hands the blocks finished since to {@code sink}, a few per step. A jump (a shot's pose, a cut in a camera
     * path: more than a quarter of level 0's window in one step) is no flight to stream behind: it waits, as the
     * start does, until every window around the new place is full.
     */
    public void follow(CameraPose pose, double step, HeightClipmap.BlockSink sink) {
        if (last == null || Math.hypot(pose.x() - last.x(), pose.z() - last.z())
                > clipmap.size() / 4.0 * heights.spacing(0)) {
            fill(pose, sink);
            return;
        }
        double vx = step > 0 ? (pose.x() - last.x()) / step : 0;
        double vz = step > 0 ? (pose.z() - last.z()) / step : 0;
        last = pose;
        clipmap.follow(pose.x(), pose.z(), vx, vz);
        clipmap.drain(UPLOADS_PER_FRAME, sink);
    }

    /**
     * Follows the camera, waiting until every level's whole window around it is resident: on every core, as nothing
     * else runs meanwhile (the waiting thread only uploads, a quarter of the time).
     */
    private void fill(CameraPose pose, HeightClipmap.BlockSink sink) {
        long start = System.nanoTime();
        int cores = Runtime.getRuntime().availableProcessors();
        workers.setMaximumPoolSize(cores);
        workers.setCorePoolSize(cores);
        clipmap.follow(pose.x(), pose.z(), 0, 0);
        last = pose;
        while (!clipmap.complete()) {
            if (clipmap.drain(Integer.MAX_VALUE, sink) == 0) {
                try {
                    Thread.sleep(1);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IllegalStateException("interrupted while streaming the terrain", e);
                }
            }
        }
        workers.setCorePoolSize(flightWorkers); // the extra threads end as they next fall idle
        workers.setMaximumPoolSize(flightWorkers);
        progress.accept(String.format(Locale.ROOT, "terrain: %-10s %7.0f ms", "streaming",
                (System.nanoTime() - start) / 1e6));
    }

    /**
     * Whether a node of the root at (offsetX, offsetZ) can be drawn: its own level and every coarser one it may read
     * (the next for morphing, up to log2 N coarser along a stitched side) are resident over its samples and the
     * row and column beyond its far sides, which its last vertices read.
     */
    @Override
    public boolean drawable(int node, float offsetX, float offsetZ) {
        return levelsOf(node, offsetX, offsetZ, null, false);
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
        return levelsOf(node, offsetX, offsetZ, out, false) && widenByError(node, out);
    }

    /**
     * As {@link #heightRange}, the levels' heights taken over the clipmap's cells ({@link ClipmapLevel#CELL} samples
     * a side) the node touches rather than over its whole blocks: what the culling tests a node's box with. A
     * block of level L + log2 N spans 64 of that level's samples, 2^(log2 N + 1) = 64 times a level-L node's side,
     * so block ranges make every node's heights those of the land far around it (a leaf's −190 .. 840 m where the
     * sea meets the hills); the cells' are 8 times closer. The level rule and the drawing order keep the blocks'
     * ranges, so this changes no patch drawn.
     */
    boolean cullRange(int node, float offsetX, float offsetZ, float[] out) {
        out[0] = Float.POSITIVE_INFINITY;
        out[1] = Float.NEGATIVE_INFINITY;
        return levelsOf(node, offsetX, offsetZ, out, true) && widenByError(node, out);
    }

    /**
     * What the culling tests the roots with: each node's {@link #cullRange}, and whether it may be split (all four
     * children {@linkplain #drawable drawable}): the level choice splits a node into no child whose heights have
     * not arrived, so below such a node nothing is drawn on its own, and the culling need not descend.
     */
    public NodeHeights cullHeights() {
        return new NodeHeights() {
            @Override
            public boolean range(int node, float offsetX, float offsetZ, float[] out) {
                return cullRange(node, offsetX, offsetZ, out);
            }

            @Override
            public boolean splits(int node, float offsetX, float offsetZ) {
                int first = tree.bounds().firstChild(node);
                for (int child = first; child < first + 4; child++) {
                    if (!drawable(child, offsetX, offsetZ)) {
                        return false;
                    }
                }
                return true;
            }
        };
    }

    /** Widens a node's range by its level's error: the finer levels below it lie within it of its surface. */
    private boolean widenByError(int node, float[] out) {
        float error = tree.error(node);
        out[0] -= error;
        out[1] += error;
        return true;
    }

    /**
     * Whether the node's levels are resident; with {@code range}, their heights' union (of the blocks touched, or
     * with {@code cells} of their cells) widened into it.
     */
    private boolean levelsOf(int node, float offsetX, float offsetZ, float[] range, boolean cells) {
        int level = tree.level(node);
        long originX = rootOrigin(offsetX) + tree.sampleX(node);
        long originZ = rootOrigin(offsetZ) + tree.sampleZ(node);
        long span = (long) tree.cells() << level;
        int coarsest = Math.min(levels - 1, level + tree.cellsLog2());
        for (int l = level; l <= coarsest; l++) {
            long x0 = originX >> l;
            long z0 = originZ >> l;
            long x1 = ((originX + span) >> l) + 1;
            long z1 = ((originZ + span) >> l) + 1;
            if (range == null ? !clipmap.resident(l, x0, z0, x1, z1)
                    : cells ? !clipmap.cellRange(l, x0, z0, x1, z1, levelRange)
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

    /** Whether level {@code level}'s block (bx, bz) is resident: its slot holds it. */
    boolean holds(int level, long bx, long bz) {
        return clipmap.resident(level, bx * BLOCK, bz * BLOCK, (bx + 1) * BLOCK, (bz + 1) * BLOCK);
    }

    /**
     * Whether the heights the sky's search ({@link StreamedSky}) reads from level {@code level}'s block (bx, bz) have
     * arrived: on each level k it reads, the samples within its reach on k of the block, as far as k's window
     * holds them (what lies beyond a window is not waited for: the search falls back on a coarser level there).
     */
    boolean skyReady(int level, long bx, long bz) {
        double d = heights.spacing(level);
        int size = clipmap.size();
        for (int k = level; k < levels; k++) {
            double reach = skyReach[level][k];
            if (reach == 0) {
                continue;
            }
            double dk = heights.spacing(k);
            // level-k samples from reach before the block's first to the one after reach beyond its last
            long x0 = Math.max(clipmap.windowX(k), (long) Math.floor((bx * BLOCK * d - reach) / dk));
            long z0 = Math.max(clipmap.windowZ(k), (long) Math.floor((bz * BLOCK * d - reach) / dk));
            long x1 = Math.min(clipmap.windowX(k) + size, end(bx, d, reach, dk));
            long z1 = Math.min(clipmap.windowZ(k) + size, end(bz, d, reach, dk));
            if (x0 < x1 && z0 < z1 && !clipmap.resident(k, x0, z0, x1, z1)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The order in which level {@code level}'s block (bx, bz) is wanted, smallest first: nearest the camera by its
     * level's blocks, then coarser levels first, the order the clipmap makes blocks in (so, about, the order a
     * pass comes to draw them).
     */
    long priority(int level, long bx, long bz) {
        return clipmap.priority(level, bx, bz);
    }

    /** One past the last level-k sample (dk apart) a search reaching {@code reach} from block b (d apart) reads. */
    private static long end(long b, double d, double reach, double dk) {
        return (long) Math.floor(((b + 1) * BLOCK * d + reach) / dk) + 2;
    }

    /**
     * The world's level-0 sample index of the north-west corner of the root whose centre lies at this offset,
     * metres, on either axis: roots lie on a lattice of their own side, so the offset is a whole number of samples
     * (terrain.vert's worldOrigin).
     */
    public long rootOrigin(float offset) {
        return Math.round(offset / heights.spacing(0)) - tree.size() / 2;
    }

    /** Roots drawn on each side of the camera's: enough to reach {@link CopyLattice#COPY_DISTANCE}. */
    public int rootRadius() {
        return rootRadius;
    }

    public TerrainQuadtree tree() {
        return tree;
    }

    public UniformHeights heights() {
        return heights;
    }

    /** The levels streamed: 0 to the roots' level. */
    public int levels() {
        return levels;
    }

    /** Samples per side of every level's window. */
    public int clipSize() {
        return clipmap.size();
    }

    /** The border of samples each block comes with. */
    public int border() {
        return clipmap.border();
    }

    /** Bytes the three texture arrays take on the GPU. */
    long textureBytes() {
        return clipmap.textureBytes() / Float.BYTES * TEXEL_BYTES;
    }

    @Override
    public void close() {
        clipmap.close();
        workers.shutdownNow();
    }
}
