package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.openworld.demo.Figure.Tool;
import org.openworld.engine.Engine;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.shadow.ShadowSettings;
import picocli.CommandLine;

/** The catalogue of the paper's figures, without OpenGL: complete, unambiguous, and every command one that parses. */
class FigureCatalogueTest {

    private static final Size SIZE = new Size(320, 180);

    @Test
    void everyPaperFigureWithAPictureIsThereOnceUnderUniqueNames() {
        List<Integer> expected = IntStream.rangeClosed(1, 14).boxed().toList();
        assertEquals(expected, FigureCatalogue.numbers(), "every figure of the paper, 7 drawn as a diagram");
        List<Figure> all = FigureCatalogue.all();
        assertEquals(all.size(), all.stream().map(Figure::id).distinct().count(), "ids must be unique");
        List<String> files = all.stream().flatMap(f -> f.files().stream()).toList();
        assertEquals(files.size(), new HashSet<>(files).size(), "no two pictures may write the same file");
        for (Figure figure : all) {
            assertTrue(figure.id().startsWith(Integer.toString(figure.number())), figure.id());
            assertFalse(figure.caption().isBlank() || figure.note().isBlank(), figure.id());
        }
    }

    @Test
    void everyShotCommandParsesAsOpenworldShotWithValidSettingsAndAFixedSeedTimeAndPose() {
        for (Figure figure : FigureCatalogue.all()) {
            Object command = parse(figure.commandLine(figure.output(), SIZE, List.of()));
            if (figure.tool() == Tool.SHOT) {
                ShotCommand shot = (ShotCommand) command;
                assertEquals(FigureCatalogue.SEED, shot.render.seed, figure.id());
                assertTrue(figure.arguments().contains("--time"), figure.id() + " must fix the time of day");
                assertNotNull(shot.pose.camera, figure.id() + " must fix the pose");
                assertEquals(SIZE, shot.render.size);
                // every --set names a real key and a valid value (else this throws), and is in force
                Settings settings = Launch.settings(shot.render);
                for (String assignment : shot.render.set) {
                    Settings alone = Engine.settingsFor(DemoScene.systems());
                    alone.apply(assignment);
                    String key = assignment.substring(0, assignment.indexOf('='));
                    assertEquals(alone.text(key), settings.text(key), figure.id() + ": " + assignment);
                }
            } else if (figure.tool() == Tool.HEIGHTMAP) {
                HeightmapCommand maps = (HeightmapCommand) command;
                assertEquals(FigureCatalogue.SEED, maps.seed, figure.id());
                assertEquals(figure.output(), maps.out.toString());
            } else if (figure.tool() == Tool.DIFF) {
                DiffCommand diff = (DiffCommand) command;
                assertEquals(figure.output(), diff.out.toString());
                // it reads two pictures of its own figure that the catalogue makes before it
                List<String> earlier = FigureCatalogue.all().subList(0, FigureCatalogue.all().indexOf(figure))
                        .stream().filter(f -> f.number() == figure.number()).flatMap(f -> f.files().stream())
                        .toList();
                assertTrue(earlier.contains(diff.first.toString()), figure.id() + " reads " + diff.first);
                assertTrue(earlier.contains(diff.second.toString()), figure.id() + " reads " + diff.second);
            } else if (figure.tool() == Tool.STRIP) {
                assertEquals(figure.output(), ((SkyStripCommand) command).out.toString());
            } else {
                assertEquals(figure.output(), ((DiagramCommand) command).out.toString());
            }
        }
    }

    @Test
    void overridesComeLastSoTheyWinOverAPicturesOwnSettings() {
        Figure twelve = byId().get("12");
        ShotCommand own = (ShotCommand) parse(twelve.commandLine("12.png", SIZE, List.of()));
        ShotCommand overridden = (ShotCommand) parse(twelve.commandLine("12.png", SIZE, List.of("shadow.kernel=7")));
        assertEquals(5, Launch.settings(own.render).get(ShadowSettings.class).kernel(), "figure 12's own kernel");
        assertEquals(7, Launch.settings(overridden.render).get(ShadowSettings.class).kernel());
    }

