package org.openworld.engine.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicFilesTest {

    @TempDir
    Path dir;

    @Test
    void aFileIsReplacedWholeAndNoTemporaryFileStays() throws IOException {
        Path file = Files.writeString(dir.resolve("a.txt"), "old");
        AtomicFiles.write(file, temp -> Files.writeString(temp, "new"));
        assertEquals("new", Files.readString(file));
        assertEquals(List.of("a.txt"), names(dir));
    }

    @Test
    void aFailedFileWriteLeavesTheOldFileAndNoTemporaryFile() throws IOException {
        Path file = Files.writeString(dir.resolve("a.txt"), "old");
        assertThrows(IOException.class, () -> AtomicFiles.write(file, temp -> {
            Files.writeString(temp, "half");
            throw new IOException("disk full");
        }));
        assertEquals("old", Files.readString(file));
        assertEquals(List.of("a.txt"), names(dir));
    }

    @Test
    void aFolderIsReplacedWithAllItsFilesAndKeepsWhatElseItHolds() throws IOException {
        Path run = oldRun();
        // a log still open for writing, as a shell's redirect into the run folder leaves it during the run
        try (var log = Files.newBufferedWriter(run.resolve("bench.log"))) {
            log.write("before ");
            log.flush();
            AtomicFiles.replaceFolder(run, fresh -> {
                Files.writeString(fresh.resolve("a.txt"), "new a");
                Files.writeString(fresh.resolve("b.txt"), "new b");
            });
            log.write("after");
        }
        assertEquals(List.of("a.txt", "b.txt", "bench.log"), names(run));
        assertEquals("new a", Files.readString(run.resolve("a.txt")), "the run's files are the new ones");
        assertEquals("new b", Files.readString(run.resolve("b.txt")));
        assertEquals("before after", Files.readString(run.resolve("bench.log")),
                "another file is kept, and an open one goes on being written in its new place");
        assertEquals(List.of("run"), names(dir), "no temporary or aside folder stays");
    }

    @Test
    void aFolderWriteFailingHalfWayLeavesTheOldFolderWhole() throws IOException {
        Path run = oldRun();
        assertThrows(IllegalStateException.class, () -> AtomicFiles.replaceFolder(run, fresh -> {
            Files.writeString(fresh.resolve("a.txt"), "new");
            throw new IllegalStateException("chart failed");
        }));
        assertEquals(List.of("a.txt", "b.txt"), names(run));
        assertEquals("old a", Files.readString(run.resolve("a.txt")));
        assertEquals(List.of("run"), names(dir));
    }

    @Test
    void aCrashBetweenTheTwoRenamesIsRecoveredByTheNextWrite() throws IOException {
        Path run = oldRun();
        Files.move(run, AtomicFiles.aside(run)); // as the first rename leaves it
        Files.createDirectory(dir.resolve(".run.new-123")); // and a crashed write's folder
        assertThrows(IOException.class, () -> AtomicFiles.replaceFolder(run, fresh -> {
            throw new IOException("stopped");
        }));
        assertEquals(List.of("a.txt", "b.txt"), names(run), "the old run is back in place");
        assertEquals(List.of("run"), names(dir));
    }

    @Test
    void recoverMovesTheAsideFolderBackOnlyWhenNothingIsInPlace() throws IOException {
        Path run = oldRun();
        assertFalse(AtomicFiles.recoverFolder(run));
        Files.move(run, AtomicFiles.aside(run));
        assertTrue(AtomicFiles.recoverFolder(run));
        assertEquals(List.of("a.txt", "b.txt"), names(run));
    }

    private Path oldRun() throws IOException {
        Path run = Files.createDirectory(dir.resolve("run"));
        Files.writeString(run.resolve("a.txt"), "old a");
        Files.writeString(run.resolve("b.txt"), "old b");
        return run;
    }

    private static List<String> names(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
