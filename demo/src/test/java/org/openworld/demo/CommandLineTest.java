package org.openworld.demo;

import org.openworld.engine.Engine;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.bench.SummaryJson;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.gl.Image;
import org.openworld.engine.settings.SettingsException;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * The commands as a user runs them: real OpenGL (headless), real files, exit codes and messages. The tests that run a
 * rendering command carry the tag {@code gl}, the others run in {@code -Dgroups='!gl'} too.
 */
class CommandLineTest {

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    @Tag("gl")
    void shotWritesAnImageOfTheAskedSize(TerrainSettings.World world) throws Exception {
        Path png = dir.resolve("shot.png");
        assertEquals(0, Main.execute("shot", "--out", png.toString(), "--size", "160x90", "--set",
                "terrain.world=" + world), console.stderr());
        Image image = Image.read(png);
        assertEquals(160, image.width());
        assertEquals(90, image.height());
        // The default view shows blue sky above and green-grey ground below.
        assertTrue(blueness(image, 0, 20) > 15, "sky at the top should be blue");
        // blue minus red in 8-bit levels: a clear sky's is tens of levels (over 15), a lit ground's near zero or
        // negative (under 5)
        assertTrue(blueness(image, 70, 90) < 5, "ground at the bottom should not be blue");
        assertTrue(console.stdout().contains("llvmpipe") || console.stdout().contains("wrote"), console.stdout());
    }

    @Test
    @Tag("gl")
    void shotWithUiDrawsThePanelOverThePicture() throws Exception {
        Path plain = dir.resolve("plain.png");
        Path ui = dir.resolve("ui.png");
        String[] common = {"--size", "320x180", "--set", "terrain.world=tile", "--set", "terrain.size=256",
                "--time", "12:00"};
        assertEquals(0, Main.execute(concat(new String[] {"shot", "--out", plain.toString()}, common)));
        assertEquals(0, Main.execute(concat(new String[] {"shot", "--ui", "--out", ui.toString()}, common)));
        Image a = Image.read(plain);
        Image b = Image.read(ui);
        int changed = 0;
        for (int y = 30; y < 100; y++) {
            for (int x = 20; x < 100; x++) {
                changed += a.channel(x, y, 0) != b.channel(x, y, 0) ? 1 : 0;
            }
        }
        // over half of the 80 × 70 pixels under the opaque panel change; text and frame may leave some equal
        assertTrue(changed > 0.5 * 80 * 70, "the panel covers the top left: " + changed);
    }

