package org.openworld.engine.terrain.stream;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.TestTerrain;

/**
 * The height clipmap without GL: its blocks are the world's levels bit for bit whatever the flight, only what a
 * move uncovers is made, stale blocks never arrive, the windows lead the camera and keep it inside, the work in
 * flight stays bounded, blocks arrive nearest first.
 */
class HeightClipmapTest {

    private static final BandedHeights WORLD = new BandedHeights(TestTerrain.settings(), 1);
    private static final int LEVELS = 4;
    private static final int SIZE = 64;
    private static final int BLOCK = 8;
    /** Samples of border each block carries (the unbounded world's snow needs ten). */
    private static final int BORDER = 3;
    private static final int BLOCKS = (SIZE / BLOCK) * (SIZE / BLOCK);
    /** A point where every level's window is centred exactly: a multiple of the coarsest level's block, metres. */
    private static final double ALIGNED = 40 * BLOCK * 16.0;
    private static final long DRAIN_TIMEOUT_NANOS = TimeUnit.SECONDS.toNanos(10);

    private ThreadPoolExecutor workers;

    @BeforeEach
    void startWorkers() {
        workers = (ThreadPoolExecutor) Executors.newFixedThreadPool(2);
    }

    @AfterEach
    void stopWorkers() throws InterruptedException {
        workers.shutdownNow();
        assertTrue(workers.awaitTermination(10, TimeUnit.SECONDS), "workers stopped");
    }

    /**
     * Each block handed over is heights.level of its place, with its border; the window is resident,
     * and no sample beyond it.
     */
    @Test
    void drainedBlocksAreTheWorldsLevelsBitForBit() throws InterruptedException {
        try (HeightClipmap clipmap = clipmap()) {
            clipmap.follow(1234.5, -5678.9, 0, 0);
            Texture texture = new Texture();
            drainAll(clipmap, texture);
            assertEquals(LEVELS * BLOCKS, texture.uploads.size(), "one upload per block of every level");
            for (Upload u : texture.uploads) {
                long ix0 = sampleOf(clipmap.windowX(u.level), u.texelX);
                long iz0 = sampleOf(clipmap.windowZ(u.level), u.texelZ);
                assertArrayEquals(WORLD.level(u.level, ix0 - BORDER, iz0 - BORDER, BLOCK + 2 * BORDER), u.heights,
                        "level " + u.level + " block at " + ix0 + ", " + iz0);
            }
            assertTextureIsTheWorld(clipmap, texture);
            for (int level = 0; level < LEVELS; level++) {
                long x0 = clipmap.windowX(level);
                long z0 = clipmap.windowZ(level);
                long x1 = x0 + SIZE;
                long z1 = z0 + SIZE;
                assertTrue(clipmap.resident(level, x0, z0, x1, z1), "level " + level + "'s window");
                assertFalse(clipmap.resident(level, x0 - 1, z0, x1, z1), "one sample west of level " + level);
                assertFalse(clipmap.resident(level, x0, z0 - 1, x1, z1), "one sample north of level " + level);
                assertFalse(clipmap.resident(level, x0, z0, x1 + 1, z1), "one sample east of level " + level);
                assertFalse(clipmap.resident(level, x0, z0, x1, z1 + 1), "one sample south of level " + level);
                assertFalse(clipmap.resident(level, x1, z0, x1 + 1, z0 + 1), "the first sample east of level " + level);
            }
        }
    }

