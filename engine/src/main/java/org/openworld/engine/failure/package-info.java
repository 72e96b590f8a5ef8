/**
 * How a failure meets the user: {@link org.openworld.engine.failure.ExitCode}, the process exit codes the command line
 * promises, and {@link org.openworld.engine.failure.UserFacing}, implemented by every error type of the project that
 * the command line reports as a message rather than a stack trace.
 *
 * <p>Each error type says itself which code it ends the program with, so the command line needs no list of types
 * (an {@code instanceof} ladder that every new error type would have to join): it asks the error. A failure that is
 * not {@code UserFacing} is a bug: one line saying what failed and asking for a report, exit code 1, its stack
 * trace printed only with {@code --dev}.
 */
package org.openworld.engine.failure;
