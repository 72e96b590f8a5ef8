package org.openworld.engine.files;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * An output that could not be written, for a reason of the operating system (a full disk, a folder removed
 * meanwhile, a lost permission): the file the user asked for and the system's reason, with the earlier output kept
 * ({@link AtomicFiles}), e.g. {@code /mnt/full/x.png: cannot write: No space left on device (the earlier output, if
 * any, is kept)}. It is the user's to correct, like an {@code --out} that cannot be made: exit 2.
 *
 * <p>The JDK reports a full disk as a bare {@code IOException("No space left on device")}, and an encoder such as
 * ImageIO's PNG writer wraps it in its own ("I/O error writing PNG file!"); the reason is found as the innermost
 * cause's message, so it reads the same whichever writer failed.
 */
public final class WriteFailure extends IOException implements UserFacing {

    private final Path file;

    public WriteFailure(Path file, IOException cause) {
        super(file + ": cannot write: " + reason(cause) + " (the earlier output, if any, is kept)", cause);
        this.file = file;
    }

    /** The output that was not written: the file the user named, not the temporary file it was written through. */
    public Path file() {
        return file;
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.USER_MISTAKE;
    }

    /**
     * The operating system's reason, as {@code strerror} says it: the innermost cause's, where an encoder wrapped
     * it; the JDK keeps it in {@link FileSystemException#getReason()}, except for the two errors it gives their own
     * exception type and no reason.
     */
    public static String reason(Throwable e) {
        Throwable inner = e;
        while (inner.getCause() != null && inner.getCause() != inner) {
            inner = inner.getCause();
        }
        if (inner instanceof FileSystemException f && f.getReason() != null) {
            return f.getReason();
        }
        if (inner instanceof NoSuchFileException) {
            return "No such file or directory";
        }
        if (inner instanceof AccessDeniedException) {
            return "Permission denied";
        }
        return inner.getMessage() != null ? inner.getMessage() : inner.getClass().getSimpleName();
    }
}