    /**
     * A straight flight 5 km east, draining 3 blocks a frame, and a zigzag to the same point, draining 2 and
     * sometimes everything, leave the texture bit for bit as a clipmap made there from nothing.
     */
    @Test
    void twoDifferentFlightsLeaveTheSameTexels() throws InterruptedException {
        double endX = ALIGNED + 5120;
        double endZ = ALIGNED;
        Texture straight = new Texture();
        Texture zigzag = new Texture();
        Texture fresh = new Texture();
        try (HeightClipmap a = clipmap(); HeightClipmap b = clipmap(); HeightClipmap c = clipmap()) {
            for (int step = 0; step <= 80; step++) {
                a.follow(ALIGNED + 64 * step, ALIGNED, 300, 0);
                a.drain(3, straight);
            }
            for (int step = 0; step <= 37; step++) {
                double x = ALIGNED + 5120 * step / 37.0;
                double z = ALIGNED + (step % 2 == 0 ? 300 : -300);
                b.follow(x, z, 200, step % 2 == 0 ? -600 : 600);
                if (step % 5 == 0) {
                    drainAll(b, zigzag);
                } else {
                    b.drain(2, zigzag);
                }
            }
            a.follow(endX, endZ, 0, 0);
            b.follow(endX, endZ, 0, 0);
            c.follow(endX, endZ, 0, 0);
            drainAll(a, straight);
            drainAll(b, zigzag);
            drainAll(c, fresh);
            for (int level = 0; level < LEVELS; level++) {
                assertEquals(c.windowX(level), a.windowX(level), "level " + level + "'s window after the flight");
                assertEquals(c.windowX(level), b.windowX(level), "level " + level + "'s window after the zigzag");
                assertEquals(TestTerrain.bitsHash(fresh.texels[level]), TestTerrain.bitsHash(straight.texels[level]),
                        "level " + level + " after the straight flight");
                assertEquals(TestTerrain.bitsHash(fresh.texels[level]), TestTerrain.bitsHash(zigzag.texels[level]),
                        "level " + level + " after the zigzag");
            }
            assertTextureIsTheWorld(c, fresh);
        }
    }

    /**
     * Three level-0 blocks east: what the old and new windows share stays resident and is not made again, the new
     * strip is not resident until drained, and exactly its blocks arrive.
     */
    @Test
    void movingAFewBlocksRemakesOnlyTheNewStrip() throws InterruptedException {
        try (HeightClipmap clipmap = clipmap()) {
            clipmap.follow(ALIGNED, ALIGNED, 0, 0);
            drainAll(clipmap, new Texture());
            long[] before = new long[LEVELS];
            for (int level = 0; level < LEVELS; level++) {
                before[level] = clipmap.windowX(level);
            }
            clipmap.follow(ALIGNED + 3 * BLOCK * WORLD.spacing(0), ALIGNED, 0, 0);
            assertEquals(before[0] + 3 * BLOCK, clipmap.windowX(0), "level 0 moved three blocks");
            int uncovered = 0;
            for (int level = 0; level < LEVELS; level++) {
                long x0 = clipmap.windowX(level);
                long z0 = clipmap.windowZ(level);
                assertTrue(x0 >= before[level], "level " + level + "'s window moves east or stays");
                if (x0 > before[level]) {
                    assertFalse(clipmap.resident(level, before[level] + SIZE, z0, x0 + SIZE, z0 + SIZE),
                            "level " + level + "'s new strip before it is drained");
                    assertTrue(clipmap.resident(level, x0, z0, before[level] + SIZE, z0 + SIZE),
                            "level " + level + "'s samples in both windows");
                } else {
                    assertTrue(clipmap.resident(level, x0, z0, x0 + SIZE, z0 + SIZE), "level " + level + " stayed");
                }
                uncovered += (int) (x0 - before[level]) / BLOCK * (SIZE / BLOCK);
            }
            Texture texture = new Texture();
            drainAll(clipmap, texture);
            assertEquals(uncovered, texture.uploads.size(), "blocks made after the move");
        }
    }

