package org.openworld.engine.terrain.stream;

import java.util.function.Consumer;

/**
 * One level of a {@link HeightClipmap}: where its window lies, which block each of its slots wants, and what each
 * slot's texels hold. The clipmap's javadoc explains the placement (lead, clamp, hysteresis) and the toroidal slots;
 * this class is their arithmetic, on the GL thread, apart from the one field workers read.
 */
final class ClipmapLevel {

    /**
     * Samples per side of the cells whose height range each slot keeps (or the block's side, if smaller): a
     * rectangle much smaller than a block (a quadtree node's on the coarser levels it reads) gets a range not much
     * wider than its own, for 2 floats per 64 samples.
     */
    static final int CELL = 8;

    final int index;
    final Slot[] slots;
    private final double spacing;
    private final int size;
    private final int block;
    /** {@link #CELL}, or the block's side if smaller. */
    private final int cell;
    private final int side;
    private final double lookahead;
    private long centreX;
    private long centreZ;
    private boolean placed;

    /** Level {@code index}, samples {@code spacing} metres apart, {@code size/block} slots a side. */
    ClipmapLevel(int index, double spacing, int size, int block, double lookaheadSeconds) {
        this.index = index;
        this.spacing = spacing;
        this.size = size;
        this.block = block;
        this.cell = Math.min(CELL, block);
        this.side = size / block;
        this.lookahead = lookaheadSeconds;
        slots = new Slot[side * side];
        for (int i = 0; i < slots.length; i++) {
            slots[i] = new Slot(i % side, i / side);
        }
    }

    /**
     * Aims the window at the camera (x, z) led by its velocity (vx, vz), in metres and m/s, and moves it if the aim
     * left its dead zone. Each slot whose wanted block changed gets a new generation; those whose texels do not hold
     * their new block go to {@code lacking}.
     */
    void follow(double x, double z, double vx, double vz, Consumer<Slot> lacking) {
        double reach = size / 4.0 - block;
        long cx = recentre(centreX, x / spacing + Math.max(-reach, Math.min(reach, vx * lookahead / spacing)));
        long cz = recentre(centreZ, z / spacing + Math.max(-reach, Math.min(reach, vz * lookahead / spacing)));
        if (placed && cx == centreX && cz == centreZ) {
            return;
        }
        long oldX = centreX;
        long oldZ = centreZ;
        boolean first = !placed;
        centreX = cx;
        centreZ = cz;
        placed = true;
        for (Slot s : slots) {
            if (first || wanted(oldX, s.sx) != wanted(cx, s.sx) || wanted(oldZ, s.sz) != wanted(cz, s.sz)) {
                s.generation++; // a job for the old block, waiting or finished, is now stale
                if (!s.resident()) {
                    lacking.accept(s);
                }
            }
        }
    }

    /** The first sample index of the window along x (it ends before this + size). */
    long windowX() {
        return centreX - size / 2;
    }

    /** The first sample index of the window along z. */
    long windowZ() {
        return centreZ - size / 2;
    }

    /** The texel of a block's first sample along one axis: {@code (b · block) & (size − 1)}. */
    int texel(long b) {
        return (int) (b * block & (size - 1));
    }

    /** The Chebyshev distance, in this level's blocks, from the block holding the camera (x, z) to block (bx, bz). */
    long ring(long bx, long bz, double x, double z) {
        double extent = spacing * block;
        return Math.max(Math.abs(bx - (long) Math.floor(x / extent)), Math.abs(bz - (long) Math.floor(z / extent)));
    }

    /** True when the whole window is resident. */
    boolean complete() {
        for (Slot s : slots) {
            if (!s.resident()) {
                return false;
            }
        }
        return placed;
    }

    /**
     * Whether every sample of [ix0, ix1) × [iz0, iz1) is in the window with its block uploaded; if so and
     * {@code out} is given, the lowest and highest height of the blocks it touches go to out[0], out[1].
     */
    boolean range(long ix0, long iz0, long ix1, long iz1, float[] out) {
        if (!placed || ix0 < windowX() || iz0 < windowZ() || ix1 > windowX() + size || iz1 > windowZ() + size) {
            return false;
        }
        float min = Float.POSITIVE_INFINITY;
        float max = Float.NEGATIVE_INFINITY;
        for (long bz = Math.floorDiv(iz0, block); bz <= Math.floorDiv(iz1 - 1, block); bz++) {
            for (long bx = Math.floorDiv(ix0, block); bx <= Math.floorDiv(ix1 - 1, block); bx++) {
                Slot s = slots[Math.floorMod(bz, side) * side + Math.floorMod(bx, side)];
                if (!s.holds(bx, bz)) {
                    return false;
                }
                min = Math.min(min, s.min);
                max = Math.max(max, s.max);
            }
        }
        if (out != null) {
            out[0] = min;
            out[1] = max;
        }
        return true;
    }