    @Test
    void figureNineShowsEachMomentOnceWithEachScatteringModelEachAtItsOwnExposure() {
        Map<String, Figure> figures = byId();
        List<Figure> single = FigureCatalogue.all().stream().filter(f -> f.number() == 9)
                .filter(f -> f.arguments().contains("atmosphere.scattering=single")).toList();
        assertEquals(List.of("9a", "9b", "9c", "9d", "9e", "9f"), single.stream().map(Figure::id).toList());
        for (Figure paper : single) {
            Figure multiple = figures.get(paper.id() + "-multiple");
            assertNotNull(multiple, paper.id());
            // the same command but for the model and the paper's one exposure (noon's, not adapted)
            List<String> swapped = new ArrayList<>(paper.arguments());
            swapped.replaceAll(a -> a.equals("atmosphere.scattering=single") ? "atmosphere.scattering=multiple" : a);
            int fixed = swapped.indexOf("sky.auto-exposure=off");
            assertTrue(fixed > 0 && swapped.get(fixed - 1).equals("--set"), paper.id());
            swapped.subList(fixed - 1, fixed + 1).clear();
            assertEquals(swapped, multiple.arguments(), paper.id());
            assertTrue(paper.arguments().stream().noneMatch(a -> a.startsWith("sky.exposure=")), paper.id());
        }
        Set<String> times = single.stream().map(f -> f.arguments().get(f.arguments().indexOf("--time") + 1))
                .collect(Collectors.toSet());
        assertEquals(Set.of("04:42", "05:06", "05:24", "12:00", "18:36", "19:18"), times);
    }

    @Test
    void theStartingPoseIsTheDemosOwn() {
        assertEquals(DemoScene.DEFAULT_POSE, new PoseOptions.PoseConverter().convert(FigureCatalogue.DEFAULT_POSE));
    }

    @Test
    void aShotWritesOneFileNamedByItsIdAndTheMapsAFolderOfThree() {
        Figure shot = byId().get("9c");
        assertEquals(List.of("9c.png"), shot.files());
        assertEquals(List.of("shot", "--out", "x/9c.png", "--size", "320x180"),
                shot.commandLine("x/9c.png", SIZE, List.of()).subList(0, 5));
        Figure maps = byId().get("2");
        assertEquals(List.of("2/height.png", "2/snow.png", "2/spectrum.png"), maps.files());
        assertFalse(maps.commandLine("2", SIZE, List.of()).contains("--size"), "the maps have no render size");
    }

    private static Map<String, Figure> byId() {
        return FigureCatalogue.all().stream().collect(Collectors.toMap(Figure::id, Function.identity()));
    }

    /** The subcommand object the demo's command line makes of these words, options filled in. */
    private static Object parse(List<String> words) {
        return new CommandLine(new Main()).parseArgs(words.toArray(String[]::new)).subcommand().commandSpec()
                .userObject();
    }

    @Test
    void theFindingsStripsAreTheTestedOnesAtNoonAndSunset() {
        Map<String, Figure> figures = byId();
        for (String when : List.of("noon", "sunset")) {
            SkyStripCommand wavelengths = (SkyStripCommand) parse(figures.get("7-wavelengths-" + when)
                    .commandLine("w.png", SIZE, List.of()));
            assertEquals(List.of(3, 4, 6, 8, 16), wavelengths.vary.wavelengths);
            assertEquals(when.equals("sunset"), wavelengths.sunset);
            SkyStripCommand samples = (SkyStripCommand) parse(figures.get("7-samples-" + when)
                    .commandLine("s.png", SIZE, List.of()));
            assertEquals(List.of(1, 2, 4, 16), samples.vary.samples);
            assertEquals(when.equals("sunset"), samples.sunset);
        }
        assertEquals(Tool.DIAGRAM, figures.get("7").tool());
    }
}
