package org.openworld.demo;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.files.AtomicFiles;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.AtmosphereSettings;
import org.openworld.engine.sky.AtmosphereSettings.Scattering;
import org.openworld.engine.sky.SkyPicture;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code openworld sky-strip}: the paper's findings on sampling (3.1: "at least 6" wavelengths, "at least 2" samples
 * in each sum) as a picture. The sky alone is computed on the CPU ({@link SkyPicture}) once per value asked for and
 * once finely sampled as the reference, and drawn as a strip, each panel with its mean CIEDE2000 difference to the
 * reference printed under it. Wavelengths are varied in the default sky (multiple scattering), or in the paper's
 * single scattering with {@code --single}; samples only exist in single scattering, in both sums at once. No
 * OpenGL. {@code SamplingFindingsTest} checks the same numbers.
 */
@Command(name = "sky-strip", mixinStandardHelpOptions = true,
        description = "Draw the sky on the CPU at several wavelength counts or samples per sum, each with its "
                + "CIEDE2000 difference to a finely sampled reference printed under it (the paper's findings, 3.1).")
final class SkyStripCommand implements Callable<Integer> {

    @Mixin
    DevOption dev;

    /** One panel measured: its value and its mean ΔE00 to the reference. */
    record Panel(int value, double deltaE) {
    }

    /** Each panel drawn this many times its computed size. */
    private static final int SCALE = 2;
    private static final int GAP = 12;
    private static final int LABEL_HEIGHT = 52;
    private static final int TITLE_HEIGHT = 34;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "The strip, a PNG file.")
    Path out;

    /** What the strip varies: exactly one of the two. */
    static final class Vary {
        @Option(names = "--wavelengths", required = true, split = ",", paramLabel = "N,M,...",
                description = "Vary atmosphere.wavelengths, one panel per value, left to right; the reference has "
                        + SkyPicture.REFERENCE_WAVELENGTHS + ".")
        List<Integer> wavelengths;

        @Option(names = "--samples", required = true, split = ",", paramLabel = "N,M,...",
                description = "Vary the samples of both single-scattering sums, outer and inner, one panel per "
                        + "value; the reference has " + SkyPicture.REFERENCE_SAMPLES + " in each.")
        List<Integer> samples;
    }

    @ArgGroup(exclusive = true, multiplicity = "1")
    Vary vary;

    @Option(names = "--sunset", description = "The sun 1° up (figure 9e), shown 3 EV brighter; without it noon, "
            + "the sun 54° up.")
    boolean sunset;

    @Option(names = "--single", description = "Vary the wavelengths in the paper's single scattering, not the "
            + "default multiple scattering (samples always are).")
    boolean single;

    @Override
    public Integer call() throws Exception {
        List<Panel> panels = draw();
        System.out.println("sky-strip: " + out + ": " + measured(panels));
        return 0;
    }

    /** Computes, measures and writes the strip; returns each panel's ΔE. */
    List<Panel> draw() throws Exception {
        Outputs.png(out, false);
        AtmosphereSettings base = !wavelengths() || single
                ? AtmosphereSettings.DEFAULTS.withScattering(Scattering.SINGLE) : AtmosphereSettings.DEFAULTS;
        Image reference = SkyPicture.render(with(base, referenceValue()), sun());
        List<Panel> panels = new ArrayList<>();
        List<Image> images = new ArrayList<>();
        for (int value : wavelengths() ? vary.wavelengths : vary.samples) {
            AtmosphereSettings settings;
            try {
                settings = with(base, value);
            } catch (IllegalArgumentException e) {
                throw new UserError((wavelengths() ? "--wavelengths " : "--samples ") + value + ": " + e.getMessage());
            }
            Image image = SkyPicture.render(settings, sun());
            images.add(image);
            panels.add(new Panel(value, ImageComparison.of(reference, image).meanDeltaE()));
        }
        images.add(reference);
        BufferedImage strip = strip(base, images, panels);
        AtomicFiles.write(out, file -> ImageIO.write(strip, "png", file.toFile()));
        return panels;
    }

    /** The panels' numbers in one line, for the console and the gallery. */
    String measured(List<Panel> panels) {
        return "mean ΔE00 to " + referenceValue() + " " + unit(referenceValue()) + ": " + panels.stream()
                .map(p -> String.format(Locale.ROOT, "%d: %.2f", p.value(), p.deltaE()))
                .collect(Collectors.joining(", "));
    }

    private boolean wavelengths() {
        return vary.wavelengths != null;
    }

    private SkyPicture.Sun sun() {
        return sunset ? SkyPicture.Sun.SUNSET : SkyPicture.Sun.NOON;
    }

    private int referenceValue() {
        return wavelengths() ? SkyPicture.REFERENCE_WAVELENGTHS : SkyPicture.REFERENCE_SAMPLES;
    }

    private AtmosphereSettings with(AtmosphereSettings base, int value) {
        return wavelengths() ? base.withWavelengths(value) : base.withSamples(value);
    }

    private String unit(int value) {
        if (wavelengths()) {
            return value == 1 ? "wavelength" : "wavelengths";
        }
        return value == 1 ? "sample per sum" : "samples per sum";
    }

    private BufferedImage strip(AtmosphereSettings base, List<Image> images, List<Panel> panels) {
        int panelWidth = SkyPicture.WIDTH * SCALE;
        int panelHeight = SkyPicture.HEIGHT * SCALE;
        int width = images.size() * panelWidth + (images.size() + 1) * GAP;
        int height = TITLE_HEIGHT + panelHeight + LABEL_HEIGHT;
        BufferedImage strip = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = strip.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
        g.setColor(new Color(0x22, 0x22, 0x22));
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
        String model = base.scattering() == Scattering.SINGLE ? "single scattering (the paper's)"
                : "multiple scattering (the default)";
        g.drawString(String.format(Locale.ROOT, "%s, %s at %s (sun %.0f° up): the sun's half of the dome, "
                        + "mean CIEDE2000 to the reference", wavelengths() ? "Wavelengths" : "Samples per sum",
                model, sun().name(), sun().elevationDeg()), GAP, 24);
        for (int i = 0; i < images.size(); i++) {
            int x = GAP + i * (panelWidth + GAP);
            g.drawImage(bufferedImage(images.get(i)), x, TITLE_HEIGHT, panelWidth, panelHeight, null);
            boolean isReference = i == panels.size();
            int value = isReference ? referenceValue() : panels.get(i).value();
            String name = value + " " + unit(value);
            String number = isReference ? "reference"
                    : String.format(Locale.ROOT, "ΔE00 %.2f", panels.get(i).deltaE());
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 18));
            centred(g, name, x, panelWidth, TITLE_HEIGHT + panelHeight + 22);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
            g.setColor(isReference || panels.get(i).deltaE() < 2 ? new Color(0x22, 0x22, 0x22)
                    : new Color(0xb0, 0x20, 0x20));
            centred(g, number, x, panelWidth, TITLE_HEIGHT + panelHeight + 44);
            g.setColor(new Color(0x22, 0x22, 0x22));
        }
        g.dispose();
        return strip;
    }

    private static void centred(Graphics2D g, String text, int x, int width, int baseline) {
        FontMetrics metrics = g.getFontMetrics();
        g.drawString(text, x + (width - metrics.stringWidth(text)) / 2, baseline);
    }

    private static BufferedImage bufferedImage(Image image) {
        BufferedImage buffered = new BufferedImage(image.width(), image.height(), BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                buffered.setRGB(x, y, image.channel(x, y, 0) << 16 | image.channel(x, y, 1) << 8
                        | image.channel(x, y, 2));
            }
        }
        return buffered;
    }
}
