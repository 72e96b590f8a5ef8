package org.openworld.engine.gl;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * No usable OpenGL context could be created. The message says what was tried, why each attempt failed, and what to
 * install; or, for a window without a display, that no display was found and how to render without one. The command
 * line prints it without a stack trace.
 */
public final class GlUnavailableException extends RuntimeException implements UserFacing {
    public GlUnavailableException(String message) {
        super(message);
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.NO_OPENGL;
    }

    /** A report of several lines that starts with what failed, printed as it is. */
    @Override
    public String userMessage(String program) {
        return getMessage();
    }
}
