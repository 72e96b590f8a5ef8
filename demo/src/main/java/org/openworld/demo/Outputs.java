package org.openworld.demo;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.Set;
import org.openworld.engine.files.WriteFailure;
import org.openworld.engine.gl.Image;

/**
 * Checks a command's {@code --out} before any work, so a run is never lost for want of a place to write it: every
 * command that writes ({@code shot}, {@code bench}, {@code figures}, {@code heightmap}, {@code diff}) calls one of
 * these first. Each check tries what the write will do: it creates the folder and creates and deletes a probe file
 * in it, so a read-only file system, a missing permission or a file in the way is found in milliseconds, not after
 * a ten-minute run. A failure is a {@link UserError} (exit 2) naming the path and the operating system's reason,
 * e.g. {@code --out /tmp/f/run: cannot create the folder: Not a directory}.
 *
 * <p>Limits: the check cannot promise the write (the disk may fill, the folder may be removed meanwhile); the
 * writes themselves are atomic and checked ({@link org.openworld.engine.files.AtomicFiles}), so such a failure is a
 * {@link WriteFailure} (exit 2, the file and the reason) and leaves the old output whole.
 */
final class Outputs {

    /** The first eight bytes of every PNG file. */
    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    /** The first three bytes of every JPEG file: the start-of-image marker and the next marker's 0xFF. */
    private static final byte[] JPEG_SIGNATURE = {(byte) 0xFF, (byte) 0xD8, (byte) 0xFF};

    private Outputs() {
    }

    /** An output folder: created if missing, and writable. */
    static void folder(Path dir) {
        notEmpty(dir);
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw refused(dir, "is a file, not a folder; give a folder (it is created if missing)");
        }
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw refused(dir, "cannot create the folder: " + WriteFailure.reason(e));
        }
        try {
            Files.delete(Files.createTempFile(dir, ".openworld-probe-", ".tmp"));
        } catch (IOException e) {
            throw refused(dir, "cannot write in the folder: " + WriteFailure.reason(e));
        }
    }

    /**
     * A PNG file to write: its folder as {@link #folder}, and the file absent or a PNG, which is overwritten; any
     * other file is overwritten only with {@code force}.
     */
    static void png(Path file, boolean force) {
        notEmpty(file);
        if (!String.valueOf(file.getFileName()).toLowerCase(Locale.ROOT).endsWith(".png")) {
            throw refused(file, "is not a .png name; this command writes PNG files only");
        }
        picture(file, force);
    }

    /**
     * A picture to write, PNG or JPEG by its name ({@link Image#write}): a name ending in {@code .png},
     * {@code .jpg} or {@code .jpeg}, its folder as {@link #folder}, and the file absent or a picture (PNG or JPEG),
     * which is overwritten; any other file is overwritten only with {@code force}.
     */
    static void picture(Path file, boolean force) {
        notEmpty(file);
        String name = String.valueOf(file.getFileName()).toLowerCase(Locale.ROOT);
        if (Files.isDirectory(file)) {
            throw refused(file, "is a folder; give a file name ending in .png or .jpg");
        }
        if (!name.endsWith(".png") && !Image.isJpegName(file)) {
            throw refused(file, "has no picture extension; give a name ending in .png (PNG) or .jpg (JPEG)");
        }
        folder(file.toAbsolutePath().getParent());
        if (Files.exists(file) && !force && !isPicture(file)) {
            throw refused(file, "exists and is not a PNG or JPEG; give another name, or --force to overwrite it");
        }
    }

    /**
     * Refuses an output that is one of the command's inputs (the same file, also through a link or another spelling
     * of its path): writing it would replace what is being read, e.g. {@code diff a.png a.png --out a.png}.
     */
    static void notAnInput(Path out, Path... inputs) {
        for (Path input : inputs) {
            try {
                if (Files.exists(out) && Files.exists(input) && Files.isSameFile(out, input)) {
                    throw refused(out, "is also an input (" + input + "); give the output another name");
                }
            } catch (IOException e) {
                throw refused(out, "cannot compare it with the input " + input + ": " + WriteFailure.reason(e));
            }
        }
    }

    /** An empty {@code --out} (a script's unset variable) names the current folder: refused as what it is. */
    private static void notEmpty(Path path) {
        if (path.toString().isBlank()) {
            throw new UserError("--out is empty: give a file or folder name");
        }
    }

    /**
     * A folder a run is written into (bench: {@code names} are its files): its parent as {@link #folder}, and a
     * folder or nothing at {@code dir}, never a file. A new run replaces the earlier run's files all together and
     * keeps whatever else the folder holds ({@code AtomicFiles.replaceFolder}).
     */
    static void runFolder(Path dir, Set<String> names) {
        notEmpty(dir);
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

    private static boolean isPicture(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            byte[] start = in.readNBytes(PNG_SIGNATURE.length);
            return Arrays.equals(start, PNG_SIGNATURE)
                    || start.length >= JPEG_SIGNATURE.length
                    && Arrays.equals(start, 0, JPEG_SIGNATURE.length, JPEG_SIGNATURE, 0, JPEG_SIGNATURE.length);
        } catch (IOException e) {
            throw refused(file, "cannot read it to check it is a picture: " + WriteFailure.reason(e));
        }
    }

    private static UserError refused(Path path, String why) {
        return new UserError("--out " + path + ": " + why);
    }
}
