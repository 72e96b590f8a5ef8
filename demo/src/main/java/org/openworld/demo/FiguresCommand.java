package org.openworld.demo;

import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.openworld.demo.Figure.Tool;
import org.openworld.engine.Engine;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.sky.AtmosphereSettings;
import org.openworld.engine.sky.AtmosphereTables;
import org.openworld.engine.sky.SkyPicture;
import org.openworld.engine.sky.SkyReference;
import org.openworld.engine.sky.SkySettings;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code openworld figures}: remakes the paper's figures ({@link FigureCatalogue}) headless, and writes an
 * {@code index.html} gallery of them. Each picture is made by parsing its printed command line with the demo's own
 * command line and running that command ({@code shot}; {@code heightmap} for figure 2; {@code diagram} and
 * {@code sky-strip}, on the CPU, for figure 7 and the findings beside it) from scratch: a fresh world and GL context
 * per picture, nothing kept between them, so the command the gallery prints makes the same picture on its own. The
 * price is small: making the 2048² world again takes about 0.15 s of the 1.8 s (median) a 960×540 shot takes on
 * llvmpipe with 2 cores once the JIT is warm; the whole set, 50 pictures, about 95 s, of which figure 7's five, on
 * the CPU, 9 s. With {@code --preset NAME} (e.g. {@code paper}, the paper's method) every picture that reads a
 * setting is made a second time with the preset, and the gallery shows the two side by side: the default, and the
 * preset's beside it.
 */
@Command(name = "figures", mixinStandardHelpOptions = true,
        description = "Remake the paper's figures headless into a folder, with an index.html gallery that shows each "
                + "picture, the paper's caption, what to look for and the command that makes it.")
final class FiguresCommand implements Callable<Integer> {

    @Mixin
    DevOption dev;

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

    @Option(names = "--preset", paramLabel = "NAME",
            description = "Also make every picture with this preset (assets/presets/NAME.settings), e.g. paper, and "
                    + "show it beside the default one; each picture's own settings win over the preset.")
    String preset;

    /**
     * One picture's command: the figure as made (the preset's picture has the preset's name added to its id, so to
     * its files), the command as the gallery prints it (output relative to the folder) and parsed to run.
     */
    private record Job(Figure figure, List<String> printed, Object command) {
    }

    @Override
    public Integer call() throws Exception {
        List<Figure> figures = chosen();
        Settings every = Engine.settingsFor(DemoScene.systems());
        if (preset != null) {
            Presets.apply(preset, every); // an unknown preset fails here, before any picture
        }
        set.forEach(every::apply); // an unknown key or a bad value too
        Outputs.folder(out);

        // 1. every command parsed, and each shot's settings checked, before the first picture is made: per figure
        // the default picture, then the preset's where the preset changes something it reads
        List<List<Job>> jobsByFigure = figures.stream().map(this::jobs).toList();
        int count = jobsByFigure.stream().mapToInt(List::size).sum();

        // 2. the pictures, each by its own command from scratch
        long start = System.nanoTime();
        String renderer = "no OpenGL: figure 2's maps are made on the CPU";
        List<Gallery.Plate> plates = new ArrayList<>();
        int made = 0;
        for (int i = 0; i < figures.size(); i++) {
            List<Gallery.Picture> pictures = new ArrayList<>();
            for (Job job : jobsByFigure.get(i)) {
                long t0 = System.nanoTime();
                String measured = "";
                switch (job.figure().tool()) {
                    case SHOT -> {
                        ShotCommand command = (ShotCommand) job.command();
                        ShotCommand.Result shot = command.take();
                        renderer = shot.renderer() + ", " + shot.contextMode();
                        measured = twilight(figures.get(i), Launch.settings(command.render));
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
                pictures.add(new Gallery.Picture(job.figure(), "openworld " + Gallery.shellLine(job.printed()),
                        measured, seconds));
                System.out.printf(Locale.ROOT, "figures: %d/%d %s ... %.1f s%n", ++made, count, job.figure().id(),
                        seconds);
            }
            plates.add(new Gallery.Plate(figures.get(i), pictures));
        }

        // 3. the gallery
        double total = (System.nanoTime() - start) / 1e9;
        Path index = Gallery.write(out, new Gallery.Made("openworld " + Gallery.shellLine(invocation()), renderer,
                ZonedDateTime.now().format(DATE), size, FigureCatalogue.SEED, set, preset == null ? "" : preset,
                total), plates);
        System.out.printf(Locale.ROOT, "figures: %d pictures and %s in %.0f s%n", made, index, total);
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

    /**
     * The figure's default picture and, with {@code --preset}, the preset's: a shot takes {@code --preset} itself,
     * figure 2's maps the preset's engine.* and terrain.* values (when it has any off their defaults), a difference
     * the preset's two pictures, figure 7's diagram and strips nothing, so they are made once.
     */
    private List<Job> jobs(Figure figure) {
        List<Job> jobs = new ArrayList<>(List.of(job(figure)));
        if (preset != null) {
            String id = figure.id() + "-" + preset;
            if (figure.tool() == Tool.DIFF) {
                // the difference of the two preset pictures, made just before it
                jobs.add(job(new Figure(id, figure.number(), figure.caption(), figure.note(), Tool.DIFF,
                        figure.arguments().stream().map(f -> f.replace(".png", "-" + preset + ".png")).toList())));
                return jobs;
            }
            List<String> presetArguments = switch (figure.tool()) {
                case SHOT -> List.of("--preset", preset);
                case HEIGHTMAP -> heightmapPreset();
                case STRIP, DIAGRAM, DIFF -> List.of();
            };
            if (!presetArguments.isEmpty()) {
                jobs.add(job(figure.with(id, presetArguments)));
            }
        }
        return jobs;
    }

    private Job job(Figure figure) {
        List<String> overrides = switch (figure.tool()) {
            case SHOT -> set;
            case HEIGHTMAP -> heightmapKeys(set);
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

    /**
     * Under figure 9a, its default picture and its preset's, each with its own settings: the zenith's luminance with
     * the sun 4° below the horizon as the picture shows it (the scene's luminance times the exposure), in the
     * figure's sky and in the default one (multiple scattering, physical constants, the exposure adapted to the
     * light): the check of figure 9's dark dawn ({@code TwilightTest}).
     */
    static String twilight(Figure figure, Settings settings) {
        if (!figure.id().equals("9a")) {
            return "";
        }
        double sun = Math.toRadians(-4);
        AtmosphereTables air = AtmosphereTables.build(settings.get(AtmosphereSettings.class));
        double self = SkyReference.displayedZenith(air, settings.get(SkySettings.class), sun,
                SkyPicture.EYE_ALTITUDE_M);
        double scene = SkyReference.zenithLuminance(air, sun, SkyPicture.EYE_ALTITUDE_M);
        AtmosphereTables defaults = AtmosphereTables.build(AtmosphereSettings.DEFAULTS);
        double reference = SkyReference.displayedZenith(defaults, SkySettings.DEFAULTS, sun,
                SkyPicture.EYE_ALTITUDE_M);
        double referenceScene = SkyReference.zenithLuminance(defaults, sun, SkyPicture.EYE_ALTITUDE_M);
        return String.format(Locale.ROOT, "zenith with the sun 4° below the horizon, as shown (luminance × exposure): "
                + "%.3g in this sky, %.3g in the default one (multiple scattering, adapted exposure), %.3g times; "
                + "in the scene, before the exposure: %.3g and %.3g", self, reference, self / reference, scene,
                referenceScene);
    }

    /** Those of these settings that the heightmap command reads (engine.*, terrain.*): no other changes its maps. */
    private static List<String> heightmapKeys(List<String> settings) {
        Set<String> keys = new HashSet<>(HeightmapCommand.newSettings().keys());
        return settings.stream().filter(s -> keys.contains(s.substring(0, s.indexOf('=')).trim())).toList();
    }

    /** The preset's values that the heightmap command reads and that are off their defaults, as --set arguments. */
    private List<String> heightmapPreset() {
        Settings defaults = Engine.settingsFor(DemoScene.systems());
        Map<String, String> values = Presets.values(preset, defaults);
        Map<String, String> defaultValues = defaults.asExactText();
        List<String> changed = values.entrySet().stream()
                .filter(e -> !e.getValue().equals(defaultValues.get(e.getKey())))
                .map(e -> e.getKey() + "=" + e.getValue()).toList();
        List<String> arguments = new ArrayList<>();
        heightmapKeys(changed).forEach(s -> arguments.addAll(List.of("--set", s)));
        return arguments;
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
        if (preset != null) {
            words.add("--preset");
            words.add(preset);
        }
        return words;
    }
}
