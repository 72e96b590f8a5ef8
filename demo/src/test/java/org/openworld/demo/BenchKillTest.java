package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.bench.BenchReport;
import org.openworld.engine.bench.FrameTimeChart;
import org.openworld.engine.bench.Summary;
import org.openworld.engine.bench.SummaryJson;
import org.openworld.engine.files.AtomicFiles;

/**
 * Nothing is lost when a bench is killed: a bench runs in a forked JVM (the test's own class path, the same headless
 * GL the tests use, chosen from the inherited environment) and is killed at a random moment (seeded) of its frames
 * or its write, 20 times, alternately by SIGKILL ({@link Process#destroyForcibly()}, no shutdown hook runs) and
 * SIGTERM ({@link Process#destroy()}). After each, {@code --out} holds the run that was there before, byte for byte,
 * or a new run whose three files agree; after SIGTERM during the frames, that new run is the partial one. The only
 * other state allowed is the one {@link AtomicFiles#replaceFolder} documents: a SIGKILL between its two renames
 * leaves the old run whole at {@link AtomicFiles#aside}, which the next run moves back.
 *
 * <p>Small on purpose: 64×36 pixels, a 256² world, water and shadows off, 240 frames (once the terrain and the sky got
 * cheaper, 60 frames at this size passed so quickly that all ten random SIGTERMs of a run could miss them), two
 * benches killed at once (each into its own folder), the forks started with C1 only. A fork spends most of its time starting the JVM and
 * making the world. Measured on the project's 2-core machine shared with other builds: 77 s at load average 5,
 * 144 s at load average 8 to 11 (174 s one fork at a time, with 100 frames); at that load a 1-frame bench took 3.5 s,
 * so the 22 forks cannot fit in a minute there.
 */
@Tag("gl")
class BenchKillTest {

    private static final long SEED = 18;
    private static final int KILLS = 20;
    private static final int FRAMES = 240;
    /** Benches killed at once, each into its own folder: most of a fork's time is its start, on one core. */
    private static final int LANES = 2;
    /** The forked bench prints this once its world is made, just before its first frame. */
    private static final String FRAMES_START = " warm-up + ";
    /** When the SIGTERM of the --discard-partial test comes: within its frames, after the first few. */
    private static final long DISCARD_AFTER_MS = 300;
    /** How long a fork may take to start rendering, or to end after a signal. */
    private static final long FORK_TIMEOUT_S = 60;

    @TempDir
    Path dir;

    @Test
    void aKilledBenchLeavesTheOldRunOrAWholeNewOne() throws Exception {
        long testStart = System.nanoTime();
        ExecutorService lanes = Executors.newFixedThreadPool(LANES);
        try {
            List<Future<Integer>> partialRuns = new ArrayList<>();
            for (int lane = 0; lane < LANES; lane++) {
                Path out = dir.resolve("run" + lane);
                Random random = new Random(SEED + lane);
                partialRuns.add(lanes.submit(() -> killRepeatedly(out, random, KILLS / LANES)));
            }
            int partial = 0;
            for (Future<Integer> lane : partialRuns) {
                partial += getOrRethrow(lane);
            }
            assertTrue(partial > 0, "no SIGTERM came during the frames: the partial run was never tested");
            System.out.printf("BenchKillTest: %d kills, %d partial runs, %.1f s%n", KILLS, partial,
                    (System.nanoTime() - testStart) / 1e9);
        } finally {
            lanes.shutdownNow();
        }
    }

    @Test
    void discardPartialKeepsTheEarlierRun() throws Exception {
        Path out = dir.resolve("run");
        Fork first = Fork.start(out);
        assertEquals(0, first.awaitExit(), first.output());
        Map<String, byte[]> before = snapshot(out);

        Fork fork = Fork.start(out, "--discard-partial");
        fork.awaitFrames();
        Thread.sleep(DISCARD_AFTER_MS);
        fork.process.destroy();
        assertEquals(143, fork.awaitExit(), fork.output());
        assertTrue(fork.output().contains("nothing written, " + out + " left as it was"), fork.output());
        assertTrue(sameFiles(before, snapshot(out)), fork.output());
    }

