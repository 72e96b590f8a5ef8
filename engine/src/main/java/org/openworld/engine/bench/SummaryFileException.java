package org.openworld.engine.bench;

import java.nio.file.Path;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * A {@code summary.json} is missing, unreadable or not a benchmark summary. The message names the file and says what
 * is wrong; the command line prints it without a stack trace.
 */
public final class SummaryFileException extends RuntimeException implements UserFacing {

    private final Path file;

    public SummaryFileException(Path file, String problem, Throwable cause) {
        super(file + ": " + problem, cause);
        this.file = file;
    }

    /** The file that could not be used. */
    public Path file() {
        return file;
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.USER_MISTAKE;
    }
}
