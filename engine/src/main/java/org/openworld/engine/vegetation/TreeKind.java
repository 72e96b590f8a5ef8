package org.openworld.engine.vegetation;

/**
 * The kinds of plant, each with its own shapes ({@link TreeShape}) and its size as a share of the settings' tree
 * heights.
 */
enum TreeKind {
    /** Spruce-like: a trunk under stacked cones of needles. */
    CONIFER(1.0, 0.45),
    /** Beech- or oak-like: a trunk under a round crown of leaf clumps. */
    BROADLEAF(0.8, 0.6),
    /** Undergrowth and forest edges: a low mound of leaves, a sixth of a tree's height (1.3-4 m at the defaults). */
    BUSH(0.16, 1.0);

    /** Height as a share of the drawn tree height. */
    final double scale;
    /**
     * The widest reach from the foot, as a share of the plant's own height: its shape's, widened by the shader's
     * widest variant and leaned by the strongest wind (tree.vert), rounded up.
     */
    final double reach;

    TreeKind(double scale, double reach) {
        this.scale = scale;
        this.reach = reach;
    }
}
