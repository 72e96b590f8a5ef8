package org.openworld.engine.erosion;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.function.Supplier;

/**
 * The eroded regions of one level, least recently used first out: a region is made once by the first thread that
 * asks for it, any other asking meanwhile waits for that one, and one dropped is made again, to the same bits, if it
 * is asked for later (a region is a pure function of its place and the seed).
 */
final class RegionCache {

    /** A region's place: its centre's sample index on its level, divided by the regions' spacing. */
    private record Key(long x, long z) {
    }

    private final Map<Key, FutureTask<Region>> regions;

    /** @param capacity regions kept at most */
    RegionCache(int capacity) {
        regions = new LinkedHashMap<>(2 * capacity, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<Key, FutureTask<Region>> eldest) {
                return size() > capacity;
            }
        };
    }

    /** The region at (x, z), made by {@code make} on the calling thread if no thread has made or is making it. */
    Region get(long x, long z, Supplier<Region> make) {
        Key key = new Key(x, z);
        FutureTask<Region> task;
        boolean mine = false;
        synchronized (regions) {
            task = regions.get(key);
            if (task == null) {
                task = new FutureTask<>(make::get);
                regions.put(key, task);
                mine = true;
            }
        }
        if (mine) {
            task.run();
        }
        try {
            return task.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for an eroded region", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("eroding a region failed", e.getCause());
        }
    }

    /** Regions held now. */
    int size() {
        synchronized (regions) {
            return regions.size();
        }
    }
}
