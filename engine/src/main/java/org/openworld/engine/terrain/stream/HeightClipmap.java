package org.openworld.engine.terrain.stream;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import org.openworld.engine.terrain.heights.HeightSource;
import org.openworld.engine.terrain.stream.ClipmapLevel.Slot;

/**
 * The unbounded world's heights around the camera: for each level L of {@link org.openworld.engine.terrain.heights.BandedHeights}, a window of {@code size
 * × size} samples d_L apart, kept in a texture-shaped array that never moves; the window moves over it, and only the
 * blocks it uncovers are made, on worker threads, and handed to the GL thread in small pieces.
 *
 * <h2>Toroidal storage</h2>
 * Level-L sample (ix, iz), the one at world (ix · d_L, iz · d_L), lives at texel
 * {@code (ix & (size − 1), iz & (size − 1))}: {@code size} is a power of two, so the mask is the index modulo
 * {@code size}, and any {@code size} consecutive indices fill every texel once. A shader therefore reads a sample by
 * its world index alone, with no offset to keep in step, and moving the window by k samples rewrites only the k
 * columns that left it: they become the new columns on the other side. The window is cut into {@code block × block}
 * blocks aligned to multiples of {@code block}; a block fills one block-aligned square of texels, its
 * <em>slot</em>, the unit of work, residency and upload.
 *
 * <h2>Where each window lies</h2>
 * Level L's window covers samples {@code [c − size/2, c + size/2)} on each axis, c a multiple of {@code block} (so
 * the window is exactly {@code size/block} blocks a side; {@code size ≥ 4 · block}, see below). Per axis, the window
 * aims at a point ahead of the camera by its velocity, t = p + lead, p the camera and
 * {@code lead = clamp(v · T / d_L, ±(size/4 − block))} with T = {@value #LOOKAHEAD_SECONDS} s, all in level-L
 * samples: the ground the camera reaches in the next seconds is made first, without letting the camera near the
 * edge. With hysteresis, c moves only when |t − c| ≥ {@code block}, and then to the multiple of {@code block}
 * nearest t; a camera hovering, or moving less than a block, therefore causes no work. Between moves
 * |t − c| &lt; {@code block}, so |p − c| &lt; (size/4 − block) + block = size/4: the camera always lies more than
 * size/4 samples inside the window on every level. That needs the lead's bound size/4 − block to be at least 0,
 * hence {@code size ≥ 4 · block}; with the defaults (512, 64) the lead reaches 64 samples (a block), so the
 * centre lies 0 to 2 blocks ahead of a fast camera: 256 to 384 samples of the window ahead of it, 128 to 256
 * behind.
 *
 * <h2>Which blocks are made</h2>
 * When a window moves, each slot's wanted block is recomputed; a slot whose wanted block is unchanged keeps its
 * texels and stays resident. A slot whose wanted block changed gets a new generation number and is queued, unless
 * its texels already hold that block (the window came back before the slot was overwritten). Until the new block is
 * drained, {@link #resident} is false over it: the texels still hold the old place. A block is the exact window
 * {@code heights.level(L, bx · block − b, bz · block − b, block + 2b)}, b its {@link #border()}; one finished for a
 * generation no longer its slot's (the camera moved on) is dropped, and a worker skips a job gone stale while it
 * waited. Every height being a pure function of (L, ix, iz), the texels are the same bits whatever path the camera
 * took, in whatever order blocks were made, on whatever thread.
 *
 * <h2>Order of work</h2>
 * Blocks are made and drained nearest first, by their ring around the camera: the Chebyshev distance, in blocks of
 * their own level, from the block holding the camera to theirs, {@code max(|bx − cbx|, |bz − cbz|)}; within a ring
 * coarser levels first. Every level thus fills outwards from the camera at once (ring 0 of all levels, then ring 1,
 * ...), and the coarse ground that stands in for missing fine ground is never last. The queue is re-sorted at every
 * {@link #follow} that leaves work queued; at the first, every block of every level is queued.
 *
 * <h2>Bounded work in flight</h2>
 * At most {@code 2 × availableProcessors} jobs are out at once: on the executor (running or waiting) or finished and
 * not yet drained, stale ones included; the rest wait in this class's own queue, which holds slots, not heights. The
 * workers therefore never run more than about one job per thread ahead of the uploads, and
 * {@link #pendingBytes()} stays at most {@link #maxPendingBytes()} = {@code 2 × processors × (block + 2b)² × 4}
 * bytes whatever the speed of flight (113 KiB on 2 processors with block 64 and the border of 10 the unbounded
 * world's snow needs). A fast camera makes the queue long, not the heap big.
 *
 * <h2>Threads</h2>
 * Everything but {@code heights.level} and a block's min/max runs on one thread (the GL thread). A worker hands its
 * result over through a {@link ConcurrentLinkedQueue}; a slot's generation is volatile, the one field workers read.
 * Nothing waits: {@link #drain} takes what has finished and returns.
 *
 * <h2>Cost</h2>
 * Texture: {@code levels · size² · 4} bytes ({@link #textureBytes()}, 8 MiB for 8 levels of 512²). A block: its
 * heights (border too) of one 16-sample B-spline per band at or above its level: measured on one core of a 2-core
 * machine with the border of 10 (84² samples), 1.95 ms for a 64² block of level 0 (9 bands), 0.57 ms of level 7
 * (2 bands); with a one-sample border (66²) they were 1.2 and 0.35 ms, the cost growing with the samples made. The
 * whole default clipmap (8 levels of 512², 512 blocks) fills in 0.37 s on 2 workers once warm (0.25 s with the
 * one-sample border). Flying at speed v along an axis, level L uncovers a column of
 * {@code size/block} blocks every {@code block · d_L} metres; summed over levels that is under
 * {@code 2 · v · (size/block) / (block · d_0)} blocks per second: 37 a second at 300 m/s with the defaults (2 m,
 * 512, 64), about 70 ms of one core per second of flight. In a 10 s flight at 300 m/s, draining 4 blocks a frame,
 * level 0 within 128 m of the camera was resident in all 600 frames.
 *
 * <h2>Limits</h2>
 * Level L's window spans {@code size · d_L} metres (1 km for level 0 with the defaults, 131 km for level 7); what
 * lies beyond the coarsest window is not held. If the camera outruns the workers or the uploads, blocks near it are
 * not yet resident and the drawing must fall back to a coarser level, which fills first by the order above.
 */
