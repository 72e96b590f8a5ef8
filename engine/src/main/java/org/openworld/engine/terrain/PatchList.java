package org.openworld.engine.terrain;

import java.util.Arrays;

/**
 * The patches to draw this frame, as a struct of arrays: what the renderer needs to place one patch's vertex grid
 * and pick its index patterns and sampled levels. Reused from frame to frame; it only grows, so once warm a frame
 * allocates nothing.
 *
 * <p>A vertex at grid (column, row) of patch i lies at level-0 sample
 * (originSampleX + column · sampleStep, originSampleZ + row · sampleStep) of the tile, in copy {@link #copy(int)}.
 * It samples pyramid level {@link #cornerLevel} at the four corners, {@link #sideLevel} elsewhere on a side, and
 * {@link #level} inside. The index patterns are {@link PatchPatterns#interior}({@link #strideLog2}) and, per side,
 * {@link PatchPatterns#edge}(side, {@link #strideLog2}, {@link #sideStrideLog2}).
 *
 * <p>Geomorphing: each patch carries its morph range ({@link #morphStart}, {@link #morphEnd}), and each side and
 * corner the range of the neighbour there that samples the same level, or {@link #NEVER} ({@link QuadtreeLod} says
 * how the shader combines them). A patch that does not morph has {@link #NEVER} everywhere.
 */
public final class PatchList {

    private static final int SIDES = 4;

    /** A morph range that never starts: both ends here, beyond any distance, so the morph factor stays 0. */
    public static final float NEVER = 1e30f;

    private int size;
    private int[] node = new int[0];
    private int[] copy = new int[0];
    private int[] originSampleX = new int[0];
    private int[] originSampleZ = new int[0];
    private int[] sampleStep = new int[0];
    private int[] level = new int[0];
    private int[] strideLog2 = new int[0];
    private int[] sideLevel = new int[0];
    private int[] sideStrideLog2 = new int[0];
    private int[] cornerLevel = new int[0];
    /** Per patch: start, end (metres). */
    private float[] morph = new float[0];
    /** Per patch × side and patch × corner: start, end (metres). */
    private float[] sideMorph = new float[0];
    private float[] cornerMorph = new float[0];

    public int size() {
        return size;
    }

    /** Empties the list, keeping its storage. */
    public void clear() {
        size = 0;
    }

    /** The quadtree node drawn (a leaf in flat-grid mode): the index to read its culling result with. */
    public int node(int i) {
        return node[i];
    }

    /** Which copy of the tile the patch belongs to (index into the selection's offsets). */
    public int copy(int i) {
        return copy[i];
    }

    /** Level-0 sample index (column, in the tile) of grid vertex (0, 0). */
    public int originSampleX(int i) {
        return originSampleX[i];
    }

    /** Level-0 sample index (row, in the tile) of grid vertex (0, 0). */
    public int originSampleZ(int i) {
        return originSampleZ[i];
    }

    /** Level-0 samples between adjacent grid vertices: 2^L in quadtree mode, 1 in flat-grid mode. */
    public int sampleStep(int i) {
        return sampleStep[i];
    }

    /** Pyramid level sampled by the interior vertices. */
    public int level(int i) {
        return level[i];
    }

    /** Own stride of the patch's index patterns: 0 in quadtree mode, L in flat-grid mode. */
    public int strideLog2(int i) {
        return strideLog2[i];
    }

    /** Pyramid level sampled by the vertices of one side, corners excepted: the coarser of the two patches there. */
    public int sideLevel(int i, Side s) {
        return sideLevel[SIDES * i + s.ordinal()];
    }

    /** Outer stride of the side's edge pattern, at least {@link #strideLog2(int)}. */
    public int sideStrideLog2(int i, Side s) {
        return sideStrideLog2[SIDES * i + s.ordinal()];
    }

    /** Pyramid level sampled by a corner vertex: the coarsest of the up to four patches touching that point. */
    public int cornerLevel(int i, Corner c) {
        return cornerLevel[SIDES * i + c.ordinal()];
    }

    /** Viewer distance, metres, where the patch starts morphing towards its parent's surface. */
    public float morphStart(int i) {
        return morph[2 * i];
    }

    /** Viewer distance, metres, where the patch is its parent's surface: where it merges into its parent. */
    public float morphEnd(int i) {
        return morph[2 * i + 1];
    }

