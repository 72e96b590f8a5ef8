package org.openworld.engine.gl;

/**
 * No usable OpenGL context could be created. The message says what was tried, why each attempt failed, and what to
 * install; the command line prints it without a stack trace.
 */
public final class GlUnavailableException extends RuntimeException {
    public GlUnavailableException(String message) {
        super(message);
    }
}
