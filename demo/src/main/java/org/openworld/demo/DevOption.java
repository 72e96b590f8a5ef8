package org.openworld.demo;

import picocli.CommandLine.Option;

/**
 * {@code --dev} for the commands without the renderer's options ({@code heightmap}, {@code diff}, {@code sky-strip},
 * {@code diagram}, {@code figures}, {@code info}): the one thing it does there is what it does everywhere, print the
 * stack trace of an internal error ({@link Main#report}, which finds {@code --dev} among the arguments before any
 * option is parsed), so that the request the error prints, "--dev prints the stack trace", works on every command.
 */
final class DevOption {

    @Option(names = "--dev", description = "Print the stack trace of an internal error, for a bug report.")
    boolean dev;
}
