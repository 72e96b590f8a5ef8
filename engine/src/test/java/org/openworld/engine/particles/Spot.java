package org.openworld.engine.particles;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import org.openworld.engine.gl.Image;

/**
 * A patch of pixels that one picture has and another lacks (4-connected, luma apart by more than
 * {@link #THRESHOLD}): what a snowflake adds to a frame.
 *
 * @param pixels how many pixels it covers
 * @param peak   its brightest luma in the picture that has it, 0–255
 * @param rim    its mean luma along its border (pixels with a neighbour outside it)
 */
record Spot(int pixels, int minX, int minY, int maxX, int maxY, double peak, double rim) {

    /** Luma difference that counts as changed, out of 255: above the noise of dithering and rounding. */
    static final double THRESHOLD = 4;

    int width() {
        return maxX - minX + 1;
    }

    int height() {
        return maxY - minY + 1;
    }

    /** The share of its bounding box it fills. */
    double fill() {
        return (double) pixels / (width() * height());
    }

    boolean touchesEdge(int w, int h) {
        return minX == 0 || minY == 0 || maxX == w - 1 || maxY == h - 1;
    }

    /** Every spot that {@code with} has and {@code without} lacks. */
    static List<Spot> find(Image with, Image without) {
        int w = with.width();
        int h = with.height();
        boolean[] changed = new boolean[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                changed[y * w + x] = with.luma(x, y) - without.luma(x, y) > THRESHOLD;
            }
        }
        boolean[] seen = new boolean[w * h];
        List<Spot> spots = new ArrayList<>();
        for (int start = 0; start < w * h; start++) {
            if (!changed[start] || seen[start]) {
                continue;
            }
            List<Integer> members = new ArrayList<>();
            Deque<Integer> todo = new ArrayDeque<>(List.of(start));
            seen[start] = true;
            while (!todo.isEmpty()) {
                int p = todo.pop();
                members.add(p);
                int x = p % w;
                int y = p / w;
                int[][] next = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
                for (int[] n : next) {
                    int q = n[1] * w + n[0];
                    if (n[0] >= 0 && n[0] < w && n[1] >= 0 && n[1] < h && changed[q] && !seen[q]) {
                        seen[q] = true;
                        todo.push(q);
                    }
                }
            }
            spots.add(measure(members, changed, with, w, h));
        }
        return spots;
    }

    private static Spot measure(List<Integer> members, boolean[] changed, Image with, int w, int h) {
        int minX = w;
        int minY = h;
        int maxX = 0;
        int maxY = 0;
        double peak = 0;
        double rimSum = 0;
        int rimCount = 0;
        for (int p : members) {
            int x = p % w;
            int y = p / w;
            minX = Math.min(minX, x);
            minY = Math.min(minY, y);
            maxX = Math.max(maxX, x);
            maxY = Math.max(maxY, y);
            peak = Math.max(peak, with.luma(x, y));
            boolean border = x == 0 || y == 0 || x == w - 1 || y == h - 1 || !changed[p - 1] || !changed[p + 1]
                    || !changed[p - w] || !changed[p + w];
            if (border) {
                rimSum += with.luma(x, y);
                rimCount++;
            }
        }
        return new Spot(members.size(), minX, minY, maxX, maxY, peak, rimSum / rimCount);
    }
}
