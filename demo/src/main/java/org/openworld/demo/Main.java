package org.openworld.demo;

import java.io.IOException;
import java.util.Set;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * {@code openworld}: the demo's command line. Without a command it runs the interactive window ({@code run}).
 *
 * <p>Exit codes ({@link ExitCode}): 0 success; 1 a failure inside the program (a shader that does not compile, an I/O
 * error); 2 a mistake in the command line or an input file (named with what was expected); 3 no usable OpenGL. Each
 * error type carries its own code ({@link UserFacing}); picocli's own errors in the command line exit with 2.
 */
@Command(name = "openworld", mixinStandardHelpOptions = true, version = "OpenWorld 0.1",
        description = "Renders large outdoor worlds in real time. Without a command: 'run'.",
        subcommands = {RunCommand.class, ShotCommand.class, BenchCommand.class, HeightmapCommand.class, FiguresCommand.class,
            DiffCommand.class, SettingsCommand.class, InfoCommand.class, CommandLine.HelpCommand.class})
public final class Main {

    private static final Set<String> TOP_LEVEL_FLAGS = Set.of("-h", "--help", "-V", "--version");

    public static void main(String[] args) {
        System.exit(execute(args));
    }

    /** Runs the command line and returns the exit code (tests call this). */
    static int execute(String... args) {
        String[] effective = args.length == 0 || (args[0].startsWith("-") && !TOP_LEVEL_FLAGS.contains(args[0]))
                ? prepend("run", args) : args;
        CommandLine cli = new CommandLine(new Main());
        cli.setExecutionExceptionHandler((e, commandLine, parseResult) -> report(e, commandLine));
        return cli.execute(effective);
    }

    /**
     * Prints a failure that ended a command and returns the exit code: the error's own message and code when it is
     * {@link UserFacing}; the JDK's message for an I/O error (it names the file); a stack trace for anything else,
     * which is a bug.
     */
    private static int report(Exception e, CommandLine commandLine) {
        var err = commandLine.getErr();
        String program = commandLine.getCommandSpec().root().name();
        if (e instanceof UserFacing failure) {
            err.println(failure.userMessage(program));
            return failure.exitCode().code();
        }
        if (e instanceof IOException) {
            err.println(program + ": " + e.getMessage());
            return ExitCode.INTERNAL_FAILURE.code();
        }
        e.printStackTrace(err);
        return ExitCode.INTERNAL_FAILURE.code();
    }

    private static String[] prepend(String first, String[] rest) {
        String[] all = new String[rest.length + 1];
        all[0] = first;
        System.arraycopy(rest, 0, all, 1, rest.length);
        return all;
    }
}