    private static String[] concat(String[] a, String[] b) {
        String[] all = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    @Tag("gl")
    void cameraOptionMovesTheView(TerrainSettings.World world) throws Exception {
        Path up = dir.resolve("up.png");
        Path down = dir.resolve("down.png");
        String chosen = "terrain.world=" + world;
        assertEquals(0, Main.execute("shot", "--out", up.toString(), "--size", "96x54", "--camera", "0,1500,400,0,60",
                "--set", chosen));
        assertEquals(0, Main.execute("shot", "--out", down.toString(), "--size", "96x54", "--camera",
                "0,1500,400,0,-60", "--set", chosen));
        // Looking up sees only sky; looking down sees only ground.
        assertTrue(blueness(Image.read(up), 0, 54) > 15, "looking up should see blue sky");
        // as above: over 15 for a sky, under 5 for ground
        assertTrue(blueness(Image.read(down), 0, 54) < 5, "looking down should see the ground");
    }

    /** Mean of blue minus red over the full-width rows y0 to y1: high for sky, low for ground. */
    private static double blueness(Image image, int y0, int y1) {
        double sum = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = 0; x < image.width(); x++) {
                sum += image.channel(x, y, 2) - image.channel(x, y, 0);
            }
        }
        return sum / ((y1 - y0) * image.width());
    }

    @Test
    @Tag("gl")
    void invalidSetValueNamesTheKeyAndRange() {
        int code = Main.execute("shot", "--out", dir.resolve("x.png").toString(), "--set", "engine.step=5");
        assertEquals(ExitCode.USER_MISTAKE.code(), code);
        assertTrue(console.stderr().contains("engine.step") && console.stderr().contains("0.001 .. 0.1"), console.stderr());
        assertFalse(console.stderr().contains("Exception"), "no stack trace for a user's mistake: " + console.stderr());
        assertFalse(Files.exists(dir.resolve("x.png")));
    }

    @Test
    @Tag("gl")
    void negativeDaySpeedNamesTheRange() {
        assertEquals(ExitCode.USER_MISTAKE.code(),
                Main.execute("shot", "--out", dir.resolve("x.png").toString(), "--day-speed", "-2"));
        assertTrue(console.stderr().contains("--day-speed -2.0: expected 0 .. 8640.0"), console.stderr());
        assertFalse(Files.exists(dir.resolve("x.png")));
    }

    @Test
    @Tag("gl")
    void invalidTimeIsACommandLineError() {
        assertEquals(ExitCode.USER_MISTAKE.code(),
                Main.execute("shot", "--out", dir.resolve("x.png").toString(), "--time", "25:00"));
        assertTrue(console.stderr().contains("--time") && console.stderr().contains("hours 0–23"), console.stderr());
        assertFalse(Files.exists(dir.resolve("x.png")));
    }

    @Test
    void unknownSetKeyIsAnError() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("settings", "--set", "camera.fovv=70"));
        assertTrue(console.stderr().contains("unknown setting 'camera.fovv'"), console.stderr());
    }

    @Test
    @Tag("gl")
    void brokenCameraPathNamesFileLineAndColumn() throws Exception {
        Path path = dir.resolve("broken.path");
        Files.writeString(path, "# a path\n0 0 100 0 0 0\n1 0 100 abc 0 0\n");
        int code = Main.execute("shot", "--out", dir.resolve("x.png").toString(), "--path", path.toString());
        assertEquals(ExitCode.USER_MISTAKE.code(), code);
        assertTrue(console.stderr().contains(path + ":3:9:"), console.stderr());
        assertFalse(console.stderr().contains("Exception"), console.stderr());
    }

    @Test
    void settingsListsEveryKeyWithItsDefault() {
        assertEquals(0, Main.execute("settings"));
        for (String key : Engine.settingsFor(DemoScene.systems()).keys()) {
            assertTrue(console.stdout().contains(key), "missing " + key);
        }
        assertTrue(console.stdout().contains("camera.fov") && console.stdout().contains("deg"));
    }

    @Test
    @Tag("gl")
    void infoPrintsRendererAndFrameOrder() {
        assertEquals(0, Main.execute("info"));
        assertTrue(console.stdout().contains("context:   headless-"), console.stdout());
        assertTrue(console.stdout().indexOf("culling") < console.stdout().indexOf("terrain"), console.stdout());
    }

    @Test
    @Tag("gl")
    void benchWritesTheThreeFilesAndCompares() throws Exception {
        Path a = dir.resolve("a");
        assertEquals(0, Main.execute("bench", "--path", "../assets/paths/valley.path", "--out", a.toString(),
                "--size", "96x54", "--frames", "12", "--warmup", "2"), console.stderr());
        assertTrue(Files.exists(a.resolve("frames.csv")));
        assertTrue(Files.exists(a.resolve("frametime.png")));
        var summary = SummaryJson.read(a.resolve("summary.json"));
        assertEquals(12, summary.frames());
        assertEquals("96x54", summary.size());
        assertTrue(summary.frameMs().median() > 0);
        assertTrue(summary.trianglesMedian() > 0);
        assertTrue(summary.passGpuMsMedian().containsKey("main.terrain"), summary.passGpuMsMedian().toString());
        // the engine's own texture count, which every driver has: the terrain's maps at least, held to the end
        var memory = summary.memory();
        assertTrue(memory.textureEndMib() > 0 && memory.texturePeakMib() >= memory.textureEndMib(), memory.toString());
        assertEquals(13, Files.readAllLines(a.resolve("frames.csv")).size(), "header plus one line per frame");

        assertEquals(0, Main.execute("bench", "--compare", a.resolve("summary.json").toString(),
                a.resolve("summary.json").toString()));
        assertTrue(console.stdout().contains("frame ms median"), console.stdout());
        assertTrue(console.stdout().contains("texture peak MiB"), console.stdout());
    }

    /**
     * The unbounded world with every system on, along the crossing path: each draws (its span is in the summary),
     * and the trees stand on the streamed world's ground (placed where its height field allows them).
     */
    @Test
    @Tag("gl")
    void theUnboundedWorldCarriesEverySystem() throws Exception {
        Path out = dir.resolve("unbounded");
        assertEquals(0, Main.execute("bench", "--path", "../assets/paths/crossing.path", "--out", out.toString(),
                "--size", "96x54", "--frames", "6", "--warmup", "2", "--set", "terrain.world=unbounded",
                "--set", "system.minimap=on", "--set", "system.particles=on"),
                console.stderr());
        var spans = SummaryJson.read(out.resolve("summary.json")).passGpuMsMedian().keySet();
        for (String span : List.of("main.terrain", "shadow0.terrain", "reflection.terrain", "main.water", "main.vegetation",
                "main.particles", "overlay.minimap")) {
            assertTrue(spans.contains(span), span + " in " + spans);
        }
        List<String> lines = Files.readAllLines(out.resolve("frames.csv"));
        int trees = List.of(lines.get(0).split(",")).indexOf("vegetation.count");
        assertTrue(trees >= 0, lines.get(0));
        double placed = Double.parseDouble(lines.get(lines.size() - 1).split(",")[trees]);
        assertTrue(placed > 100, "plants placed on the unbounded world: " + placed);
    }

    /** A budget too small for the unbounded world, or an imported map asked to be unbounded: a clear message. */
    @Test
    @Tag("gl")
    void theUnboundedWorldsMistakesAreNamed() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("shot", "--out", dir.resolve("x.png").toString(),
                "--size", "96x54", "--set", "terrain.world=unbounded", "--set", "terrain.memory-budget=4"));
        assertTrue(console.stderr().contains("terrain.memory-budget=4 MiB is too little")
                && console.stderr().contains("20 MiB or more"), console.stderr());
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("shot", "--out", dir.resolve("y.png").toString(),
                "--size", "96x54", "--set", "terrain.world=unbounded", "--set", "terrain.import-file=map.png"));
        assertTrue(console.stderr().contains("terrain.world=unbounded cannot go with terrain.import-file=map.png"),
                console.stderr());
    }

    /**
     * The unbounded world is the default, and an imported map is always the tile: given alone, beside a settings
     * file that holds the default world, or after the world was named and named again; refused only when the
     * command line names the unbounded world beside it, in either order.
     */
    @Test
    void anImportedMapIsAlwaysTheTile() throws Exception {
        assertEquals(TerrainSettings.World.UNBOUNDED, worldOf(null));
        assertEquals(TerrainSettings.World.TILE, worldOf(null, "terrain.import-file=map.png"));
        Path saved = dir.resolve("saved.settings");
        Files.writeString(saved, "terrain.world=unbounded\n");
        assertEquals(TerrainSettings.World.TILE, worldOf(saved, "terrain.import-file=map.png"));
        assertEquals(TerrainSettings.World.TILE,
                worldOf(null, "terrain.world=unbounded", "terrain.import-file=map.png", "terrain.world=tile"));
        for (List<String> both : List.of(List.of("terrain.world=unbounded", "terrain.import-file=map.png"),
                List.of("terrain.import-file=map.png", "terrain.world=UNBOUNDED"))) {
            var e = assertThrows(SettingsException.class, () -> worldOf(null, both.toArray(String[]::new)));
            assertTrue(e.getMessage().contains("terrain.world=unbounded")
                    && e.getMessage().contains("terrain.import-file=map.png"), e.getMessage());
        }
    }

    private static TerrainSettings.World worldOf(Path config, String... set) {
        var options = new RenderOptions();
        options.config = config;
        options.set.addAll(List.of(set));
        return Launch.settings(options).get(TerrainSettings.class).world();
    }

    @Test
    @Tag("gl")
    void benchCanSwitchASystemOff() throws Exception {
        Path out = dir.resolve("no-water");
        assertEquals(0, Main.execute("bench", "--path", "../assets/paths/valley.path", "--out", out.toString(),
                "--size", "96x54", "--frames", "3", "--warmup", "1", "--set", "system.water=off"), console.stderr());
        var spans = SummaryJson.read(out.resolve("summary.json")).passGpuMsMedian().keySet();
        assertTrue(spans.contains("main.terrain"), spans.toString());
        assertTrue(spans.stream().noneMatch(s -> s.endsWith(".water") || s.startsWith("reflection")), spans.toString());
    }

    @Test
    @Tag("gl")
    void configFileIsReadAndSetWinsOverIt() throws Exception {
        Path config = dir.resolve("mine.settings");
        Files.writeString(config, "# saved by hand\ncamera.fov=75\nsky.exposure=2\n");
        assertEquals(0, Main.execute("settings", "--config", config.toString(), "--set", "sky.exposure=3"));
        // 'settings' lists the defaults; the values in force are checked through the launch's settings
        var options = new RenderOptions();
        options.config = config;
        options.set.add("sky.exposure=3");
        var settings = Launch.settings(options);
        assertEquals("75", settings.text("camera.fov"));
        assertEquals("3", settings.text("sky.exposure"), "--set wins");

        Files.writeString(config, "camera.fov=75\ncamera.fov=500\n");
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("shot", "--out", dir.resolve("x.png").toString(),
                "--config", config.toString()));
        assertTrue(console.stderr().contains(config + ":2: camera.fov=500") && console.stderr().contains("20 .. 120"),
                console.stderr());
        assertFalse(console.stderr().contains("Exception"), console.stderr());
        assertFalse(Files.exists(dir.resolve("x.png")));
    }

    @Test
    @Tag("gl")
    void benchWithoutPathSaysWhatItNeeds() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("bench", "--out", dir.toString()));
        assertTrue(console.stderr().contains("--path"), console.stderr());
    }
}
