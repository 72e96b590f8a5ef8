package org.openworld.engine.settings;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.bench.SummaryFileException;
import org.openworld.engine.bench.SummaryJson;
import org.openworld.engine.camera.CameraPath;
import org.openworld.engine.camera.CameraPathFormatException;
import org.openworld.engine.camera.CameraPathParser;
import org.openworld.engine.settings.SettingsTest.ProbeSettings;

/**
 * Hand-written files read as text: a UTF-8 byte order mark is skipped, and a file that is not UTF-8 text is refused
 * with the byte and its offset, by {@link TextFile} and by the readers built on it (settings files, camera paths,
 * benchmark summaries).
 */
class TextFileTest {

    private static final byte[] BOM = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};

    @TempDir
    Path dir;

    private static byte[] withPrefix(byte[] prefix, String text) {
        byte[] body = text.getBytes(StandardCharsets.UTF_8);
        byte[] all = new byte[prefix.length + body.length];
        System.arraycopy(prefix, 0, all, 0, prefix.length);
        System.arraycopy(body, 0, all, prefix.length, body.length);
        return all;
    }

    @Test
    void aLeadingByteOrderMarkIsSkippedAndOnlyThere() throws Exception {
        assertEquals("a=1\n", TextFile.decode(withPrefix(BOM, "a=1\n")));
        assertEquals("é\uFEFF", TextFile.decode("é\uFEFF".getBytes(StandardCharsets.UTF_8)), "a later U+FEFF is text");
    }

    @Test
    void malformedUtf8NamesTheByteAndItsOffset() throws Exception {
        byte[] bad = {'a', 'b', 'c', (byte) 0xFF, 'd'};
        var e = assertThrows(TextFile.NotTextException.class, () -> TextFile.decode(bad));
        assertEquals("not a text file: byte 0xff at offset 3", e.getMessage());
        assertEquals(3, e.offset());
        byte[] truncated = {'x', (byte) 0xC3};
        assertEquals("not a text file: byte 0xc3 at offset 1",
                assertThrows(TextFile.NotTextException.class, () -> TextFile.decode(truncated)).getMessage());
        assertEquals("abc", TextFile.decode("abc".getBytes(StandardCharsets.US_ASCII)));
    }

    @Test
    void offsetsCountTheByteOrderMarkAndNulIsNotText() {
        byte[] bad = withPrefix(BOM, "ab\0c");
        assertEquals("not a text file: byte 0x00 at offset 5",
                assertThrows(TextFile.NotTextException.class, () -> TextFile.decode(bad)).getMessage());
    }

    @Test
    void aSettingsFileWithAByteOrderMarkIsRead() throws Exception {
        Settings settings = new Settings(List.of(SettingsGroup.of("probe", ProbeSettings.class, ProbeSettings.DEFAULTS)));
        Path file = dir.resolve("bom.settings");
        Files.write(file, withPrefix(BOM, "probe.radius=42\n"));
        SettingsFile.read(file, settings);
        assertEquals("42", settings.text("probe.radius"));
    }

    @Test
    void aSettingsFileThatIsNotTextSaysSo() throws Exception {
        Settings settings = new Settings(List.of(SettingsGroup.of("probe", ProbeSettings.class, ProbeSettings.DEFAULTS)));
        Path file = dir.resolve("latin1.settings");
        Files.write(file, "probe.radius=4\n# caf\u00e9\n".getBytes(StandardCharsets.ISO_8859_1));
        var e = assertThrows(SettingsException.class, () -> SettingsFile.read(file, settings));
        assertEquals("settings file " + file + " is not a text file: byte 0xe9 at offset 20", e.getMessage());
    }

    @Test
    void aCameraPathWithAByteOrderMarkIsRead() throws Exception {
        Path file = dir.resolve("bom.path");
        Files.write(file, withPrefix(BOM, "0 0 100 0 0 0\n5 0 100 40 0 0\n"));
        CameraPath path = CameraPathParser.parse(file);
        assertEquals(0, path.startTime());
        assertEquals(5, path.endTime());
    }

    @Test
    void aCameraPathThatIsNotTextSaysSo() throws Exception {
        Path file = dir.resolve("picture.path");
        Files.write(file, new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n'});
        var e = assertThrows(CameraPathFormatException.class, () -> CameraPathParser.parse(file));
        assertEquals(file + ": not a text file: byte 0x89 at offset 0", e.getMessage());
    }

    @Test
    void aSummaryThatIsNotTextSaysSo() throws Exception {
        Path file = dir.resolve("summary.json");
        Files.write(file, new byte[] {'{', (byte) 0xFE, '}'});
        var e = assertThrows(SummaryFileException.class, () -> SummaryJson.read(file));
        assertTrue(e.getMessage().startsWith(file + ": not a text file: byte 0xfe at offset 1"), e.getMessage());
    }
}
