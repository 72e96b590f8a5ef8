package org.openworld.demo;

import java.io.PrintWriter;
import java.nio.file.FileSystemException;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.failure.UserFacing;
import org.openworld.engine.gl.ProcessExit;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * {@code openworld}: the demo's command line. Without a command it runs the interactive window ({@code run}).
 *
 * <p>Exit codes ({@link ExitCode}, docs/errors.md): 0 success; 1 a failure inside the program (a shader that does
 * not compile, an I/O error, a bug); 2 a mistake in the command line or an input file (named with what was
 * expected), or a world too large for the Java heap; 3 no usable OpenGL or no display. Each error type carries its
 * own code ({@link UserFacing}); picocli's own errors in the command line exit with 2.
 *
 * <p>Every failure is reported here, in one place, as one line (a report of several lines only where the error
 * itself is one, such as the OpenGL attempts): a stack trace is printed only for a bug and only under {@code --dev},
 * which the report finds among the arguments, since it must know before, or without, any option being parsed.
 */
@Command(name = "openworld", mixinStandardHelpOptions = true, version = "OpenWorld 0.1",
        description = "Renders large outdoor worlds in real time. Without a command: 'run'.",
        subcommands = {RunCommand.class, ShotCommand.class, BenchCommand.class, HeightmapCommand.class, FiguresCommand.class,
            SkyStripCommand.class, DiagramCommand.class,
            DiffCommand.class, StabilityCommand.class, SettingsCommand.class, InfoCommand.class, CommandLine.HelpCommand.class})
public final class Main {

    private static final Set<String> TOP_LEVEL_FLAGS = Set.of("-h", "--help", "-V", "--version");
    private static final double BYTES_PER_MIB = 1024.0 * 1024.0;
    private static final double BYTES_PER_GIB = 1024 * BYTES_PER_MIB;

    public static void main(String[] args) {
        ProcessExit.exit(execute(args));
    }

    /** Runs the command line and returns the exit code (tests call this). */
    static int execute(String... args) {
        String[] effective = args.length == 0 || (args[0].startsWith("-") && !TOP_LEVEL_FLAGS.contains(args[0]))
                ? prepend("run", args) : args;
        boolean dev = Arrays.asList(args).contains("--dev");
        CommandLine cli = new CommandLine(new Main());
        cli.setParameterExceptionHandler(Main::reportUsage);
        cli.setExecutionExceptionHandler((e, commandLine, parseResult) -> report(e, commandLine, dev));
        try {
            return cli.execute(effective);
        } catch (OutOfMemoryError e) {
            cli.getErr().println(outOfMemory(cli.getCommandName()));
            cli.getErr().flush();
            return ExitCode.USER_MISTAKE.code();
        }
    }

    /**
     * A mistake in the command line that picocli found: its message and where to read about the options, one line
     * (picocli's default prints the whole usage after it, which buries the message), with picocli's "did you mean"
     * for a misspelt option or command in the same line.
     */
    private static int reportUsage(CommandLine.ParameterException e, String[] args) {
        CommandLine command = e.getCommandLine();
        PrintWriter err = command.getErr();
        String name = command.getCommandSpec().qualifiedName();
        List<String> suggestions = e instanceof CommandLine.UnmatchedArgumentException unmatched
                ? unmatched.getSuggestions() : List.of();
        err.println(command.getCommandSpec().root().name() + ": " + e.getMessage()
                + (suggestions.isEmpty() ? "" : "; did you mean " + String.join(" or ", suggestions) + "?")
                + " ('" + name + " --help' lists the options)");
        return ExitCode.USER_MISTAKE.code();
    }

    /**
     * Prints a failure that ended a command and returns the exit code: the error's own message and code when it is
     * {@link UserFacing}; the file and the operating system's reason for an I/O error; for anything else, which is a
     * bug, what failed in plain words and a request to report it, with the stack trace under {@code --dev}.
     */
    static int report(Exception e, CommandLine commandLine, boolean dev) {
        var err = commandLine.getErr();
        String program = commandLine.getCommandSpec().root().name();
        if (e instanceof UserFacing failure) {
            err.println(failure.userMessage(program));
            return failure.exitCode().code();
        }
        if (e instanceof FileSystemException io && io.getFile() != null) {
            err.println(program + ": " + io.getFile() + ": " + plainWords(io)
                    + (io.getReason() == null ? "" : " (" + io.getReason() + ")"));
        } else if (e instanceof java.io.IOException) {
            err.println(program + ": " + e.getMessage());
        } else {
            err.println(program + ": internal error, " + plainWords(e)
                    + (e.getMessage() == null ? "" : ": " + e.getMessage())
                    + "; this is a bug in OpenWorld: please report it with the command line"
                    + (dev ? "" : " (--dev prints the stack trace)"));
            if (dev) {
                e.printStackTrace(err);
            }
        }
        return ExitCode.INTERNAL_FAILURE.code();
    }

    /**
     * The line for an exhausted heap: how much was tried and how to give more. It is the world's size against the
     * machine's memory, so it is the user's to change (exit 2), like any setting out of range.
     */
    static String outOfMemory(String program) {
        long heap = Runtime.getRuntime().maxMemory();
        String tried = heap < BYTES_PER_GIB ? String.format(Locale.ROOT, "%.0f MiB", heap / BYTES_PER_MIB)
                : String.format(Locale.ROOT, "%.1f GiB", heap / BYTES_PER_GIB);
        return program + ": out of memory: the Java heap of " + tried + " is too small for this world; give Java more "
                + "(e.g. JAVA_OPTS=-Xmx8g ./openworld ...) or make the world smaller (e.g. --set terrain.size=2048)";
    }

    /** An exception's class in words: {@code NullPointerException} is "null pointer", {@code AccessDeniedException} "access denied". */
    static String plainWords(Throwable e) {
        String name = e.getClass().getSimpleName().replaceAll("(Exception|Error)$", "");
        return name.replaceAll("(?<=[a-z0-9])(?=[A-Z])", " ").toLowerCase(Locale.ROOT);
    }

    private static String[] prepend(String first, String[] rest) {
        String[] all = new String[rest.length + 1];
        all[0] = first;
        System.arraycopy(rest, 0, all, 1, rest.length);
        return all;
    }
}
