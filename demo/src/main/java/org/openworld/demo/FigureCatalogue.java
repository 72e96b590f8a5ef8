package org.openworld.demo;

import java.util.ArrayList;
import java.util.List;
import org.openworld.demo.Figure.Tool;

/**
 * Every figure of the paper, as pictures the demo makes: the one list {@code openworld figures} renders. Figure 7,
 * the paper's diagram of the scattering sums, is drawn ({@code openworld diagram}), and beside it are the paper's
 * findings on those sums as strips ({@code openworld sky-strip}): how many wavelengths and samples per sum it
 * takes for the sky's colour to settle, with the measured difference printed under each. Poses, times and settings
 * are those of the docs pages (docs/terrain.md, sky.md, shadows.md, water.md, particles.md) where they give them;
 * the rest were chosen by looking at the result, and are named below with what they show. Captions quote the
 * paper: a figure's own caption where it has one, else the sentence of the text that shows it.
 */
final class FigureCatalogue {

    /** The world seed of every picture: the default world, the one the docs pages show. */
    static final int SEED = 1;

    // Poses, x,y,z (m) and yaw,pitch (deg), as --camera takes them.
    /** The demo's starting pose ({@link DemoScene#DEFAULT_POSE}): a valley and the central mountain, looking north. */
    static final String DEFAULT_POSE = "0,400,900,0,-8";
    /** Seed 1's highest peak, about 1 km away to the north-west, from 600 m: its whole snow line in view (1, 4). */
    static final String PEAK_POSE = "-1200,600,200,313,-6";
    /** The central mountain's rock and snow face, close enough that the 2.7 m detail tiles show (figure 3). */
    static final String FACE_POSE = "0,350,450,0,-15";
    /** High and looking down the valley: several distance rings of detail levels in view at once (figure 6). */
    static final String RINGS_POSE = "0,600,1500,0,-22";
    /** 80 m above a lake, looking down across it: water that mirrors a slope and shows its bed (figure 13). */
    static final String LAKE_ABOVE_POSE = "-900,80,300,0,-14";
    /** 10 m above a lake, looking west along it (docs/water.md, docs/particles.md). */
    static final String LAKE_POSE = "-780,10,0,270,-2";
    /** The starting point looking west and a little up, towards the evening sun (docs/sky.md, figure 8). */
    static final String WEST_SKY_POSE = "0,400,900,280,8";
    /** The starting point looking north-north-east and up, away from the noon sun (docs/sky.md, figure 5). */
    static final String CLOUDS_POSE = "0,400,900,20,12";
    /** Figure 9 looks at the sun: east in the morning, west in the evening, and north at noon (backscattering). */
    static final String DAWN_POSE = "0,400,900,75,5";
    static final String NOON_POSE = "0,400,900,0,5";
    static final String DUSK_POSE = "0,400,900,285,5";

    private static final List<Figure> ALL = catalogue();

    private FigureCatalogue() {
    }

    /** Every picture, in the paper's order. */
    static List<Figure> all() {
        return ALL;
    }

    /** The paper's figure numbers that have pictures here, ascending. */
    static List<Integer> numbers() {
        return ALL.stream().map(Figure::number).distinct().sorted().toList();
    }