    /**
     * A move while the first jobs wait on a held worker: they are for the blocks around the camera, which stay in
     * the window, so they are kept, and every block is made exactly once (a move that restarted every slot's job
     * would make them twice). The move uncovers level 0's east column, far from the camera and not yet started.
     */
    @Test
    void aMoveKeepsTheJobsForBlocksThatStay() throws InterruptedException {
        ThreadPoolExecutor one = (ThreadPoolExecutor) Executors.newFixedThreadPool(1);
        CountDownLatch hold = new CountDownLatch(1);
        try (HeightClipmap clipmap = new HeightClipmap(WORLD, LEVELS, SIZE, BLOCK, BORDER, one)) {
            one.execute(() -> {
                try {
                    hold.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            clipmap.follow(ALIGNED, ALIGNED, 0, 0);
            long before = clipmap.windowX(0);
            clipmap.follow(ALIGNED + BLOCK * WORLD.spacing(0), ALIGNED, 0, 0);
            assertEquals(before + BLOCK, clipmap.windowX(0), "level 0 moved a block");
            hold.countDown();
            Texture texture = new Texture();
            drainAll(clipmap, texture);
            assertEquals(LEVELS * BLOCKS, texture.uploads.size(), "blocks uploaded");
            assertEquals(1 + LEVELS * BLOCKS, one.getTaskCount(), "jobs given to the worker, after the one holding it");
        } finally {
            one.shutdownNow();
            assertTrue(one.awaitTermination(10, TimeUnit.SECONDS), "the worker stopped");
        }
    }

    /**
     * Blocks made for a window the camera left at once never arrive: P's first blocks are finished and waiting
     * when the camera jumps 100 km, and only Q's blocks reach the sink, each once.
     */
    @Test
    void blocksForAWindowLeftBehindAreDropped() throws InterruptedException {
        try (HeightClipmap clipmap = clipmap()) {
            clipmap.follow(0, 0, 0, 0);
            long deadline = System.nanoTime() + DRAIN_TIMEOUT_NANOS;
            while (workers.getCompletedTaskCount() < workers.getTaskCount()) {
                if (System.nanoTime() > deadline) {
                    fail("the first jobs did not finish in 10 s");
                }
                Thread.sleep(1);
            }
            assertTrue(clipmap.pendingBytes() > 0, "P's finished blocks wait to be drained");
            clipmap.follow(100_000, 0, 0, 0);
            Texture texture = new Texture();
            drainAll(clipmap, texture);
            assertEquals(LEVELS * BLOCKS, texture.uploads.size(), "Q's blocks, each once");
            for (Upload u : texture.uploads) {
                long ix0 = sampleOf(clipmap.windowX(u.level), u.texelX);
                long iz0 = sampleOf(clipmap.windowZ(u.level), u.texelZ);
                assertArrayEquals(WORLD.level(u.level, ix0 - BORDER, iz0 - BORDER, BLOCK + 2 * BORDER), u.heights,
                        "level " + u.level + " block at texel " + u.texelX + ", " + u.texelZ + " belongs to Q");
            }
        }
    }

    /**
     * At 300 m/s east every window reaches further east of the camera than west (and the reverse flying west);
     * over a random flight of 500 frames up to 1 000 m/s, the camera stays more than size/4 inside every window.
     */
    @Test
    void theWindowsLeadAFastCameraAndKeepItInside() {
        try (HeightClipmap clipmap = clipmap()) {
            for (double vx : new double[] {300, -300}) {
                clipmap.follow(ALIGNED + vx * 10, ALIGNED, vx, 0);
                for (int level = 0; level < LEVELS; level++) {
                    double p = (ALIGNED + vx * 10) / WORLD.spacing(level);
                    double east = clipmap.windowX(level) + SIZE - p;
                    double west = p - clipmap.windowX(level);
                    assertTrue((east - west) * vx > 0,
                            "level " + level + " at " + vx + " m/s: " + east + " samples east, " + west + " west");
                }
            }
            SplittableRandom random = new SplittableRandom(3);
            double x = 0;
            double z = 0;
            for (int frame = 0; frame < 500; frame++) {
                double speed = random.nextDouble(1000);
                double angle = random.nextDouble(2 * Math.PI);
                double vx = speed * Math.cos(angle);
                double vz = speed * Math.sin(angle);
                x += vx / 60;
                z += vz / 60;
                clipmap.follow(x, z, vx, vz);
                for (int level = 0; level < LEVELS; level++) {
                    double d = WORLD.spacing(level);
                    double margin = Math.min(
                            Math.min(x / d - clipmap.windowX(level), clipmap.windowX(level) + SIZE - x / d),
                            Math.min(z / d - clipmap.windowZ(level), clipmap.windowZ(level) + SIZE - z / d));
                    assertTrue(margin > SIZE / 4.0, "frame " + frame + ", level " + level + ": the camera is "
                            + margin + " samples inside");
                }
            }
        }
    }

    /**
     * 2 000 frames at 300 m/s (10 km), draining 2 blocks a frame: the heights held on the Java side never pass the
     * stated bound of 2 × processors blocks, and the clipmap still fills where the flight ends.
     */
    @Test
    void pendingBytesStayBoundedOnALongFastFlight() throws InterruptedException {
        try (HeightClipmap clipmap = clipmap()) {
            int side = BLOCK + 2 * BORDER;
            assertEquals(2L * Runtime.getRuntime().availableProcessors() * side * side * Float.BYTES,
                    clipmap.maxPendingBytes(), "the bound: 2 × processors blocks of floats, borders included");
            Texture texture = new Texture();
            long peak = 0;
            double x = 0;
            for (int frame = 0; frame < 2000; frame++) {
                x += 300.0 / 60;
                clipmap.follow(x, 0, 300, 0);
                clipmap.drain(2, texture);
                peak = Math.max(peak, clipmap.pendingBytes());
                assertTrue(clipmap.pendingBytes() <= clipmap.maxPendingBytes(),
                        "frame " + frame + ": " + clipmap.pendingBytes() + " bytes pending");
            }
            assertTrue(peak > 0, "work was in flight");
            clipmap.follow(x, 0, 0, 0);
            drainAll(clipmap, texture);
            assertTextureIsTheWorld(clipmap, texture);
        }
    }

    /** The largest power of two whose texture fits, from 4 blocks to 4096; too small a budget says what it needs. */
    @Test
    void sizeForPicksTheLargestPowerOfTwoInTheBudget() {
        long mib = 1 << 20;
        assertEquals(512, HeightClipmap.sizeFor(8 * mib, 8, 64), "8 levels of 512² are exactly 8 MiB");
        assertEquals(256, HeightClipmap.sizeFor(8 * mib - 1, 8, 64), "a byte less");
        assertEquals(1024, HeightClipmap.sizeFor(100 * mib, 8, 64), "100 MiB: 32 MiB fits, 128 MiB does not");
        assertEquals(4096, HeightClipmap.sizeFor(1L << 40, 8, 64), "no larger than 4096");
        assertEquals(256, HeightClipmap.sizeFor(2 * mib, 8, 64), "the smallest, 4 blocks a side");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> HeightClipmap.sizeFor(2 * mib - 1, 8, 64));
        assertTrue(e.getMessage().contains("2097151 bytes") && e.getMessage().contains("needs 2097152 bytes"),
                e.getMessage());
    }

    /** heightRange is the min and max of the drained blocks a rectangle touches; false and untouched elsewhere. */
    @Test
    void heightRangeIsTheRangeOfTheDrainedBlocks() throws InterruptedException {
        try (HeightClipmap clipmap = clipmap()) {
            clipmap.follow(-777, 4321, 0, 0);
            drainAll(clipmap, new Texture());
            int level = 1;
            long x0 = clipmap.windowX(level) + 5;
            long z0 = clipmap.windowZ(level) + 3;
            long x1 = x0 + 17;
            long z1 = z0 + 9;
            float min = Float.POSITIVE_INFINITY;
            float max = Float.NEGATIVE_INFINITY;
            for (long bz = Math.floorDiv(z0, BLOCK); bz <= Math.floorDiv(z1 - 1, BLOCK); bz++) {
                for (long bx = Math.floorDiv(x0, BLOCK); bx <= Math.floorDiv(x1 - 1, BLOCK); bx++) {
                    for (float h : WORLD.level(level, bx * BLOCK, bz * BLOCK, BLOCK)) {
                        min = Math.min(min, h);
                        max = Math.max(max, h);
                    }
                }
            }
            float[] out = new float[2];
            assertTrue(clipmap.heightRange(level, x0, z0, x1, z1, out), "a rectangle inside the window");
            assertArrayEquals(new float[] {min, max}, out, "min and max of the blocks it touches");
            float[] untouched = {Float.NaN, Float.NaN};
            assertFalse(clipmap.heightRange(level, x0 - SIZE, z0, x1, z1, untouched), "reaching beyond the window");
            assertArrayEquals(new float[] {Float.NaN, Float.NaN}, untouched, "out is left alone");
            clipmap.follow(-777 + 2 * SIZE * WORLD.spacing(LEVELS - 1), 4321, 0, 0);
            long nx = clipmap.windowX(level);
            long nz = clipmap.windowZ(level);
            assertFalse(clipmap.heightRange(level, nx, nz, nx + BLOCK, nz + BLOCK, untouched), "not yet drained");
            assertArrayEquals(new float[] {Float.NaN, Float.NaN}, untouched, "out is left alone");
        }
    }

    /**
     * The stated order, seen with one worker (which finishes jobs in the order given): by ring of blocks around the
     * camera's block, and within a ring coarser levels first; so the first blocks are the camera's own on every
     * level, coarsest first.
     */
    @Test
    void blocksArriveNearestFirstAndCoarserLevelsFirst() throws InterruptedException {
        ExecutorService one = Executors.newSingleThreadExecutor();
        try (HeightClipmap clipmap = new HeightClipmap(WORLD, LEVELS, SIZE, BLOCK, BORDER, one)) {
            double x = 1000.3;
            double z = -2000.7;
            clipmap.follow(x, z, 0, 0);
            List<Long> keys = new ArrayList<>();
            Texture texture = new Texture();
            long deadline = System.nanoTime() + DRAIN_TIMEOUT_NANOS;
            while (!clipmap.complete()) {
                int from = texture.uploads.size();
                if (clipmap.drain(1, texture) == 0) {
                    assertTrue(System.nanoTime() < deadline, "filled within 10 s");
                    Thread.sleep(1);
                }
                for (Upload u : texture.uploads.subList(from, texture.uploads.size())) {
                    double extent = WORLD.spacing(u.level) * BLOCK;
                    long bx = Math.floorDiv(sampleOf(clipmap.windowX(u.level), u.texelX), BLOCK);
                    long bz = Math.floorDiv(sampleOf(clipmap.windowZ(u.level), u.texelZ), BLOCK);
                    long ring = Math.max(Math.abs(bx - (long) Math.floor(x / extent)),
                            Math.abs(bz - (long) Math.floor(z / extent)));
                    keys.add(ring * LEVELS + (LEVELS - 1 - u.level));
                }
            }
            assertEquals(LEVELS * BLOCKS, keys.size(), "every block");
            for (int i = 1; i < keys.size(); i++) {
                assertTrue(keys.get(i - 1) <= keys.get(i), "upload " + i + " (ring, level) order: " + keys);
            }
            for (int i = 0; i < LEVELS; i++) {
                assertEquals(LEVELS - 1 - i, texture.uploads.get(i).level, "upload " + i + " is ring 0's");
                assertEquals(i, keys.get(i), "upload " + i + " is the camera's own block");
            }
        } finally {
            one.shutdownNow();
            assertTrue(one.awaitTermination(10, TimeUnit.SECONDS), "the worker stopped");
        }
    }

    /** Jitter of under half a block and slow drift move no window: nothing is queued, made or uploaded. */
    @Test
    void aHoveringCameraCausesNoWork() throws InterruptedException {
        try (HeightClipmap clipmap = clipmap()) {
            clipmap.follow(ALIGNED, ALIGNED, 0, 0);
            drainAll(clipmap, new Texture());
            long window = clipmap.windowX(0);
            SplittableRandom random = new SplittableRandom(9);
            Texture texture = new Texture();
            double jitter = 0.45 * BLOCK * WORLD.spacing(0);
            for (int frame = 0; frame < 300; frame++) {
                double x = ALIGNED + random.nextDouble(-jitter, jitter);
                double z = ALIGNED + random.nextDouble(-jitter, jitter);
                clipmap.follow(x, z, random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                assertEquals(0, clipmap.pendingBytes(), "frame " + frame + ": nothing in flight");
                assertEquals(0, clipmap.drain(8, texture), "frame " + frame + ": nothing uploaded");
            }
            assertEquals(window, clipmap.windowX(0), "level 0's window stayed");
            assertTrue(clipmap.complete(), "still resident");
        }
    }

    /** Impossible shapes are refused with a message that names the rule. */
    @Test
    void badShapesAreRefusedClearly() {
        assertMessage("power of two", () -> new HeightClipmap(WORLD, LEVELS, 96, BLOCK, BORDER, workers));
        assertMessage("at least 4 blocks", () -> new HeightClipmap(WORLD, LEVELS, 16, BLOCK, BORDER, workers));
        assertMessage("block must be a power of two",
                () -> new HeightClipmap(WORLD, LEVELS, SIZE, 6, BORDER, workers));
        assertMessage("border must be 0 .. " + BLOCK,
                () -> new HeightClipmap(WORLD, LEVELS, SIZE, BLOCK, BLOCK + 1, workers));
        assertMessage("1 .. " + WORLD.levels() + " levels",
                () -> new HeightClipmap(WORLD, 0, SIZE, BLOCK, BORDER, workers));
        assertMessage("1 .. " + WORLD.levels() + " levels",
                () -> new HeightClipmap(WORLD, WORLD.levels() + 1, SIZE, BLOCK, BORDER, workers));
        try (HeightClipmap clipmap = clipmap()) {
            assertMessage("must be finite", () -> clipmap.follow(Double.NaN, 0, 0, 0));
            assertMessage("empty rectangle", () -> clipmap.resident(0, 5, 0, 5, 1));
        }
    }

    /** Closing drops the queued work and later calls to follow or drain say the clipmap is closed. */
    @Test
    void closingDropsTheQueuedWork() {
        HeightClipmap clipmap = clipmap();
        clipmap.follow(0, 0, 0, 0);
        assertTrue(clipmap.pendingBytes() > 0, "work in flight before closing");
        clipmap.close();
        assertEquals(0, clipmap.pendingBytes(), "nothing held after closing");
        assertThrows(IllegalStateException.class, () -> clipmap.follow(0, 0, 0, 0));
        assertThrows(IllegalStateException.class, () -> clipmap.drain(1, new Texture()));
    }

    private HeightClipmap clipmap() {
        return new HeightClipmap(WORLD, LEVELS, SIZE, BLOCK, BORDER, workers);
    }

    private static void assertMessage(String part, Runnable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call::run);
        assertTrue(e.getMessage().contains(part), e.getMessage());
    }

    /** Drains until every window is resident, waiting for the workers; fails after 10 s. */
    private static void drainAll(HeightClipmap clipmap, HeightClipmap.BlockSink sink) throws InterruptedException {
        long deadline = System.nanoTime() + DRAIN_TIMEOUT_NANOS;
        while (!clipmap.complete()) {
            if (clipmap.drain(Integer.MAX_VALUE, sink) == 0) {
                if (System.nanoTime() > deadline) {
                    fail("the clipmap did not fill in 10 s; " + clipmap.pendingBytes() + " bytes pending");
                }
                Thread.sleep(1);
            }
        }
    }

    /** The world sample index of a window's sample on a texel: the one index in the window congruent to it. */
    private static long sampleOf(long windowStart, int texel) {
        return windowStart + ((texel - windowStart) & (SIZE - 1));
    }

    /** Every texel of every level holds heights.level at the window's sample that falls on it. */
    private static void assertTextureIsTheWorld(HeightClipmap clipmap, Texture texture) {
        for (int level = 0; level < LEVELS; level++) {
            long x0 = clipmap.windowX(level);
            long z0 = clipmap.windowZ(level);
            float[] world = WORLD.level(level, x0, z0, SIZE);
            float[] expected = new float[SIZE * SIZE];
            for (int j = 0; j < SIZE; j++) {
                for (int i = 0; i < SIZE; i++) {
                    int texel = (int) ((z0 + j) & (SIZE - 1)) * SIZE + (int) ((x0 + i) & (SIZE - 1));
                    expected[texel] = world[j * SIZE + i];
                }
            }
            assertArrayEquals(expected, texture.texels[level], "level " + level + "'s texels");
        }
    }

    private record Upload(int level, int texelX, int texelZ, float[] heights) {
    }

    /** The GL texture's stand-in: each level's texels, filled by the uploads, and the uploads in order. */
    private static final class Texture implements HeightClipmap.BlockSink {
        final float[][] texels = new float[LEVELS][SIZE * SIZE];
        final List<Upload> uploads = new ArrayList<>();

        @Override
        public void upload(int level, long ix0, long iz0, int texelX, int texelZ, int block, float[] heights) {
            assertEquals(texelX, (int) (ix0 & (SIZE - 1)), "texel column of the block's first sample");
            assertEquals(texelZ, (int) (iz0 & (SIZE - 1)), "texel row of the block's first sample");
            uploads.add(new Upload(level, texelX, texelZ, heights));
            for (int j = 0; j < block; j++) { // the block without its border
                System.arraycopy(heights, (j + BORDER) * (block + 2 * BORDER) + BORDER, texels[level],
                        (texelZ + j) * SIZE + texelX, block);
            }
        }
    }
}
