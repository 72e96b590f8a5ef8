package org.openworld.demo;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** The options every rendering command takes (docs/design.md, "Command line"). */
final class RenderOptions {

    @Option(names = "--size", paramLabel = "WxH", converter = Size.Converter.class,
            description = "Render size in pixels (default: ${DEFAULT-VALUE}).", defaultValue = "1280x720")
    Size size;

    @Option(names = "--seed", paramLabel = "N", converter = SeedConverter.class,
            description = "World seed, 0 .. 2147483647; short for --set engine.seed=N (default: 1).")
    Integer seed;

    /** A seed: a whole number 0 .. 2147483647, the range said when the text is not one (picocli says "not an int"). */
    static final class SeedConverter implements picocli.CommandLine.ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            try {
                int seed = Integer.parseInt(text.trim());
                if (seed >= 0) {
                    return seed;
                }
            } catch (NumberFormatException e) {
                // the message below says what is valid
            }
            throw new picocli.CommandLine.TypeConversionException("'" + text + "': expected a whole number 0 .. "
                    + Integer.MAX_VALUE);
        }
    }

    @Option(names = "--preset", paramLabel = "NAME",
            description = "Preset: low, default or ultra (quality), or paper (the 2017 paper's method) "
                    + "(assets/presets/NAME.settings); --config, --seed "
                    + "and --set given too win over it.")
    String preset;

    @Option(names = "--config", paramLabel = "FILE",
            description = "Read settings from a file of key=value lines (the settings panel saves one); "
                    + "--seed and --set given too win over it.")
    Path config;

    @Option(names = "--time", paramLabel = "HH:MM", description = "Time of day, local solar time (default: ${DEFAULT-VALUE}).",
            defaultValue = "10:00", converter = HoursConverter.class)
    double hours;

    /** {@code HH:MM} to hours, a wrong time being a command-line error like any other. */
    static final class HoursConverter implements picocli.CommandLine.ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            try {
                return org.openworld.engine.environment.TimeOfDay.parseHours(text);
            } catch (IllegalArgumentException e) {
                throw new picocli.CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }

    @Option(names = "--day-speed", paramLabel = "X",
            description = "Simulated hours per real hour of the day cycle, 0 .. 8640; 0 stops the sun (default: 60 in "
                    + "the window, a day in 24 minutes; 0 elsewhere). In the window: T pauses, [ and ] scrub, - and = "
                    + "change the speed.")
    Double daySpeed;

    /** The day cycle's speed: what the user said, else the command's own default; out of range is a user error. */
    double daySpeed(double commandDefault) {
        double speed = daySpeed != null ? daySpeed : commandDefault;
        if (!(speed >= 0 && speed <= DayCycle.MAX_SPEED)) {
            throw new UserError("--day-speed " + speed + ": expected 0 .. " + DayCycle.MAX_SPEED
                    + " simulated hours per real hour");
        }
        return speed;
    }

    @Option(names = "--set", paramLabel = "KEY=VALUE",
            description = "Change a setting; repeatable. 'openworld settings' lists every key.")
    List<String> set = new ArrayList<>();

    @Option(names = "--window", description = "Render in a visible window.")
    boolean window;

    @Option(names = "--headless", description = "Render without a window (EGL's device platform, GLFW's null "
            + "platform with EGL, or a hidden X11 window; --gl picks one).")
    boolean headless;

    @Mixin
    ContextOptions context = new ContextOptions();

    /** Whether to open a window: what the user said, else the command's own default. */
    boolean windowed(boolean commandDefault) {
        if (window && headless) {
            throw new picocli.CommandLine.ParameterException(new picocli.CommandLine(this),
                    "--window and --headless exclude each other");
        }
        return window || (!headless && commandDefault);
    }

    @Option(names = "--dev", description = "Read shaders from ./shaders on disk (F5 reloads them in the window); "
            + "a GL debug context whose driver messages are printed on stderr.")
    boolean dev;

    /** These options at another size, with {@code extra} {@code --set} assignments after the user's. */
    RenderOptions resized(Size newSize, List<String> extra) {
        RenderOptions copy = new RenderOptions();
        copy.size = newSize;
        copy.seed = seed;
        copy.preset = preset;
        copy.config = config;
        copy.hours = hours;
        copy.daySpeed = daySpeed;
        copy.set = new ArrayList<>(set);
        copy.set.addAll(extra);
        copy.window = window;
        copy.headless = headless;
        copy.context = context;
        copy.dev = dev;
        return copy;
    }
}
