package org.openworld.engine.core;

import java.util.function.Supplier;
import org.visnow.jlargearrays.ConcurrencyUtils;

/**
 * JTransforms' thread count, pinned while a system's FFT runs. JTransforms picks different code paths by that count,
 * which is one global number, so every user of the FFT (the terrain's spectral synthesis, its material textures'
 * noise and its power spectrum, the sky's clouds, the water's ripples) runs its transforms through {@link #pinned}:
 * with {@link #COUNT} threads, under one lock, the count restored afterwards. A seed then gives the same field bit
 * for bit on any number of cores.
 */
public final class FftThreads {

    /** Two threads use both cores of a small machine; more buy little for one-off transforms at start-up. */
    public static final int COUNT = 2;

    private FftThreads() {
    }

    /** Runs {@code work} with JTransforms' thread count pinned to {@link #COUNT}, and returns its result. */
    public static <T> T pinned(Supplier<T> work) {
        synchronized (ConcurrencyUtils.class) {
            int saved = ConcurrencyUtils.getNumberOfThreads();
            ConcurrencyUtils.setNumberOfThreads(COUNT);
            try {
                return work.get();
            } finally {
                ConcurrencyUtils.setNumberOfThreads(saved);
            }
        }
    }

    /** Runs {@code work} with JTransforms' thread count pinned to {@link #COUNT}. */
    public static void pinned(Runnable work) {
        pinned(() -> {
            work.run();
            return null;
        });
    }
}
