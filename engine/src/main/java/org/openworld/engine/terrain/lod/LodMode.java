package org.openworld.engine.terrain.lod;

/**
 * Which level-of-detail scheme picks the terrain's patches ({@link LodScheme}); how fine each patch must be is the
 * {@link LodRule}'s.
 */
public enum LodMode {
    /**
     * A quadtree cut: far away, big nodes drawn with the same vertex grid at coarser sample spacing, so the patch
     * count grows with the logarithm of the world size ({@link QuadtreeLod}).
     */
    QUADTREE,
    /**
     * The paper's literal geomipmapping: a flat grid of equal patches, each drawing every 2^L-th vertex
     * ({@link FlatGridLod}); kept to reproduce the paper's figure 6.
     */
    FLAT_GRID
}
