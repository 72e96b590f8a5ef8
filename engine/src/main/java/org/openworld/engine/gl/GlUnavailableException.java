package org.openworld.engine.gl;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * No usable OpenGL context could be created. The message says what was tried, why each attempt failed, and what to
 * install; or, for a window without a display, that no display was found and how to render without one. The command
 * line prints it without a stack trace.
 */
public final class GlUnavailableException extends RuntimeException implements UserFacing {
    private final ExitCode exitCode;

    public GlUnavailableException(String message) {
        this(message, ExitCode.NO_OPENGL);
    }

    /**
     * @param exitCode {@link ExitCode#USER_MISTAKE} where the user asked for what this machine does not have (a
     *                 headless mode it lacks, a device number past its devices)
     */
    public GlUnavailableException(String message, ExitCode exitCode) {
        super(message);
        this.exitCode = exitCode;
    }

    @Override
    public ExitCode exitCode() {
        return exitCode;
    }

    /**
     * A report that starts with what failed, printed as it is; a user's one-line mistake (a device number past the
     * list) as any other mistake, after the program's name.
     */
    @Override
    public String userMessage(String program) {
        boolean oneLineMistake = exitCode == ExitCode.USER_MISTAKE && !getMessage().contains("\n");
        return oneLineMistake ? UserFacing.super.userMessage(program) : getMessage();
    }
}