    /** Morph start of the neighbour across a side that samples the side's level, or {@link #NEVER}. */
    public float sideMorphStart(int i, Side s) {
        return sideMorph[2 * (SIDES * i + s.ordinal())];
    }

    /** Morph end of the neighbour across a side that samples the side's level, or {@link #NEVER}. */
    public float sideMorphEnd(int i, Side s) {
        return sideMorph[2 * (SIDES * i + s.ordinal()) + 1];
    }

    /** Morph start of the patch diagonally across a corner when it samples the corner's level, or {@link #NEVER}. */
    public float cornerMorphStart(int i, Corner c) {
        return cornerMorph[2 * (SIDES * i + c.ordinal())];
    }

    /** Morph end of the patch diagonally across a corner when it samples the corner's level, or {@link #NEVER}. */
    public float cornerMorphEnd(int i, Corner c) {
        return cornerMorph[2 * (SIDES * i + c.ordinal()) + 1];
    }

    /** Turns morphing off for every patch ({@code lod.morph=off}): each draws its own level's surface. */
    public void withoutMorph() {
        Arrays.fill(morph, 0, 2 * size, NEVER);
        Arrays.fill(sideMorph, 0, 2 * SIDES * size, NEVER);
        Arrays.fill(cornerMorph, 0, 2 * SIDES * size, NEVER);
    }

    /** Appends a patch whose sides and corners are then set with {@link #setSide} and {@link #setCorner}. */
    int add(int node, int copy, int originSampleX, int originSampleZ, int sampleStep, int level, int strideLog2) {
        if (size == this.node.length) {
            grow(Math.max(64, 2 * size));
        }
        int i = size++;
        this.node[i] = node;
        this.copy[i] = copy;
        this.originSampleX[i] = originSampleX;
        this.originSampleZ[i] = originSampleZ;
        this.sampleStep[i] = sampleStep;
        this.level[i] = level;
        this.strideLog2[i] = strideLog2;
        Arrays.fill(morph, 2 * i, 2 * i + 2, NEVER);
        Arrays.fill(sideMorph, 2 * SIDES * i, 2 * SIDES * (i + 1), NEVER);
        Arrays.fill(cornerMorph, 2 * SIDES * i, 2 * SIDES * (i + 1), NEVER);
        return i;
    }

    void setMorph(int i, float start, float end) {
        morph[2 * i] = start;
        morph[2 * i + 1] = end;
    }

    void setSideMorph(int i, Side s, float start, float end) {
        sideMorph[2 * (SIDES * i + s.ordinal())] = start;
        sideMorph[2 * (SIDES * i + s.ordinal()) + 1] = end;
    }

    void setCornerMorph(int i, Corner c, float start, float end) {
        cornerMorph[2 * (SIDES * i + c.ordinal())] = start;
        cornerMorph[2 * (SIDES * i + c.ordinal()) + 1] = end;
    }

    void setSide(int i, Side s, int level, int strideLog2) {
        sideLevel[SIDES * i + s.ordinal()] = level;
        sideStrideLog2[SIDES * i + s.ordinal()] = strideLog2;
    }

    void setCorner(int i, Corner c, int level) {
        cornerLevel[SIDES * i + c.ordinal()] = level;
    }

    private void grow(int capacity) {
        node = Arrays.copyOf(node, capacity);
        copy = Arrays.copyOf(copy, capacity);
        originSampleX = Arrays.copyOf(originSampleX, capacity);
        originSampleZ = Arrays.copyOf(originSampleZ, capacity);
        sampleStep = Arrays.copyOf(sampleStep, capacity);
        level = Arrays.copyOf(level, capacity);
        strideLog2 = Arrays.copyOf(strideLog2, capacity);
        sideLevel = Arrays.copyOf(sideLevel, SIDES * capacity);
        sideStrideLog2 = Arrays.copyOf(sideStrideLog2, SIDES * capacity);
        cornerLevel = Arrays.copyOf(cornerLevel, SIDES * capacity);
        morph = Arrays.copyOf(morph, 2 * capacity);
        sideMorph = Arrays.copyOf(sideMorph, 2 * SIDES * capacity);
        cornerMorph = Arrays.copyOf(cornerMorph, 2 * SIDES * capacity);
    }
}
