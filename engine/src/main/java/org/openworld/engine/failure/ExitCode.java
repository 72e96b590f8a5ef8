package org.openworld.engine.failure;

/**
 * The exit codes of {@code openworld}, as the README's "Commands" section and docs/errors.md document them. Scripts branch on these
 * numbers, so they never change meaning.
 */
public enum ExitCode {
    /** The command did what was asked (a comparison that finds differences included). */
    OK(0),
    /** A failure inside the program: a shader that does not compile, a file that cannot be written, a bug. */
    INTERNAL_FAILURE(1),
    /**
     * A mistake in the command line or in an input file, the message naming it and what was expected; or a world
     * too large for the Java heap, the message giving the heap tried and how to give more.
     */
    USER_MISTAKE(2),
    /**
     * No usable OpenGL context could be made, the message saying what was tried and what to install; or no display
     * for a window, the message offering the headless commands.
     */
    NO_OPENGL(3);

    private final int code;

    ExitCode(int code) {
        this.code = code;
    }

    /** The number the process exits with. */
    public int code() {
        return code;
    }
}
