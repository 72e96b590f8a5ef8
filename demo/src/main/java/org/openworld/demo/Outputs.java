package org.openworld.demo;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Set;

/**
 * Checks a command's {@code --out} before any work, so a run is never lost for want of a place to write it: every
 * command that writes ({@code shot}, {@code bench}, {@code figures}, {@code heightmap}, {@code diff}) calls one of
 * these first. Each check tries what the write will do: it creates the folder and creates and deletes a probe file
 * in it, so a read-only file system, a missing permission or a file in the way is found in milliseconds, not after
 * a ten-minute run. A failure is a {@link UserError} (exit 2) naming the path and the operating system's reason,
 * e.g. {@code --out /tmp/f/run: cannot create the folder: Not a directory}.
 *
 * <p>Limits: the check cannot promise the write (the disk may fill, the folder may be removed meanwhile); the
 * writes themselves are atomic ({@link org.openworld.engine.files.AtomicFiles}), so such a failure leaves the old
 * output whole.
 */
final class Outputs {

    /** The first eight bytes of every PNG file. */
    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

    private Outputs() {
    }

    /** An output folder: created if missing, and writable. */
    static void folder(Path dir) {
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw refused(dir, "is a file, not a folder; give a folder (it is created if missing)");
        }
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw refused(dir, "cannot create the folder: " + reason(e));
        }
        try {
            Files.delete(Files.createTempFile(dir, ".openworld-probe-", ".tmp"));
        } catch (IOException e) {
            throw refused(dir, "cannot write in the folder: " + reason(e));
        }
    }

    /**
     * A PNG file to write: its folder as {@link #folder}, and the file absent or a PNG, which is overwritten; any
     * other file is overwritten only with {@code force}.
     */
    static void png(Path file, boolean force) {
        folder(file.toAbsolutePath().getParent());
        if (Files.isDirectory(file)) {
            throw refused(file, "is a folder; give a file name ending in .png");
        }
        if (Files.exists(file) && !force && !isPng(file)) {
            throw refused(file, "exists and is not a PNG; give another name, or --force to overwrite it");
        }
    }

    /**
     * A folder a run is written into (bench: {@code names} are its files): its parent as {@link #folder}, and a
     * folder or nothing at {@code dir}, never a file. A new run replaces the earlier run's files all together and
     * keeps whatever else the folder holds ({@code AtomicFiles.replaceFolder}).
     */
    static void runFolder(Path dir, Set<String> names) {
        Path absolute = dir.toAbsolutePath();
        folder(absolute.getParent());
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw refused(dir, "is a file; give a folder for the run's " + String.join(", ", names.stream().sorted()
                    .toList()));
        }
        if (Files.isDirectory(dir) && !Files.isWritable(dir)) {
            throw refused(dir, "cannot write in the folder");
        }
    }

    private static boolean isPng(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            return Arrays.equals(in.readNBytes(PNG_SIGNATURE.length), PNG_SIGNATURE);
        } catch (IOException e) {
            throw refused(file, "cannot read it to check it is a PNG: " + reason(e));
        }
    }

    private static UserError refused(Path path, String why) {
        return new UserError("--out " + path + ": " + why);
    }

    /**
     * The operating system's reason, as {@code strerror} says it: the JDK keeps it in
     * {@link FileSystemException#getReason()}, except for the two errors it gives their own exception type and no
     * reason.
     */
    static String reason(IOException e) {
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return f.getReason();
        }
        if (e instanceof NoSuchFileException) {
            return "No such file or directory";
        }
        if (e instanceof AccessDeniedException) {
            return "Permission denied";
        }
        return e.getMessage();
    }
}
