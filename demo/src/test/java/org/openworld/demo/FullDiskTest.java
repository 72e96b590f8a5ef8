package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.bench.BenchReport;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.bench.MemoryUse;
import org.openworld.engine.bench.RunInfo;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;
import org.openworld.engine.gl.Image;

/**
 * Outputs written onto a full disk: a small tmpfs is mounted, the earlier output written on it, the rest of it
 * filled, and the command run again. Each write must fail the command (exit 2, one line: the file the user named and
 * the operating system's "No space left on device") and leave the earlier output byte for byte, with no hidden
 * temporary file or folder behind. Mounting needs root (or CAP_SYS_ADMIN): elsewhere the tests are skipped, saying
 * so.
 */
class FullDiskTest {

    /** The disk's size: room for the earlier outputs (heightmap's three maps of a 256² world take ~190 KiB). */
    private static final String DISK_SIZE = "1m";
    /** The strerror(ENOSPC) text the JDK passes on. */
    private static final String NO_SPACE = "No space left on device";

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    private Path disk;
    private boolean mounted;

    @BeforeEach
    void mountSmallDisk() throws Exception {
        disk = Files.createDirectories(dir.resolve("disk"));
        Process mount = new ProcessBuilder("mount", "-t", "tmpfs", "-o", "size=" + DISK_SIZE, "tmpfs",
                disk.toString()).redirectErrorStream(true).start();
        String said = new String(mount.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        mounted = mount.waitFor(30, TimeUnit.SECONDS) && mount.exitValue() == 0;
        Assumptions.assumeTrue(mounted, "cannot mount a tmpfs here (it needs root or CAP_SYS_ADMIN): " + said);
    }

    @AfterEach
    void unmount() throws Exception {
        if (mounted) {
            new ProcessBuilder("umount", "--lazy", disk.toString()).inheritIO().start().waitFor(30, TimeUnit.SECONDS);
        }
    }

    @Test
    void aPictureOnAFullDiskFailsAndKeepsTheEarlierOne() throws Exception {
        Path a = noise(dir.resolve("a.png"), 1);
        Path b = noise(dir.resolve("b.png"), 2);
        Path out = disk.resolve("x.png");
        new Image(4, 2, new byte[4 * 2 * 4]).writePng(out);
        byte[] earlier = Files.readAllBytes(out);
        fill();

        int code = Main.execute("diff", a.toString(), b.toString(), "--out", out.toString());

        assertOneLineFailure(code, out);
        assertArrayEquals(earlier, Files.readAllBytes(out), "the earlier picture is kept whole");
        assertOnlyEarlierFiles("x.png");
    }

    @Test
    void heightmapOnAFullDiskFailsAndKeepsTheEarlierMaps() throws Exception {
        Path maps = disk.resolve("maps");
        assertEquals(0, Main.execute("heightmap", "--out", maps.toString(), "--set", "terrain.size=256"),
                console.stderr());
        byte[] earlier = Files.readAllBytes(maps.resolve(HeightmapCommand.HEIGHT_PNG));
        fill();

        int code = Main.execute("heightmap", "--out", maps.toString(), "--seed", "9", "--set", "terrain.size=256");

        assertOneLineFailure(code, maps.resolve(HeightmapCommand.HEIGHT_PNG));
        assertArrayEquals(earlier, Files.readAllBytes(maps.resolve(HeightmapCommand.HEIGHT_PNG)));
        try (Stream<Path> left = Files.list(maps)) {
            assertEquals(List.of(), left.filter(p -> p.getFileName().toString().startsWith(".")).toList(),
                    "no temporary file left beside the maps");
        }
    }

    @Test
    void aBenchRunOnAFullDiskFailsAndKeepsTheEarlierRun() throws Exception {
        Path run = disk.resolve("run");
        RunInfo info = new RunInfo("test renderer", "3.3 test", "headless-egl", 64, 36, 1L, Map.of(), "t.path", 0,
                false);
        MemoryUse memory = new MemoryUse(1.0, 1.0, 1.0, null, null, null, 1.0, 1.0);
        BenchReport.write(info, frames(2), memory, run, true);
        byte[] earlier = Files.readAllBytes(run.resolve(BenchReport.SUMMARY_JSON));
        fill();

        IOException failure = assertThrows(IOException.class,
                () -> BenchReport.write(info, frames(2000), memory, run, true));

        assertTrue(failure.getMessage().startsWith(run.toString()) && failure.getMessage().contains(NO_SPACE),
                failure.getMessage());
        assertTrue(failure instanceof UserFacing f && f.exitCode() == ExitCode.USER_MISTAKE, "exit 2: " + failure);
        assertArrayEquals(earlier, Files.readAllBytes(run.resolve(BenchReport.SUMMARY_JSON)));
        assertOnlyEarlierFiles("run");
    }

    private void assertOneLineFailure(int code, Path named) {
        String err = console.stderr();
        assertEquals(ExitCode.USER_MISTAKE.code(), code, err);
        assertEquals(1, err.lines().count(), "one line: " + err);
        assertTrue(err.contains(named.toString()) && err.contains(NO_SPACE), err);
    }

    /** The disk holds the earlier output and the filler, and nothing a failed write left. */
    private void assertOnlyEarlierFiles(String earlier) throws IOException {
        try (Stream<Path> left = Files.list(disk)) {
            assertEquals(List.of(earlier, "filler"), left.map(p -> p.getFileName().toString()).sorted(
                    (x, y) -> x.equals(earlier) ? -1 : y.equals(earlier) ? 1 : x.compareTo(y)).toList());
        }
    }

    /** Writes zeros until the disk refuses, so that no page of it is left. */
    private void fill() throws IOException {
        byte[] block = new byte[4096];
        try (OutputStream filler = Files.newOutputStream(disk.resolve("filler"))) {
            while (true) {
                filler.write(block);
                filler.flush();
            }
        } catch (IOException full) {
            assertTrue(String.valueOf(full.getMessage()).contains(NO_SPACE), full.toString());
        }
    }

    /** A picture of random pixels (seeded): incompressible, so its PNG needs room on any disk. */
    private static Path noise(Path file, long seed) throws IOException {
        byte[] rgba = new byte[64 * 36 * 4];
        new Random(seed).nextBytes(rgba);
        new Image(64, 36, rgba).writePng(file);
        return file;
    }

    private static List<FrameRecord> frames(int count) {
        return java.util.stream.IntStream.range(0, count).mapToObj(i -> new FrameRecord(i, i / 60.0, 5.0, 4.0,
                Map.of("terrain", 2.0), Map.of("terrain", 3.0), 1000, 10, Map.of())).toList();
    }
}