    /**
     * As {@link #range} with out given, but the lowest and highest height of the cells ({@link #CELL}) the
     * rectangle touches rather than of its blocks: a tighter range for a rectangle smaller than a block.
     */
    boolean cellRange(long ix0, long iz0, long ix1, long iz1, float[] out) {
        if (!placed || ix0 < windowX() || iz0 < windowZ() || ix1 > windowX() + size || iz1 > windowZ() + size) {
            return false;
        }
        int cells = block / cell;
        float min = Float.POSITIVE_INFINITY;
        float max = Float.NEGATIVE_INFINITY;
        for (long cz = Math.floorDiv(iz0, cell); cz <= Math.floorDiv(iz1 - 1, cell); cz++) {
            for (long cx = Math.floorDiv(ix0, cell); cx <= Math.floorDiv(ix1 - 1, cell); cx++) {
                long bx = Math.floorDiv(cx, cells);
                long bz = Math.floorDiv(cz, cells);
                Slot s = slots[Math.floorMod(bz, side) * side + Math.floorMod(bx, side)];
                if (!s.holds(bx, bz)) {
                    return false;
                }
                int c = (int) (cz - bz * cells) * cells + (int) (cx - bx * cells);
                min = Math.min(min, s.cellMin[c]);
                max = Math.max(max, s.cellMax[c]);
            }
        }
        out[0] = min;
        out[1] = max;
        return true;
    }

    /** The centre after the aim t: kept while within a block of t, else the multiple of block nearest t. */
    private long recentre(long centre, double t) {
        return placed && Math.abs(t - centre) < block ? centre : Math.round(t / block) * block;
    }

    /** Along one axis, the block of the window centred at {@code centre} that falls on slot column {@code slot}. */
    private long wanted(long centre, int slot) {
        long first = Math.floorDiv(centre - size / 2, block);
        return first + Math.floorMod(slot - first, side);
    }

    /** A block-sized square of texels, and what it holds. */
    final class Slot {
        final int sx;
        final int sz;
        /** Bumped on the GL thread each time the slot's wanted block changes; read by workers to skip stale jobs. */
        volatile int generation;
        /** In the clipmap's queue. */
        boolean queued;
        private boolean uploaded;
        private long heldX;
        private long heldZ;
        private float min;
        private float max;
        /** Per cell of the block ({@link #CELL}), row-major: its samples' lowest and highest height. */
        private final float[] cellMin;
        private final float[] cellMax;

        private Slot(int sx, int sz) {
            this.sx = sx;
            this.sz = sz;
            cellMin = new float[(block / cell) * (block / cell)];
            cellMax = new float[cellMin.length];
        }

        ClipmapLevel level() {
            return ClipmapLevel.this;
        }

        long wantedX() {
            return wanted(centreX, sx);
        }

        long wantedZ() {
            return wanted(centreZ, sz);
        }

        /** The texels hold the window's block for this slot. */
        boolean resident() {
            return placed && holds(wantedX(), wantedZ());
        }

        /**
         * Records that the texels now hold block (bx, bz), its heights given with {@code border} samples on each
         * side; keeps their range, the block's and each cell's.
         */
        void hold(long bx, long bz, float[] bordered, int border) {
            uploaded = true;
            heldX = bx;
            heldZ = bz;
            int cells = block / cell;
            int stride = block + 2 * border;
            java.util.Arrays.fill(cellMin, Float.POSITIVE_INFINITY);
            java.util.Arrays.fill(cellMax, Float.NEGATIVE_INFINITY);
            for (int j = 0; j < block; j++) {
                for (int i = 0; i < block; i++) {
                    float h = bordered[(j + border) * stride + i + border];
                    int c = (j / cell) * cells + i / cell;
                    cellMin[c] = Math.min(cellMin[c], h);
                    cellMax[c] = Math.max(cellMax[c], h);
                }
            }
            min = Float.POSITIVE_INFINITY;
            max = Float.NEGATIVE_INFINITY;
            for (int c = 0; c < cellMin.length; c++) {
                min = Math.min(min, cellMin[c]);
                max = Math.max(max, cellMax[c]);
            }
        }

        private boolean holds(long bx, long bz) {
            return uploaded && heldX == bx && heldZ == bz;
        }
    }
}