    private static List<Figure> catalogue() {
        List<Figure> list = new ArrayList<>();

        // Figure 1: snow by altitude bands against the snow map (paper 2.2)
        list.add(shot("1a", 1, "Texturing according to spatial coordinates only gives a very flat and unrealistic "
                + "impression, especially for the snow texture as can be seen in figure 1a.",
                "Snow by height alone (materials.snow-mode=altitude-bands): one level snow line cuts straight across "
                        + "the peak.",
                "16:30", PEAK_POSE, "materials.snow-mode=altitude-bands"));
        list.add(shot("1b", 1, "However, using the height-map generated previously and generate snow with probability "
                + "proportional to the height (normalized between minimum and maximum height, and some morphological "
                + "operations afterwards) gives the result shown in figure 1b.",
                "The snow map (the default): patches that thin out down the slopes instead of a line.",
                "16:30", PEAK_POSE));

        // Figure 2: the maps, made on the CPU
        list.add(new Figure("2", 2, "(a) Generated height-map (b) Generated snow-map",
                "height.png: lowest sample black, highest white; snow.png: white where snow lies, on the bright high "
                        + "ground of height.png; spectrum.png (not in the paper): the spectrum falls as 1/f^(2β).",
                Tool.HEIGHTMAP, List.of("--seed", Integer.toString(SEED))));

        // Figure 3: local detail from the tangent frame
        String detail = "The results corresponding to no local detail, with normal-map, with gloss-map and with both "
                + "is shown in figure 3.";
        list.add(shot("3a", 3, detail, "No local detail: smooth rock and snow, shaded by the height map's slope alone.",
                "16:30", FACE_POSE, "materials.normal-map=off", "materials.gloss-map=off"));
        list.add(shot("3b", 3, detail, "Normal map: the rock breaks into lit and shaded lumps, the snow gets a grain.",
                "16:30", FACE_POSE, "materials.normal-map=on", "materials.gloss-map=off"));
        list.add(shot("3c", 3, detail,
                "Gloss map: a faint sheen of sky and sun on the snow and smooth rock, subtle at this angle.",
                "16:30", FACE_POSE, "materials.normal-map=off", "materials.gloss-map=on"));
        list.add(shot("3d", 3, detail, "Both (the default): the lumps of 3b, their sunlit sides a little brighter.",
                "16:30", FACE_POSE, "materials.normal-map=on", "materials.gloss-map=on"));
        // the gloss is a sheen of a few levels, hard to see side by side (looking into a low sun too, tried): its
        // ΔE00 against 3a shows where
        list.add(new Figure("3c-diff", 3, detail, "Not in the paper: where 3c differs from 3a (ΔE00; 3a in grey, red "
                + "to yellow the most changed): most on the shaded snow of the right-hand slope, which mirrors the "
                + "bright sky at a grazing angle, then on the rock; the sunlit snow, near white already, hardly "
                + "changes.", Tool.DIFF, List.of("3a.png", "3c.png")));

        // Figure 4: the tangent frame itself
        list.add(shot("4", 4, "Figure 4: Visualization of the local topology",
                "terrain-debug.colouring=tangent-space: red the tangent's rise (slope along x), green the normal's "
                        + "height (flatness), blue the bitangent's rise (slope along z).",
                "16:30", PEAK_POSE, "terrain-debug.colouring=tangent-space"));

        // Figure 5: mapping the clouds onto the dome (paper 2.3)
        list.add(shot("5a", 5, "Sampling from the cloud texture with the skydome texture coordinates (spherical "
                + "angles) directly results in a very non-open effect, as can be seen in figure 5a.",
                "Spherical: one tile stretched over the dome, streaks at the horizon, a closed-in look.",
                "11:00", CLOUDS_POSE, "clouds.mode=layer", "clouds.mapping=spherical"));
        list.add(shot("5b", 5, "The problem clearly lies in the horizon, so a first approach could be to try to hide "
                + "this effect with a fog, the result can be seen in figure 5b.",
                "Spherical with fog: the horizon hidden, the error not.",
                "11:00", CLOUDS_POSE, "clouds.mode=layer", "clouds.mapping=spherical-fog"));
        list.add(shot("5c", 5, "The problem is that the coordinates need to be perspective corrected, as can be seen "
                + "in figure 5c.",
                "Perspective: clouds shrink towards the horizon as they should, but the tile repeats and far texels "
                        + "alias.",
                "11:00", CLOUDS_POSE, "clouds.mode=layer", "clouds.mapping=perspective"));
        list.add(shot("5d", 5, "Now the problem is that we can see how the same texture is repeated over and over, so "
                + "we again try to hide this with a fog effect, the result is quite pleasing and can be seen in "
                + "figure 5d.",
                "Perspective with fog (the layer's default): the far layer fades into the sky's own horizon colour.",
                "11:00", CLOUDS_POSE, "clouds.mode=layer", "clouds.mapping=perspective-fog"));

        // Figure 6: the paper's flat grid of geomipmaps, coloured by level (paper 2.5). The terrain alone: the level
        // colours keep a quarter of their brightness in the ground's shadows (terrain.frag), while a plant keeps its true light, so a
        // bush in a ridge's shadow would show as a black dot on the bright ground
        String levels = "Figure 6: Geomipmapping with various base resolution levels";
        int[] bases = {32, 64, 128, 256};
        for (int i = 0; i < bases.length; i++) {
            list.add(shot("6" + (char) ('a' + i), 6, levels,
                    "B = " + bases[i] + " m: each colour one level L = floor(log2(D/B)) of the paper's flat grid "
                            + "(lod.mode=flat-grid, lod.rule=paper); doubling B moves every ring one level out.",
                    "16:30", RINGS_POSE, "lod.mode=flat-grid", "lod.rule=paper", "lod.patch-vertices=65",
                    "terrain-debug.colouring=levels", "lod.base-resolution=" + bases[i],
                    "system.vegetation=off"));
        }

        // Figure 7: the scattering sums drawn, and the paper's findings on them measured (paper 3.1)
        list.add(new Figure("7", 7, "Figure 7: Illustration of the scattering equations",
                "The eye a, the view ray to b with the outer sum's points p, from each the inner sum toward the sun "
                        + "to c at the top of the atmosphere.", Tool.DIAGRAM, List.of()));
        String found = "This project found that the visible spectrum (400-750 nm) needs to be sampled at least 6 "
                + "times (linearly spaced samples) in order to approximate the resulting color distribution good "
                + "enough. Also, the light rays in both inner and outer integrals needs to be sampled at least 2 "
                + "times each (linearly spaced samples).";
        for (String when : List.of("noon", "sunset")) {
            List<String> sun = when.equals("noon") ? List.of() : List.of("--sunset");
            list.add(strip("7-wavelengths-" + when, found, "Wavelengths in the default sky at " + when + ", against "
                    + "32: 3 are far off (red: above ΔE00 2, a just-noticeable difference), 6 and more settle; 4 "
                    + "passes by where its wavelengths happen to fall (5 does not).", sun, "--wavelengths",
                    "3,4,6,8,16"));
            list.add(strip("7-samples-" + when, found, "Samples in each of the paper's sums at " + when + ", against "
                    + "64: with physical constants 2 are far off; it takes about 16.", sun, "--samples", "1,2,4,16"));
        }

        // Figure 8: the two kinds of scattering (paper 3.1)
        String phases = "The scattering equations are solved for two phase functions, one for Rayleigh scattering "
                + "(giving the ambient background colors), and one for Mie scattering (giving the red-yellow colors "
                + "resulting from larger particles).";
        list.add(shot("8a", 8, phases, "Both (the default).", "17:30", WEST_SKY_POSE, "atmosphere.component=both"));
        list.add(shot("8b", 8, phases, "Rayleigh only: the blue background, reddening towards the low sun.",
                "17:30", WEST_SKY_POSE, "atmosphere.component=rayleigh"));
        list.add(shot("8c", 8, phases, "Mie only: the bright glow around the sun, forward-peaked.",
                "17:30", WEST_SKY_POSE, "atmosphere.component=mie"));

        // Figure 9: a day, the paper's single scattering at one exposure for every hour (noon's: the paper does not
        // adapt it, so its dawn and dusk are dark), then the default, multiple scattering at the exposure adapted to
        // the light of the moment, for comparison (docs/sky.md)
        record Moment(String letter, String caption, String time, String pose, String look) {
        }
        List<Moment> day = List.of(
                new Moment("a", "(a) Early dawn, absence of higher order scattering terms obvious", "04:42", DAWN_POSE,
                        "sun 6° below the horizon: a glow in the east and a duller, greyer sky away from it"),
                new Moment("b", "(b) Just before sunrise", "05:06", DAWN_POSE,
                        "sun 2° below: orange horizon, the peaks still unlit"),
                new Moment("c", "(c) Sunrise", "05:24", DAWN_POSE,
                        "sun 1° up: the first light on the peaks, lit cloud undersides"),
                new Moment("d", "(d) Daylight backscattering", "12:00", NOON_POSE,
                        "noon, looking away from the sun: deep blue overhead, paler at the horizon"),
                new Moment("e", "(e) Sunset", "18:36", DUSK_POSE,
                        "sun 1° up in the west: red-yellow light, long shadows"),
                new Moment("f", "(f) Dusk, absence of higher order scattering terms obvious", "19:18", DUSK_POSE,
                        "sun 6° below: only the western horizon still glows"));
        for (String model : List.of("single", "multiple")) {
            for (Moment m : day) {
                boolean paper = model.equals("single");
                List<String> settings = paper
                        ? List.of("atmosphere.scattering=single", "sky.auto-exposure=off")
                        : List.of("atmosphere.scattering=multiple");
                list.add(shot("9" + m.letter() + (paper ? "" : "-multiple"), 9, m.caption(),
                        (paper ? "Single scattering, the paper's, at noon's exposure: " : "Multiple scattering at the "
                                + "adapted exposure (the default), to set beside 9" + m.letter() + ": ") + m.look()
                                + ".", m.time(), m.pose(), settings.toArray(String[]::new)));
            }
        }

        // Figures 10-12: the paper's single shadow map (paper 3.2), at the docs' 17:00 from the starting pose
        String margins = "Figure 10: Shadow mapping with different Z-buffer margins";
        String[] marginValues = {"0", "0.001", "0.01", "0.1"};
        String[] marginLooks = {"acne: false shadow in stripes and speckles on the sunlit slopes",
            "less acne", "clean", "the shadows shrink away from the ridges that cast them"};
        for (int i = 0; i < marginValues.length; i++) {
            list.add(shot("10" + (char) ('a' + i), 10, margins,
                    "Margin " + marginValues[i] + ", 1×1 kernel: " + marginLooks[i] + ".",
                    "17:00", DEFAULT_POSE, "shadow.method=paper", "shadow.kernel=1",
                    "shadow.margin=" + marginValues[i]));
        }
        String kernels = "Figure 11: Shadow mapping with different filter kernel sizes";
        int[] kernelSides = {1, 3, 5, 7};
        for (int i = 0; i < kernelSides.length; i++) {
            int n = kernelSides[i];
            list.add(shot("11" + (char) ('a' + i), 11, kernels,
                    n + "×" + n + " kernel, margin 0.01: " + (n == 1
                            ? "stair-stepped shadow edges, one texel each (10c's settings)"
                            : "edges fade over " + n + " texels"),
                    "17:00", DEFAULT_POSE, "shadow.method=paper", "shadow.margin=0.01", "shadow.kernel=" + n));
        }
        list.add(shot("12", 12, "Figure 12: Shadow mapping with 0.01 Z-buffer margin and 5x5 filter kernel size gives "
                + "a good trade-off between rendering quality and efficiency",
                "Clean and soft, but the single map's metres-wide texels blur the small shadows of ledges into blots.",
                "17:00", DEFAULT_POSE, "shadow.method=paper", "shadow.margin=0.01", "shadow.kernel=5"));
        list.add(shot("12-cascades", 12, "Figure 12: Shadow mapping with 0.01 Z-buffer margin and 5x5 filter kernel "
                + "size gives a good trade-off between rendering quality and efficiency",
                "Not in the paper: the default cascaded maps at the same moment, to set beside 12: sharp near shadows.",
                "17:00", DEFAULT_POSE, "shadow.method=cascades"));

        // Figure 13: the paper's stencil water (paper 3.3)
        String alpha = "Figure 13: Different alpha values for the water mask determines the transparency and "
                + "reflective properties";
        String[] alphas = {"0", "0.5", "1"};
        String[] alphaLooks = {"the lake bed through the water, no reflection",
            "half and half; nothing clips the mirrored scene, so mirrored slopes under the water show too",
            "only the mirror: sky and slopes"};
        for (int i = 0; i < alphas.length; i++) {
            list.add(shot("13" + (char) ('a' + i), 13, alpha, "Water alpha " + alphas[i] + ": " + alphaLooks[i] + ".",
                    "15:00", LAKE_ABOVE_POSE, "water.method=stencil", "water.alpha=" + alphas[i]));
        }

        // Figure 14: snowfall (paper 4)
        list.add(shot("14", 14, "Figure 14: A snowfall effect",
                "A million flakes in the 30 m cube around the eye under a cloudy sky: round, soft-rimmed, larger near "
                        + "the eye.",
                "14:00", LAKE_POSE, "system.particles=on", "particles.count=1000000", "clouds.cover=0.9"));
        return List.copyOf(list);
    }

    /** A strip of the sky at several samplings: {@code --wavelengths} or {@code --samples}, at noon or sunset. */
    private static Figure strip(String id, String caption, String note, List<String> sun, String... vary) {
        List<String> arguments = new ArrayList<>(List.of(vary));
        arguments.addAll(sun);
        return new Figure(id, 7, caption, note, Tool.STRIP, arguments);
    }

    /**
     * A shot at the catalogue's seed on the tile, the paper's world: {@code --seed --time --camera=}, {@code --set
     * terrain.world=tile} (the default is the unbounded world), then one {@code --set} per setting.
     */
    private static Figure shot(String id, int number, String caption, String note, String time, String pose,
            String... settings) {
        List<String> arguments = new ArrayList<>(List.of("--seed", Integer.toString(SEED), "--time", time,
                "--camera=" + pose, "--set", "terrain.world=tile"));
        for (String setting : settings) {
            arguments.add("--set");
            arguments.add(setting);
        }
        return new Figure(id, number, caption, note, Tool.SHOT, arguments);
    }
}
