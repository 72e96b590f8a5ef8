package org.openworld.engine.failure;

/**
 * An error the command line reports to its user as a message and an exit code, with no stack trace: the message
 * already says what went wrong and what would be right. Implemented by the project's exceptions, which supply
 * {@link #getMessage()} from {@link Throwable}.
 *
 * <p>The printed form follows Unix tools: {@code openworld: MESSAGE}. A message that starts with its own place, the
 * {@code file:line:column:} form compilers use and editors jump to, or that is a report of several lines, is printed
 * alone by overriding {@link #userMessage(String)}.
 */
public interface UserFacing {

    /** The code the program ends with when this error stops a command. */
    ExitCode exitCode();

    /** What went wrong, as the user should read it (Throwable's message). */
    String getMessage();

    /**
     * The text to print for this error.
     *
     * @param program the command's name, e.g. {@code openworld}
     */
    default String userMessage(String program) {
        return program + ": " + getMessage();
    }
}
