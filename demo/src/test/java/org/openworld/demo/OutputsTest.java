package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.bench.BenchReport;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.gl.Image;

/**
 * Every command that writes checks {@code --out} before any work ({@link Outputs}): one line naming the path and the
 * operating system's reason, exit 2. The tests run as root, whom permissions do not stop, so an unwritable place is
 * a path through a regular file ("Not a directory") or under {@code /proc} ("No such file or directory"). No
 * refusal needs OpenGL: each comes before the context is made; only the shot that overwrites does.
 */
class OutputsTest {

    private static final String VALLEY = "../assets/paths/valley.path";

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @Test
    void benchRefusesAFileAsItsFolderBeforeRunning() throws Exception {
        Path file = Files.writeString(dir.resolve("f"), "x");
        assertRefused("--out " + file + ": is a file; give a folder for the run's frames.csv, frametime.png, "
                + "summary.json", "bench", "--path", VALLEY, "--frames", "2", "--warmup", "0", "--out", file.toString());
        assertEquals("x", Files.readString(file));
    }

    @Test
    void benchUnderAFileNamesTheOperatingSystemsReason() throws Exception {
        Path file = Files.writeString(dir.resolve("file.txt"), "x");
        Path out = file.resolve("sub").resolve("run");
        assertRefused("--out " + file.resolve("sub") + ": cannot create the folder: Not a directory",
                "bench", "--path", VALLEY, "--out", out.toString());
    }


    @Test
    void shotInAFolderThatCannotBeWrittenSaysWhy() {
        assertRefused("--out /proc: cannot write in the folder: No such file or directory",
                "shot", "--out", "/proc/x.png");
    }

    @Test
    void shotRefusesToOverwriteAFileThatIsNotAPng() throws Exception {
        Path notes = Files.writeString(dir.resolve("notes.png"), "my notes, not a picture");
        assertRefused("--out " + notes + ": exists and is not a PNG or JPEG; give another name, or --force to "
                + "overwrite it",
                "shot", "--out", notes.toString());
        assertEquals("my notes, not a picture", Files.readString(notes));
    }

    @Test
    void shotRefusesAFolderAsItsFile() throws Exception {
        Path folder = Files.createDirectory(dir.resolve("pictures"));
        assertRefused("--out " + folder + ": is a folder; give a file name ending in .png or .jpg", "shot", "--out",
                folder.toString());
    }

    @Test
    void heightmapAndFiguresUnderAFileSayNotADirectory() throws Exception {
        Path file = Files.writeString(dir.resolve("file.txt"), "x");
        Path out = file.resolve("maps");
        assertRefused("--out " + out + ": cannot create the folder: Not a directory", "heightmap", "--out",
                out.toString(), "--set", "terrain.size=256");
        assertRefused("--out " + out + ": cannot create the folder: Not a directory", "figures", "--out",
                out.toString(), "--only", "2");
    }

    @Test
    void diffOverwritesAPngRefusesOtherFilesAndForceOverwritesThem() throws Exception {
        Path a = picture("a.png", 100);
        Path b = picture("b.png", 120);
        Path old = picture("d.png", 7);
        assertEquals(0, Main.execute("diff", a.toString(), b.toString(), "--out", old.toString()), console.stderr());
        assertEquals(8, Image.read(old).width());
        assertTrue(Image.read(old).channel(0, 0, 0) != 7, "the earlier PNG was overwritten");

        Path text = Files.writeString(dir.resolve("d-notes.png"), "keep me");
        assertRefused("--out " + text + ": exists and is not a PNG or JPEG; give another name, or --force to "
                + "overwrite it",
                "diff", a.toString(), b.toString(), "--out", text.toString());
        assertEquals("keep me", Files.readString(text));
        assertEquals(0, Main.execute("diff", a.toString(), b.toString(), "--out", text.toString(), "--force"));
        assertArrayEquals(new byte[] {(byte) 0x89, 'P', 'N', 'G'},
                Arrays.copyOf(Files.readAllBytes(text), 4));
        try (Stream<Path> files = Files.list(dir)) {
            assertFalse(files.anyMatch(p -> p.getFileName().toString().startsWith(".")), "no temporary file left");
        }
    }

    @Test
    @Tag("gl")
    void shotOverwritesAPngAndWithForceAnyFile() throws Exception {
        Path old = picture("old.png", 7);
        assertEquals(0, Main.execute("shot", "--out", old.toString(), "--size", "32x18"), console.stderr());
        assertEquals(32, Image.read(old).width(), "the earlier 8x6 PNG was replaced");
        Path text = Files.writeString(dir.resolve("x.png"), "not a picture");
        assertEquals(0, Main.execute("shot", "--out", text.toString(), "--size", "32x18", "--force"),
                console.stderr());
        assertEquals(18, Image.read(text).height());
    }

    @Test
    void diffRefusesAnOutThatIsOneOfItsInputsAlsoThroughALinkOrAnotherSpelling() throws Exception {
        Path a = picture("a.png", 100);
        Path b = picture("b.png", 120);
        byte[] before = Files.readAllBytes(a);
        assertRefused("--out " + a + ": is also an input (" + a + "); give the output another name",
                "diff", a.toString(), a.toString(), "--out", a.toString());
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), a);
        assertRefused("--out " + link + ": is also an input (" + a + "); give the output another name",
                "diff", a.toString(), b.toString(), "--out", link.toString());
        Path spelt = dir.resolve(".").resolve("b.png");
        assertRefused("--out " + spelt + ": is also an input (" + b + "); give the output another name",
                "diff", a.toString(), b.toString(), "--out", spelt.toString());
        assertArrayEquals(before, Files.readAllBytes(a), "the input is untouched");
    }

    @Test
    @Tag("gl")
    void aJpegNameGetsAJpegAndAnotherExtensionOrAnEmptyNameIsRefused() throws Exception {
        Path a = picture("a.png", 100);
        Path b = picture("b.png", 120);
        Path jpeg = dir.resolve("d.jpg");
        assertEquals(0, Main.execute("diff", a.toString(), b.toString(), "--out", jpeg.toString()), console.stderr());
        assertArrayEquals(new byte[] {(byte) 0xFF, (byte) 0xD8, (byte) 0xFF}, Arrays.copyOf(Files.readAllBytes(jpeg), 3),
                "JPEG's start-of-image marker");
        assertEquals(8, Image.read(jpeg).width());
        Path bmp = dir.resolve("d.bmp");
        assertRefused("--out " + bmp + ": has no picture extension; give a name ending in .png (PNG) or .jpg (JPEG)",
                "diff", a.toString(), b.toString(), "--out", bmp.toString());
        assertRefused("--out is empty: give a file or folder name", "shot", "--out", "");
        assertRefused("--out is empty: give a file or folder name", "heightmap", "--out", " ");
    }

    /** The command exits 2 with exactly this one line after the program's name, and prints nothing else. */
    private void assertRefused(String message, String... args) {
        int errBefore = console.stderr().length();
        int outBefore = console.stdout().length();
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute(args), console.stderr());
        assertEquals("openworld: " + message, console.stderr().substring(errBefore).strip());
        assertEquals("", console.stdout().substring(outBefore), "no work began");
    }

    private Path picture(String name, int grey) throws Exception {
        byte[] rgba = new byte[8 * 6 * 4];
        Arrays.fill(rgba, (byte) grey);
        Path file = dir.resolve(name);
        new Image(8, 6, rgba).writePng(file);
        return file;
    }
}