public final class HeightClipmap implements AutoCloseable {

    /** Seconds of flight by which each window's centre leads the camera, before the clamp to size/4 − block. */
    static final double LOOKAHEAD_SECONDS = 2;
    /** The largest size {@link #sizeFor} picks: 4096² heights are 64 MiB a level. */
    static final int MAX_SIZE = 4096;
    /** The smallest window, in blocks a side, for which the camera can stay size/4 inside with hysteresis. */
    static final int MIN_BLOCKS = 4;

    /** Receives a finished block on the GL thread. */
    public interface BlockSink {
        /**
         * Uploads the block of level {@code level} whose first sample is (ix0, iz0): texel origin
         * {@code (texelX, texelZ) = (ix0 & (size − 1), iz0 & (size − 1))} of level {@code level}'s
         * layer. {@code heights} holds the block with a border of {@link #border()} samples on every side,
         * row-major, {@code (block + 2 · border)²}, rows along z, starting at sample (ix0 − border, iz0 − border):
         * the border lets the sink filter up to the block's own edges without its neighbours (slopes by central
         * differences, the snow's morphology and blur).
         */
        void upload(int level, long ix0, long iz0, int texelX, int texelZ, int block, float[] heights);
    }

    private final HeightSource heights;
    private final int size;
    private final int block;
    private final int border;
    private final ExecutorService workers;
    private final int maxInFlight;
    private final ClipmapLevel[] levels;
    /** Slots waiting for a job, sorted worst first so that the best is taken from the end. */
    private final List<Slot> queued = new ArrayList<>();
    /** Finished jobs taken from {@link #finished} and not yet handed to a sink. */
    private final List<Finished> ready = new ArrayList<>();
    private final Queue<Finished> finished = new ConcurrentLinkedQueue<>();
    /** Jobs submitted and not yet drained or dropped: on the executor, in {@link #finished} or in {@link #ready}. */
    private int outstanding;
    private double cameraX;
    private double cameraZ;
    private boolean placed;
    private volatile boolean closed;

    /**
     * A clipmap of {@code levels} levels of {@code heights}, windows {@code size} samples a side made of
     * {@code block}-sample blocks, computed on {@code workers} (not owned: {@link #close} does not shut it down).
     */
    public HeightClipmap(HeightSource heights, int levels, int size, int block, int border,
                         ExecutorService workers) {
        if (levels < 1 || levels > heights.levels()) {
            throw new IllegalArgumentException("a height clipmap needs 1 .. " + heights.levels()
                    + " levels (the world's bands), got " + levels);
        }
        checkBlock(block);
        if (border < 0 || border > block) {
            throw new IllegalArgumentException("a block's border must be 0 .. " + block + " samples, got " + border);
        }
        if (Integer.bitCount(size) != 1 || size < MIN_BLOCKS * block) {
            throw new IllegalArgumentException("a height clipmap's size must be a power of two of at least "
                    + MIN_BLOCKS + " blocks (" + MIN_BLOCKS * block + " samples for blocks of " + block
                    + "), got " + size);
        }
        this.heights = heights;
        this.size = size;
        this.block = block;
        this.border = border;
        this.workers = workers;
        this.maxInFlight = 2 * Runtime.getRuntime().availableProcessors();
        this.levels = new ClipmapLevel[levels];
        for (int l = 0; l < levels; l++) {
            this.levels[l] = new ClipmapLevel(l, heights.spacing(l), size, block, LOOKAHEAD_SECONDS);
        }
    }

