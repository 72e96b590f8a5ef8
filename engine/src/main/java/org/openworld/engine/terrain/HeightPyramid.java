package org.openworld.engine.terrain;

import java.util.List;

/**
 * The height map at every power-of-two resolution (paper 2.5): level 0 is the map itself, level k+1 is level k
 * low-pass filtered with a Gaussian and then decimated by two, so it holds no detail finer than its own sample
 * spacing ({@code spacing · 2^k}) and a patch drawn at level k shows heights, not aliases. Geomipmapping samples
 * level L for a patch of level L.
 */
public final class HeightPyramid {

    private final List<HeightMap> levels;

    /** @param levels level 0 first; each half the size and twice the spacing of the one before */
    public HeightPyramid(List<HeightMap> levels) {
        for (int k = 1; k < levels.size(); k++) {
            if (levels.get(k).size() * 2 != levels.get(k - 1).size()) {
                throw new IllegalArgumentException("pyramid level " + k + " must be half the size of level " + (k - 1));
            }
        }
        this.levels = List.copyOf(levels);
    }

    public HeightMap level(int k) {
        return levels.get(k);
    }

    public int levelCount() {
        return levels.size();
    }

    public HeightMap base() {
        return levels.get(0);
    }
}
