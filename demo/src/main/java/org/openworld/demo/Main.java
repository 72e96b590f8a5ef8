package org.openworld.demo;

import java.util.Set;
import org.openworld.engine.bench.SummaryFileException;
import org.openworld.engine.camera.CameraPathFormatException;
import org.openworld.engine.core.SystemOrderException;
import org.openworld.engine.gl.GlUnavailableException;
import org.openworld.engine.gl.ShaderException;
import org.openworld.engine.settings.SettingsException;
import org.openworld.engine.terrain.HeightImportException;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * {@code openworld}: the demo's command line. Without a command it runs the interactive window ({@code run}).
 *
 * <p>Exit codes: 0 success; 1 a failure inside the program (a shader that does not compile, an I/O error);
 * 2 a mistake in the command line or an input file (named with what was expected); 3 no usable OpenGL.
 */
@Command(name = "openworld", mixinStandardHelpOptions = true, version = "OpenWorld 0.1",
        description = "Renders large outdoor worlds in real time. Without a command: 'run'.",
        subcommands = {RunCommand.class, ShotCommand.class, BenchCommand.class, HeightmapCommand.class, FiguresCommand.class,
            SettingsCommand.class, InfoCommand.class, CommandLine.HelpCommand.class})
public final class Main {

    static final int EXIT_USER_ERROR = 2;
    static final int EXIT_NO_GL = 3;

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

    private static int report(Exception e, CommandLine commandLine) {
        var err = commandLine.getErr();
        if (e instanceof GlUnavailableException) {
            err.println(e.getMessage());
            return EXIT_NO_GL;
        }
        if (e instanceof CameraPathFormatException) {
            err.println(e.getMessage());
            return EXIT_USER_ERROR;
        }
        if (e instanceof UserError || e instanceof SettingsException || e instanceof SummaryFileException
                || e instanceof HeightImportException) {
            err.println("openworld: " + e.getMessage());
            return EXIT_USER_ERROR;
        }
        if (e instanceof ShaderException || e instanceof SystemOrderException || e instanceof java.io.IOException) {
            err.println("openworld: " + e.getMessage());
            return 1;
        }
        e.printStackTrace(err);
        return 1;
    }

    private static String[] prepend(String first, String[] rest) {
        String[] all = new String[rest.length + 1];
        all[0] = first;
        System.arraycopy(rest, 0, all, 1, rest.length);
        return all;
    }
}
