package org.openworld.engine.terrain.lod;

import java.util.Arrays;

/**
 * The patches to draw this frame, as a struct of arrays: what the renderer needs to place one patch's vertex grid
 * and pick its index patterns and sampled levels. Reused from frame to frame; it only grows, so once warm a frame
 * allocates nothing.
 *
 * <p>A vertex at grid (column, row) of patch i lies at level-0 sample
 * (originSampleX + column · sampleStep, originSampleZ + row · sampleStep) of the tile, in copy {@link #copy(int)}.
 * It samples pyramid level {@link #cornerLevel} at the four corners, {@link #sideLevel} elsewhere on a side, and
 * {@link #level} inside. The index patterns are {@link org.openworld.engine.terrain.mesh.PatchPatterns#interior}({@link #strideLog2}) and, per side,
 * {@link org.openworld.engine.terrain.mesh.PatchPatterns#edge}(side, {@link #strideLog2}, {@link #sideStrideLog2}).
 *
 * <p>Geomorphing: each patch carries how far it has morphed towards its parent's surface ({@link #morph}, 0 to 1),
 * and each side and corner that of the neighbour there when it samples the same level, else 0 ({@link QuadtreeLod}
 * says how the shader combines them). A patch that does not morph has 0 everywhere.
 */
public final class PatchList {

    private static final int SIDES = 4;

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
    /** Per patch, per patch × side and per patch × corner: the morph factor k, 0 to 1. */
    private float[] morph = new float[0];
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

    /** How far the patch has morphed towards its parent's surface: 0 its own, 1 its parent's. */
    public float morph(int i) {
        return morph[i];
    }

    /** The morph factor of the neighbour across a side when it samples the side's level, else 0. */
    public float sideMorph(int i, Side s) {
        return sideMorph[SIDES * i + s.ordinal()];
    }

    /** The morph factor of the patch diagonally across a corner when it samples the corner's level, else 0. */
    public float cornerMorph(int i, Corner c) {
        return cornerMorph[SIDES * i + c.ordinal()];
    }

    /** Turns morphing off for every patch ({@code lod.morph=off}): each draws its own level's surface. */
    public void withoutMorph() {
        Arrays.fill(morph, 0, size, 0);
        Arrays.fill(sideMorph, 0, SIDES * size, 0);
        Arrays.fill(cornerMorph, 0, SIDES * size, 0);
    }

    /** Appends a patch whose sides and corners are then set with {@link #setSide} and {@link #setCorner}. */
    public int add(int node, int copy, int originSampleX, int originSampleZ, int sampleStep, int level, int strideLog2) {
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
        morph[i] = 0;
        Arrays.fill(sideMorph, SIDES * i, SIDES * (i + 1), 0);
        Arrays.fill(cornerMorph, SIDES * i, SIDES * (i + 1), 0);
        return i;
    }

    void setMorph(int i, float k) {
        morph[i] = k;
    }

    void setSideMorph(int i, Side s, float k) {
        sideMorph[SIDES * i + s.ordinal()] = k;
    }

    void setCornerMorph(int i, Corner c, float k) {
        cornerMorph[SIDES * i + c.ordinal()] = k;
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
        morph = Arrays.copyOf(morph, capacity);
        sideMorph = Arrays.copyOf(sideMorph, SIDES * capacity);
        cornerMorph = Arrays.copyOf(cornerMorph, SIDES * capacity);
    }
}