    /**
     * The largest power-of-two size, from {@code 4 · block} to {@value #MAX_SIZE}, whose texture
     * ({@code levels · size² · 4} bytes) fits {@code budgetBytes}.
     *
     * @throws IllegalArgumentException if even the smallest clipmap does not fit
     */
    public static int sizeFor(long budgetBytes, int levels, int block) {
        checkBlock(block);
        if (levels < 1) {
            throw new IllegalArgumentException("a height clipmap needs at least one level, got " + levels);
        }
        int smallest = MIN_BLOCKS * block;
        if (smallest > MAX_SIZE || textureBytes(levels, smallest) > budgetBytes) {
            long needs = textureBytes(levels, smallest);
            throw new IllegalArgumentException(String.format("a memory budget of %d bytes (%.1f MiB) is too small"
                    + " for the height clipmap: its smallest, %d levels of %d × %d heights, needs %d bytes (%.1f MiB)",
                    budgetBytes, budgetBytes / 1048576.0, levels, smallest, smallest, needs, needs / 1048576.0));
        }
        int size = smallest;
        while (size < MAX_SIZE && textureBytes(levels, 2 * size) <= budgetBytes) {
            size *= 2;
        }
        return size;
    }

    /**
     * Moves each level's window after the camera at (x, z) metres moving at (vx, vz) m/s, and queues the blocks it
     * now lacks. Once per frame, before {@link #drain}.
     */
    public void follow(double x, double z, double vx, double vz) {
        checkOpen();
        if (!(Double.isFinite(x) && Double.isFinite(z) && Double.isFinite(vx) && Double.isFinite(vz))) {
            throw new IllegalArgumentException("the camera's position and velocity must be finite, got ("
                    + x + ", " + z + ") and (" + vx + ", " + vz + ")");
        }
        cameraX = x;
        cameraZ = z;
        placed = true;
        for (ClipmapLevel level : levels) {
            level.follow(x, z, vx, vz, s -> {
                if (!s.queued) {
                    s.queued = true;
                    queued.add(s);
                }
            });
        }
        if (!queued.isEmpty()) {
            queued.sort(Comparator.comparingLong((Slot s) -> priority(s.level().index, s.wantedX(), s.wantedZ()))
                    .reversed());
            feed();
        }
    }

    /**
     * Hands at most {@code maxBlocks} finished blocks, best first, to {@code sink} on the calling thread, marks each
     * resident, and sends more work to the workers. Finished blocks that went stale are dropped. Returns how many
     * were handed over.
     */
    public int drain(int maxBlocks, BlockSink sink) {
        checkOpen();
        if (maxBlocks < 0) {
            throw new IllegalArgumentException("maxBlocks must not be negative, got " + maxBlocks);
        }
        for (Finished f = finished.poll(); f != null; f = finished.poll()) {
            ready.add(f);
        }
        ready.removeIf(f -> {
            boolean stale = f.slot.generation != f.generation;
            if (stale) {
                outstanding--;
            }
            return stale;
        });
        ready.sort(Comparator.comparingLong(f -> priority(f.slot.level().index, f.bx, f.bz)));
        int n = Math.min(maxBlocks, ready.size());
        for (Finished f : ready.subList(0, n)) {
            ClipmapLevel level = f.slot.level();
            sink.upload(level.index, f.bx * block, f.bz * block, level.texel(f.bx), level.texel(f.bz), block,
                    f.heights);
            f.slot.hold(f.bx, f.bz, f.heights, border);
            outstanding--;
        }
        ready.subList(0, n).clear();
        feed();
        return n;
    }

    /** True when every level-L sample in [ix0, ix1) × [iz0, iz1) is in the window and its block is uploaded. */
    public boolean resident(int level, long ix0, long iz0, long ix1, long iz1) {
        return range(level, ix0, iz0, ix1, iz1, null);
    }

    /**
     * The lowest and highest height of the resident blocks the rectangle touches, into out[0] and out[1]; false, out
     * untouched, when not all of it is {@link #resident}.
     */
    public boolean heightRange(int level, long ix0, long iz0, long ix1, long iz1, float[] out) {
        return range(level, ix0, iz0, ix1, iz1, out);
    }

