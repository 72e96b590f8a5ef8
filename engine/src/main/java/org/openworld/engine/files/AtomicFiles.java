package org.openworld.engine.files;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Comparator;
import java.util.stream.Stream;

/**
 * Replaces a file, or a folder of files, all at once: the new content is written beside its place (a temporary file
 * or folder in the same parent folder, so on the same file system) and then renamed into place.
 *
 * <p><b>A file</b> ({@link #write}) is replaced by one {@code rename(2)} ({@code Files.move} with
 * {@code ATOMIC_MOVE}): a reader, or a crash at any moment, sees the whole old file or the whole new one. Where the
 * file system cannot move atomically, the move falls back to {@code REPLACE_EXISTING}, which is not atomic. A crash
 * while writing leaves a hidden {@code .NAME.*.tmp} file beside the target.
 *
 * <p><b>A folder</b> ({@link #replaceFolder}) is written complete into a hidden {@code .NAME.new-*} folder beside
 * it, then swapped in by two renames: the old folder to {@code .NAME.old} beside it, the new one to its place; then
 * the old one is deleted. POSIX has no rename that swaps two folders in one step, so this is not atomic as a whole:
 * a crash between the two renames leaves no folder at {@code NAME} and the whole old one at {@code .NAME.old}; the
 * next {@link #replaceFolder} of the same folder (and {@link #recoverFolder}) moves it back first. At every other
 * moment {@code NAME} holds the whole old folder or the whole new one. Leftover {@code .NAME.new-*} folders of a
 * crashed write are deleted by the next write.
 *
 * <p><b>A write that fails</b> (a full disk, a folder removed meanwhile) fails the call with a {@link WriteFailure}
 * naming the file and the operating system's reason, and leaves the old output whole: every new file is flushed to
 * the disk ({@code FileChannel.force}, {@code fsync(2)}) before the rename, since a file system may accept a write and
 * find no room for it only when it is flushed, and a rename of a file not yet on the disk can show an empty file
 * after a power cut. Content must report its own failures: a writer that ignores them (stb_image_write's
 * {@code fwrite}) encodes into memory first, and the bytes are written here ({@link #write(Path, byte[])}).
 *
 * <p>Cost: one extra rename per file, two per folder, and one {@code fsync} per file (milliseconds on a disk, nothing
 * on tmpfs); the old and the new folder take disk space together until the old one is deleted. Limits: the folder
 * holding the renamed entry is not itself flushed, so a power cut just after the rename may show the old output
 * again (whole), never a part of either.
 */
public final class AtomicFiles {

    /** Writes content at the path it is given: a file to create, or a new empty folder to fill. */
    @FunctionalInterface
    public interface Content {
        void writeTo(Path path) throws IOException;
    }

    private AtomicFiles() {
    }

    /**
     * Writes a file through a temporary file in the same folder, flushes it to the disk and renames it over
     * {@code file}; a failure is a {@link WriteFailure} naming {@code file}, and {@code file} is left as it was.
     */
    public static void write(Path file, Content content) throws IOException {
        Path target = file.toAbsolutePath();
        Path temp = target.resolveSibling("." + target.getFileName() + "." + uniqueSuffix() + ".tmp");
        try {
            content.writeTo(temp);
            flush(temp);
            move(temp, target);
        } catch (WriteFailure e) {
            throw e;
        } catch (IOException e) {
            throw new WriteFailure(file, e);
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** Writes bytes encoded in memory as {@code file}, as {@link #write(Path, Content)} does. */
    public static void write(Path file, byte[] bytes) throws IOException {
        write(file, temp -> Files.write(temp, bytes));
    }

    /**
     * Writes one file of a folder being filled by {@link #replaceFolder}: {@code shown} is the name the user knows
     * it by (in the folder's place, not in the hidden new folder), which a failure names.
     */
    public static void writeInto(Path file, Path shown, Content content) throws IOException {
        try {
            content.writeTo(file);
            flush(file);
        } catch (WriteFailure e) {
            throw e;
        } catch (IOException e) {
            throw new WriteFailure(shown, e);
        }
    }

    /**
     * Fills a new folder and swaps it in for {@code folder} (created if absent). What the old folder holds that the
     * new content does not write (a log, the camera path a script put beside the run) is moved into the new folder
     * just before the swap, by renames, so it is kept, and a file still open for writing (a shell's redirect) goes on
     * being written in its new place; the old folder, holding only the replaced files, is then deleted. If
     * {@code content} fails, the new folder is deleted and {@code folder} is left as it was.
     */
    public static void replaceFolder(Path folder, Content content) throws IOException {
        try {
            swapIn(folder, content);
        } catch (WriteFailure e) {
            throw e;
        } catch (IOException e) {
            throw new WriteFailure(folder, e);
        }
    }

    private static void swapIn(Path folder, Content content) throws IOException {
        Path target = folder.toAbsolutePath();
        Path parent = target.getParent();
        Files.createDirectories(parent);
        recoverFolder(target);
        deleteStaleWrites(target);
        Path fresh = Files.createDirectory(parent.resolve("." + target.getFileName() + ".new-" + uniqueSuffix()));
        try {
            content.writeTo(fresh);
        } catch (IOException | RuntimeException | Error e) {
            deleteTree(fresh);
            throw e;
        }
        Path aside = aside(target);
        if (Files.isDirectory(target)) {
            try (Stream<Path> old = Files.list(target)) {
                for (Path kept : old.filter(p -> !Files.exists(fresh.resolve(p.getFileName()))).toList()) {
                    move(kept, fresh.resolve(kept.getFileName()));
                }
            }
            move(target, aside);
        }
        move(fresh, target);
        deleteTree(aside);
    }

    /**
     * Moves the old folder back to {@code folder} if a crash between {@link #replaceFolder}'s two renames left it
     * aside and nothing in its place; returns whether it did.
     */
    public static boolean recoverFolder(Path folder) throws IOException {
        Path target = folder.toAbsolutePath();
        Path aside = aside(target);
        if (Files.exists(target)) {
            deleteTree(aside); // a crash after the second rename: the new folder is in place
            return false;
        }
        if (!Files.isDirectory(aside)) {
            return false;
        }
        move(aside, target);
        return true;
    }

    /** Where {@link #replaceFolder} puts the old folder between its two renames: {@code .NAME.old} beside it. */
    public static Path aside(Path folder) {
        Path target = folder.toAbsolutePath();
        return target.resolveSibling("." + target.getFileName() + ".old");
    }

    /**
     * A name part no other writer uses: this process and a clock tick. Not {@code Files.createTempFile}, which
     * makes files only their owner may read (0600): the temporary file becomes the output, which should get the
     * usual permissions (the umask's), as a file written in place would.
     */
    private static String uniqueSuffix() {
        return ProcessHandle.current().pid() + "-" + System.nanoTime();
    }

    private static void deleteStaleWrites(Path target) throws IOException {
        try (DirectoryStream<Path> stale = Files.newDirectoryStream(target.getParent(),
                "." + target.getFileName() + ".new-*")) {
            for (Path leftover : stale) {
                deleteTree(leftover);
            }
        }
    }

    /** Flushes a written file to the disk: where a full disk shows itself on file systems that accept writes first. */
    private static void flush(Path file) throws IOException {
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.WRITE)) {
            channel.force(true);
        }
    }

    private static void move(Path from, Path to) throws IOException {
        try {
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    private static void deleteTree(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        try (Stream<Path> all = Files.walk(root)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }
}
