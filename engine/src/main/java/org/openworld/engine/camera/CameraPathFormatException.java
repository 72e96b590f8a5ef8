package org.openworld.engine.camera;

import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;

/**
 * A camera path file that cannot be read, with the place and the reason in the form compilers use and editors
 * understand: {@code file:line:column: expected WHAT, found WHAT}, for example
 * {@code assets/paths/x.path:7:14: expected a number for pitch, found 'abc'}. Lines and columns are 1-based; the column
 * is that of the offending token (just past the last token when a field is missing). A file that cannot be read at
 * all is reported at 1:1.
 *
 * <p>Checked, because a broken hand-edited file is an expected outcome that the caller must answer: the command line
 * prints {@link #getMessage()} alone and exits with code 2, so the message carries everything a user needs.
 */
public final class CameraPathFormatException extends Exception implements UserFacing {

    /**
     * @param source   the file as the user named it
     * @param line     1-based line
     * @param column   1-based column of the offending token
     * @param expected what the format wanted there, e.g. "a number for pitch"
     * @param found    what was there, e.g. "'abc'" or "end of line"
     */
    public CameraPathFormatException(String source, int line, int column, String expected, String found) {
        super(source + ":" + line + ":" + column + ": expected " + expected + ", found " + found);
    }

    /**
     * A file that is no camera path at all, e.g. not text: {@code file: PROBLEM}.
     *
     * @param source  the file as the user named it
     * @param problem what is wrong with the whole file, e.g. "not a text file: byte 0xff at offset 3"
     */
    public CameraPathFormatException(String source, String problem) {
        super(source + ": " + problem);
    }

    @Override
    public ExitCode exitCode() {
        return ExitCode.USER_MISTAKE;
    }

    /** Printed as it is: the message starts with its place, {@code file:line:column:}. */
    @Override
    public String userMessage(String program) {
        return getMessage();
    }
}