    /**
     * One lane: a complete run into {@code out}, then {@code kills} benches into the same folder, each killed at a
     * random moment between its first frame and a little after the complete run's end; returns how many partial
     * runs SIGTERM left.
     */
    private static int killRepeatedly(Path out, Random random, int kills) throws Exception {
        Fork first = Fork.start(out);
        long rendering = first.awaitFrames();
        assertEquals(0, first.awaitExit(), first.output());
        long runMs = (System.nanoTime() - rendering) / 1_000_000; // the frames and the write
        assertWholeRun(out, true, first.output());

        int partialRuns = 0;
        for (int kill = 0; kill < kills; kill++) {
            Map<String, byte[]> before = snapshot(out);
            boolean term = kill % 2 == 1;
            long delayMs = random.nextLong(runMs + runMs / 5);
            Fork fork = Fork.start(out);
            fork.awaitFrames();
            Thread.sleep(delayMs);
            if (term) {
                fork.process.destroy();
            } else {
                fork.process.destroyForcibly();
            }
            int exit = fork.awaitExit();
            String what = (term ? "SIGTERM" : "SIGKILL") + " after " + delayMs + " ms of " + runMs + ", exit " + exit
                    + ":\n" + fork.output();

            if (!Files.exists(out)) {
                assertEquals(List.copyOf(before.keySet()), List.copyOf(snapshot(AtomicFiles.aside(out)).keySet()),
                        what);
                assertTrue(AtomicFiles.recoverFolder(out), what);
            }
            Map<String, byte[]> after = snapshot(out);
            boolean partial = fork.output().contains("writing them as a partial run");
            if (!sameFiles(before, after)) {
                assertWholeRun(out, !partial, what);
            }
            if (term && exit != 0) {
                assertEquals(143, exit, what);
                if (partial) {
                    assertTrue(assertWholeRun(out, false, what).frames() < FRAMES, what);
                    partialRuns++;
                } else if (fork.output().contains("nothing written")) {
                    assertTrue(sameFiles(before, after), what);
                }
            }
        }
        return partialRuns;
    }

    private static int getOrRethrow(Future<Integer> lane) throws Exception {
        try {
            return lane.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw (Exception) e.getCause();
        }
    }

    /** The folder holds exactly a run's three files, and they agree: one frame count, a readable chart. */
    private static Summary assertWholeRun(Path out, boolean complete, String what) throws IOException {
        assertEquals(BenchReport.FILES.stream().sorted().toList(), List.copyOf(snapshot(out).keySet()), what);
        Summary summary = SummaryJson.read(out.resolve(BenchReport.SUMMARY_JSON));
        assertEquals(complete, summary.complete(), what);
        assertEquals(summary.frames() + 1, Files.readAllLines(out.resolve(BenchReport.FRAMES_CSV)).size(),
                () -> "frames.csv: a header and one line per frame of summary.json; " + what);
        BufferedImage chart = ImageIO.read(out.resolve(BenchReport.FRAMETIME_PNG).toFile());
        assertNotNull(chart, () -> "frametime.png is a readable picture; " + what);
        assertEquals(FrameTimeChart.WIDTH_PX, chart.getWidth());
        return summary;
    }

    private static Map<String, byte[]> snapshot(Path folder) throws IOException {
        Map<String, byte[]> files = new TreeMap<>();
        try (Stream<Path> list = Files.list(folder)) {
            for (Path file : list.toList()) {
                files.put(file.getFileName().toString(), Files.readAllBytes(file));
            }
        }
        return files;
    }

    private static boolean sameFiles(Map<String, byte[]> a, Map<String, byte[]> b) {
        return a.keySet().equals(b.keySet()) && a.keySet().stream().allMatch(k -> Arrays.equals(a.get(k), b.get(k)));
    }

    /**
     * One forked {@code openworld bench}, its output sent to a file: {@link Process#destroy()} closes the pipes of a
     * process, so output read through them would lose the lines printed after the signal, which tell what it did.
     */
    private record Fork(Process process, Path log) {

        /** How often the log is read while waiting for the frames to begin. */
        private static final long POLL_MS = 10;

        static Fork start(Path out, String... options) throws IOException {
            Path java = Path.of(System.getProperty("java.home"), "bin", "java");
            Path log = Files.createTempFile(out.toAbsolutePath().getParent(), "bench-", ".log");
            List<String> command = new ArrayList<>(List.of(java.toString(), "-Djava.awt.headless=true",
                    "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", // a quicker start; the timings are not tested
                    "-cp", System.getProperty("java.class.path"), Main.class.getName(), "bench",
                    "--path", "../assets/paths/orbit.path", "--size", "64x36", "--frames", Integer.toString(FRAMES),
                    "--warmup", "0", "--set", "terrain.world=tile", "--set", "terrain.size=256",
                    "--set", "system.water=off", "--set", "system.shadow=off", "--out", out.toString()));
            command.addAll(List.of(options));
            Process process = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile())
                    .start();
            return new Fork(process, log);
        }

        /** Waits until the fork starts its frames; returns when (System.nanoTime). */
        long awaitFrames() throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(FORK_TIMEOUT_S);
            while (!output().contains(FRAMES_START)) {
                assertTrue(process.isAlive() && System.nanoTime() < deadline, () -> "the bench never began:\n"
                        + output());
                Thread.sleep(POLL_MS);
            }
            return System.nanoTime();
        }

        /** Waits until the fork has ended; returns its exit code. */
        int awaitExit() throws InterruptedException {
            assertTrue(process.waitFor(FORK_TIMEOUT_S, TimeUnit.SECONDS), () -> "the bench did not end:\n" + output());
            return process.exitValue();
        }

        String output() {
            try {
                return Files.readString(log);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
    }
}
