package org.openworld.engine.settings;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;

/**
 * Settings saved to a text file and read back: one {@code key=value} per line, exactly as {@code --set} takes them;
 * a line starting with {@code #} is a comment (only at the start, since a value such as a file name may hold one),
 * blank lines are ignored. The settings panel saves every key, so a file read
 * into fresh settings gives the same settings; a hand-written file may hold just a few keys.
 * {@code openworld --config FILE} reads one, with any {@code --set} given after it winning. The file is read as UTF-8
 * with a leading byte order mark skipped ({@link TextFile}). A file name ({@link Setting#file}) given relative in a
 * file is read from the file's own folder; saved, it is written absolute, so it names the same file wherever the
 * settings file is read from.
 */
public final class SettingsFile {

    private SettingsFile() {
    }

    /** Writes every key with its exact current value, under a header that says how to use the file. */
    public static void write(Settings settings, Path file) throws IOException {
        StringBuilder text = new StringBuilder("""
                # OpenWorld settings: one key=value per line, as --set takes them ('openworld settings' lists them).
                # Use with: openworld --config FILE  (a --set after it wins). Lines starting with '#' are comments.
                """);
        settings.asExactText().forEach((key, value) -> text.append(key).append('=')
                .append(settings.isFile(key) ? absolute(value) : value).append('\n'));
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        Files.writeString(file, text, StandardCharsets.UTF_8);
    }

    /**
     * Applies every line of the file to {@code settings}, in order.
     *
     * @throws SettingsException naming the file and line of the first bad line (and nothing after it is applied),
     *                           or saying the file cannot be read
     */
    public static void read(Path file, Settings settings) {
        String text;
        try {
            text = TextFile.read(file);
        } catch (NoSuchFileException e) {
            throw new SettingsException("settings file " + file + " does not exist");
        } catch (TextFile.NotTextException e) {
            throw new SettingsException("settings file " + file + " is " + e.getMessage());
        } catch (IOException e) {
            throw new SettingsException("cannot read settings file " + file + ": " + e.getMessage());
        }
        apply(file.toString(), file.toAbsolutePath().getParent(), text, settings);
    }

    /**
     * Applies every line of a settings file on the classpath (e.g. {@code assets/presets/low.settings}), as
     * {@link #read(Path, Settings)} does.
     *
     * @return false if there is no such resource (nothing applied)
     * @throws SettingsException naming the resource and line of the first bad line
     */
    public static boolean readResource(String name, Settings settings) {
        try (InputStream in = SettingsFile.class.getClassLoader().getResourceAsStream(name)) {
            if (in == null) {
                return false;
            }
            apply(name, null, TextFile.decode(in.readAllBytes()), settings);
            return true;
        } catch (TextFile.NotTextException e) {
            throw new SettingsException("settings file " + name + " is " + e.getMessage());
        } catch (IOException e) {
            throw new SettingsException("cannot read settings file " + name + ": " + e.getMessage());
        }
    }

    /**
     * Applies each {@code key=value} line of {@code text}; {@code source} names the file in an error, and a relative
     * file name ({@link Setting#file}) is resolved against {@code folder}, the file's folder (none for a resource).
     */
    private static void apply(String source, Path folder, String text, Settings settings) {
        List<String> lines = text.lines().toList();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            try {
                settings.apply(resolved(line, folder, settings));
            } catch (SettingsException e) {
                throw new SettingsException(source + ":" + (i + 1) + ": " + e.getMessage());
            }
        }
    }

    /**
     * A file name as a saved file holds it: absolute, since a relative one would be read back from the settings
     * file's folder ({@link #read}), not from the current folder it meant. A value that is no file name is kept.
     */
    private static String absolute(String value) {
        try {
            return value.isBlank() ? value : Path.of(value.strip()).toAbsolutePath().normalize().toString();
        } catch (InvalidPathException e) {
            return value;
        }
    }

    /** A {@code key=value} line whose value is a relative file name, resolved against {@code folder}. */
    private static String resolved(String line, Path folder, Settings settings) {
        int eq = line.indexOf('=');
        if (folder == null || eq <= 0) {
            return line;
        }
        String key = line.substring(0, eq).trim();
        String value = line.substring(eq + 1).trim();
        try {
            if (value.isEmpty() || !settings.isFile(key) || Path.of(value).isAbsolute()) {
                return line;
            }
            return key + "=" + folder.resolve(value).normalize();
        } catch (InvalidPathException e) {
            return line; // not a file name at all: the setting's own check names it
        }
    }
}
