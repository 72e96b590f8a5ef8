package org.openworld.demo;

import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.openworld.demo.Figure.Tool;
import org.openworld.engine.Engine;
import org.openworld.engine.settings.Settings;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code openworld figures}: remakes the paper's figures ({@link FigureCatalogue}) headless, and writes an
 * {@code index.html} gallery of them. Each picture is made by parsing its printed command line with the demo's own
 * command line and running that command ({@code shot}; {@code heightmap} for figure 2; {@code diagram} and
 * {@code sky-strip}, on the CPU, for figure 7 and the findings beside it) from scratch: a fresh world and GL context
 * per picture, nothing kept between them, so the command the gallery prints makes the same picture on its own. The
 * price is small: making the 2048² world again takes about 0.15 s of the 1.8 s (median) a 960×540 shot takes on
 * llvmpipe with 2 cores once the JIT is warm; the whole set, 50 pictures, about 95 s, of which figure 7's five, on
 * the CPU, 9 s.
 */
@Command(name = "figures", mixinStandardHelpOptions = true,
        description = "Remake the paper's figures headless into a folder, with an index.html gallery that shows each "
                + "picture, the paper's caption, what to look for and the command that makes it.")
final class FiguresCommand implements Callable<Integer> {

    private static final DateTimeFormatter DATE = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm xxx", Locale.ROOT);

    @Option(names = "--out", required = true, paramLabel = "DIR",
            description = "Output folder, created if missing: the pictures and index.html.")
    Path out;

    @Option(names = "--only", paramLabel = "N", split = ",",
            description = "Only figure N of the paper; repeatable or N,M (default: all, 1-14).")
    List<Integer> only = new ArrayList<>();

    @Option(names = "--size", paramLabel = "WxH", converter = Size.Converter.class, defaultValue = "960x540",
            description = "Render size of every shot in pixels (default: ${DEFAULT-VALUE}).")
    Size size;

    @Option(names = "--set", paramLabel = "KEY=VALUE",
            description = "A setting added to every picture's command after its own, so it wins; repeatable. "
                    + "Figure 2's maps take only the engine.* and terrain.* keys; figure 7's diagram and strips none.")
    List<String> set = new ArrayList<>();

    /** One picture's command: as the gallery prints it (output relative to the folder) and parsed to run. */
    private record Job(Figure figure, List<String> printed, Object command) {
    }

    @Override
    public Integer call() throws Exception {
        List<Figure> figures = chosen();
        Settings every = Engine.settingsFor(DemoScene.systems());
        set.forEach(every::apply); // an unknown key or a bad value fails here, before any picture
        Outputs.folder(out);

        // 1. every command parsed, and each shot's settings checked, before the first picture is made
        List<Job> jobs = figures.stream().map(this::job).toList();

        // 2. the pictures, each by its own command from scratch
        long start = System.nanoTime();
        String renderer = "no OpenGL: figure 2's maps are made on the CPU";
        List<Gallery.Plate> plates = new ArrayList<>();
        for (Job job : jobs) {
            long t0 = System.nanoTime();
            String measured = "";
            switch (job.figure().tool()) {
                case SHOT -> {
                    ShotCommand.Result shot = ((ShotCommand) job.command()).take();
                    renderer = shot.renderer() + ", " + shot.contextMode();
                }
                case HEIGHTMAP -> ((HeightmapCommand) job.command()).call();
                case STRIP -> {
                    SkyStripCommand strip = (SkyStripCommand) job.command();
                    measured = strip.measured(strip.draw());
                }
                case DIAGRAM -> ((DiagramCommand) job.command()).call();
                case DIFF -> ((DiffCommand) job.command()).call();
            }
            double seconds = (System.nanoTime() - t0) / 1e9;
            plates.add(new Gallery.Plate(job.figure(), "openworld " + Gallery.shellLine(job.printed()), measured,
                    seconds));
            System.out.printf(Locale.ROOT, "figures: %d/%d %s ... %.1f s%n", plates.size(), jobs.size(),
                    job.figure().id(), seconds);
        }

        // 3. the gallery
        double total = (System.nanoTime() - start) / 1e9;
        Path index = Gallery.write(out, new Gallery.Made("openworld " + Gallery.shellLine(invocation()), renderer,
                ZonedDateTime.now().format(DATE), size, FigureCatalogue.SEED, set, total), plates);
        System.out.printf(Locale.ROOT, "figures: %d pictures and %s in %.0f s%n", plates.size(), index, total);
        return 0;
    }

    /** The catalogue's pictures of the figures asked for, in the paper's order; an unknown figure is a user error. */
    private List<Figure> chosen() {
        List<Integer> valid = FigureCatalogue.numbers();
        for (int n : only) {
            if (!valid.contains(n)) {
                throw new UserError("--only " + n + ": the paper has no figure " + n + " to make; choose from "
                        + valid.stream().map(String::valueOf).collect(Collectors.joining(", ")));
            }
        }
        return FigureCatalogue.all().stream().filter(f -> only.isEmpty() || only.contains(f.number())).toList();
    }

    private Job job(Figure figure) {
        List<String> overrides = switch (figure.tool()) {
            case SHOT -> set;
            case HEIGHTMAP -> heightmapOverrides();
            case STRIP, DIAGRAM, DIFF -> List.of(); // they take no settings: each strip fixes its own
        };
        List<String> printed = figure.commandLine(figure.output(), size, overrides);
        List<String> run = figure.readingFrom(out).commandLine(out.resolve(figure.output()).toString(), size,
                overrides);
        CommandLine.ParseResult parsed = new CommandLine(new Main()).parseArgs(run.toArray(String[]::new));
        Object command = parsed.subcommand().commandSpec().userObject();
        if (figure.tool() == Tool.SHOT) {
            Launch.settings(((ShotCommand) command).render);
        }
        return new Job(figure, printed, command);
    }

    /** The overrides the heightmap command reads (engine.* and terrain.*); the others do not change its maps. */
    private List<String> heightmapOverrides() {
        Set<String> keys = new HashSet<>(HeightmapCommand.newSettings().keys());
        return set.stream().filter(s -> keys.contains(s.substring(0, s.indexOf('=')).trim())).toList();
    }

    /** This run's own command line, for the gallery's header. */
    private List<String> invocation() {
        List<String> words = new ArrayList<>(List.of("figures", "--out", out.toString(), "--size",
                size.width() + "x" + size.height()));
        if (!only.isEmpty()) {
            words.add("--only");
            words.add(only.stream().map(String::valueOf).collect(Collectors.joining(",")));
        }
        for (String override : set) {
            words.add("--set");
            words.add(override);
        }
        return words;
    }
}