    /** As {@link #heightRange}, from its blocks' {@value ClipmapLevel#CELL}-sample cells: tighter within a block. */
    public boolean cellRange(int level, long ix0, long iz0, long ix1, long iz1, float[] out) {
        if (ix1 <= ix0 || iz1 <= iz0) {
            throw new IllegalArgumentException("an empty rectangle of samples [" + ix0 + ", " + ix1 + ") × ["
                    + iz0 + ", " + iz1 + ")");
        }
        return level(level).cellRange(ix0, iz0, ix1, iz1, out);
    }

    /** True when every level's whole window is resident: nothing queued, computing or waiting to be drained. */
    public boolean complete() {
        for (ClipmapLevel level : levels) {
            if (!level.complete()) {
                return false;
            }
        }
        return true;
    }

    /** The first sample index along x of a level's window (its last is this + size − 1). */
    public long windowX(int level) {
        return placedLevel(level).windowX();
    }

    /** The first sample index along z of a level's window. */
    public long windowZ(int level) {
        return placedLevel(level).windowZ();
    }

    /** Bytes of heights held on the Java side now: jobs submitted and not yet drained, a block's bytes each. */
    public long pendingBytes() {
        return outstanding * blockBytes();
    }

    /** The bound on {@link #pendingBytes()}: 2 × processors blocks. */
    public long maxPendingBytes() {
        return maxInFlight * blockBytes();
    }

    /** A block's heights with their border, bytes. */
    private long blockBytes() {
        return (long) (block + 2 * border) * (block + 2 * border) * Float.BYTES;
    }

    public int size() {
        return size;
    }

    /** Samples of border every block is handed with, on each side. */
    public int border() {
        return border;
    }

    /** Bytes the GPU copy takes: levels · size² · 4. */
    public long textureBytes() {
        return textureBytes(levels.length, size);
    }

    /** Drops the queued work; jobs waiting on the executor skip their work. The executor is the caller's. */
    @Override
    public void close() {
        closed = true;
        queued.clear();
        ready.clear();
        finished.clear();
        outstanding = 0;
    }

    private static long textureBytes(int levels, int size) {
        return (long) levels * size * size * Float.BYTES;
    }

    private static void checkBlock(int block) {
        if (Integer.bitCount(block) != 1) {
            throw new IllegalArgumentException("a height clipmap's block must be a power of two, got " + block);
        }
    }

    private boolean range(int level, long ix0, long iz0, long ix1, long iz1, float[] out) {
        if (ix1 <= ix0 || iz1 <= iz0) {
            throw new IllegalArgumentException("an empty rectangle of samples [" + ix0 + ", " + ix1 + ") × ["
                    + iz0 + ", " + iz1 + ")");
        }
        return level(level).range(ix0, iz0, ix1, iz1, out);
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("the height clipmap is closed");
        }
    }

    private ClipmapLevel level(int level) {
        if (level < 0 || level >= levels.length) {
            throw new IllegalArgumentException("level " + level + " outside 0 .. " + (levels.length - 1));
        }
        return levels[level];
    }

    private ClipmapLevel placedLevel(int level) {
        if (!placed) {
            throw new IllegalStateException("the height clipmap has no window before its first follow");
        }
        return level(level);
    }

    /** The sort key of level {@code l}'s block: its ring around the camera's block first, then coarser levels first. */
    long priority(int l, long bx, long bz) {
        return level(l).ring(bx, bz, cameraX, cameraZ) * levels.length + (levels.length - 1 - l);
    }

    /** Sends the best queued slots to the workers while fewer than {@link #maxInFlight} jobs are out. */
    private void feed() {
        while (outstanding < maxInFlight && !queued.isEmpty()) {
            Slot s = queued.remove(queued.size() - 1);
            s.queued = false;
            if (s.resident()) {
                continue; // the window came back to the block the texels hold
            }
            int generation = s.generation;
            long bx = s.wantedX();
            long bz = s.wantedZ();
            outstanding++;
            workers.execute(() -> finished.add(compute(s, generation, bx, bz)));
        }
    }

    /** A worker's job: the block's heights, or nothing if it went stale while waiting. */
    private Finished compute(Slot slot, int generation, long bx, long bz) {
        if (closed || slot.generation != generation) {
            return new Finished(slot, generation, bx, bz, null);
        }
        int side = block + 2 * border;
        float[] h = heights.level(slot.level().index, bx * block - border, bz * block - border, side);
        return new Finished(slot, generation, bx, bz, h);
    }

    /** A worker's result for a slot's generation: the block's heights, or null heights if skipped. */
    private record Finished(Slot slot, int generation, long bx, long bz, float[] heights) {
    }
}
