package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.settings.Settings;

/**
 * The line the gallery prints under figure 9a: the zenith's luminance with the sun 4° down as the picture shows it,
 * in the figure's sky and in the default one, and their ratio. No OpenGL: the sky is the CPU's.
 */
class FiguresTwilightTest {

    private static final Pattern LINE = Pattern.compile(
            "4° below the horizon, as shown .*: (\\S+) in this sky, (\\S+) in the default one .*, (\\S+) times;");

    @Test
    void figureNineAAtThePapersOneExposureShowsADarkerZenithThanTheDefault() {
        // --preset paper's sky: normalised constants, 6 wavelengths, 2 + 2 samples, noon's exposure at every hour
        Settings paper = settings("atmosphere.scattering=single", "atmosphere.constants=normalised",
                "atmosphere.wavelengths=6", "atmosphere.outer-samples=2", "atmosphere.inner-samples=2",
                "sky.auto-exposure=off");
        double ratio = ratio(FiguresCommand.twilight(figure("9a"), paper));
        // under half: at least a stop darker, a plainly darker sky (as TwilightTest)
        assertTrue(ratio < 0.5, "the dark dawn: below half the default's, " + ratio);
        // adapted to its light, the same sky would show brighter than the default, not darker (docs/sky.md)
        Settings adapted = settings("atmosphere.scattering=single", "atmosphere.constants=normalised",
                "atmosphere.wavelengths=6", "atmosphere.outer-samples=2", "atmosphere.inner-samples=2");
        assertTrue(ratio(FiguresCommand.twilight(figure("9a"), adapted)) > 1);
    }

    @Test
    void otherFiguresPrintNothing() {
        assertEquals("", FiguresCommand.twilight(figure("9b"), settings("atmosphere.constants=normalised")));
        assertEquals("", FiguresCommand.twilight(figure("8a"), settings()));
    }

    /** The printed ratio, checked against the two printed luminances. */
    private static double ratio(String line) {
        Matcher m = LINE.matcher(line);
        assertTrue(m.find(), line);
        double self = Double.parseDouble(m.group(1));
        double reference = Double.parseDouble(m.group(2));
        double ratio = Double.parseDouble(m.group(3));
        assertEquals(self / reference, ratio, 0.01 * ratio, line);
        return ratio;
    }

    private static Figure figure(String id) {
        return FigureCatalogue.all().stream().filter(f -> f.id().equals(id)).findFirst().orElseThrow();
    }

    private static Settings settings(String... overrides) {
        Settings s = Engine.settingsFor(DemoScene.systems());
        for (String o : overrides) {
            s.apply(o);
        }
        return s;
    }
}
