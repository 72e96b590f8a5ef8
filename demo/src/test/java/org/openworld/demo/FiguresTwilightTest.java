package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.settings.Settings;

/**
 * The line the gallery prints under figure 9a made with the paper's normalised constants: the zenith's luminance
 * with the sun 4° down in that sky and in the default one, and their ratio. No OpenGL: the sky is the CPU's.
 */
class FiguresTwilightTest {

    private static final Pattern LINE = Pattern.compile(
            "4° below the horizon: (\\S+) in this sky, (\\S+) in the default one .*, (\\S+) times");

    @Test
    void figureNineAWithNormalisedConstantsPrintsBothLuminancesAndTheirRatio() {
        Settings paper = settings("atmosphere.scattering=single", "atmosphere.constants=normalised",
                "atmosphere.wavelengths=6", "atmosphere.outer-samples=2", "atmosphere.inner-samples=2");
        String line = FiguresCommand.twilight(figure("9a"), paper);
        Matcher m = LINE.matcher(line);
        assertTrue(m.find(), line);
        double self = Double.parseDouble(m.group(1));
        double reference = Double.parseDouble(m.group(2));
        assertEquals(self / reference, Double.parseDouble(m.group(3)), 0.01 * self / reference, line);
        assertTrue(self > reference, "the normalised twilight is the brighter (docs/sky.md): " + line);
    }

    @Test
    void otherFiguresAndPhysicalConstantsPrintNothing() {
        assertEquals("", FiguresCommand.twilight(figure("9a"), settings("atmosphere.scattering=single")));
        assertEquals("", FiguresCommand.twilight(figure("9b"), settings("atmosphere.constants=normalised")));
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
