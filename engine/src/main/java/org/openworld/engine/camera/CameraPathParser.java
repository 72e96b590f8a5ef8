package org.openworld.engine.camera;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.openworld.engine.settings.TextFile;

/**
 * Reads the plain-text camera path format (docs/camera-paths.md):
 * <pre>
 *   # comment to the end of the line; blank lines are fine
 *   heights ground              # optional, before the first key: y above sea (default) or above the ground
 *   # time  x      y    z      yaw  pitch  [fov]
 *   0       120    1.7  240    0    -5
 *   5       121    1.7  232.5  5    -5     55
 * </pre>
 * Every problem is reported as a {@link CameraPathFormatException} that points at the offending token. The file is
 * read as UTF-8 with a leading byte order mark skipped ({@link TextFile}); a file that is not text says so.
 */
public final class CameraPathParser {

    /** A plain decimal number: no NaN, Infinity, hexadecimal or type suffixes, which Double.parseDouble allows. */
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");

    /**
     * Largest magnitude of any number, 10⁹ (metres, seconds or degrees): far beyond any world or flight, and small
     * enough that the path's arithmetic (reflected end points, distances, their products in the curve) stays finite;
     * 1e308 would sample as NaN.
     */
    static final double MAX_MAGNITUDE = 1e9;

    /**
     * Shortest time between keys, seconds: the format's precision ({@link CameraPathRecorder#MIN_INTERVAL}), less a
     * micro-second for times printed to 1 ms whose difference rounds a hair below it. Closer keys are a mistake, and
     * 10⁻³²⁰ s apart a turn's slope overflows and samples as NaN.
     */
    static final double MIN_KEY_GAP = CameraPathRecorder.MIN_INTERVAL - 1e-6;

    private static final String DIRECTIVE = "heights";

    private CameraPathParser() {
    }

    /** Parses a file; {@code file} as given is the name used in error messages. */
    public static CameraPath parse(Path file) throws CameraPathFormatException {
        String source = file.toString();
        try {
            return parse(source, TextFile.read(file));
        } catch (NoSuchFileException e) {
            throw unreadable(source, "no such file");
        } catch (TextFile.NotTextException e) {
            throw new CameraPathFormatException(source, e.getMessage());
        } catch (IOException e) {
            throw unreadable(source, "an unreadable file (" + e.getMessage() + ")");
        }
    }

    /** Parses a classpath resource, e.g. {@code assets/paths/orbit.path}; the name is used in error messages. */
    public static CameraPath parseResource(String name) throws CameraPathFormatException {
        try (InputStream in = CameraPathParser.class.getClassLoader().getResourceAsStream(name)) {
            if (in == null) {
                throw unreadable(name, "no such resource on the classpath");
            }
            return parse(name, TextFile.decode(in.readAllBytes()));
        } catch (TextFile.NotTextException e) {
            throw new CameraPathFormatException(name, e.getMessage());
        } catch (IOException e) {
            throw unreadable(name, "an unreadable resource (" + e.getMessage() + ")");
        }
    }

    /**
     * Parses path text.
     *
     * @param source the name used in error messages
     */
    public static CameraPath parse(String source, String text) throws CameraPathFormatException {
        List<String> lines = text.lines().toList();
        HeightReference heights = null;
        List<Keyframe> keys = new ArrayList<>();
        String previousTime = null;
        for (int n = 0; n < lines.size(); n++) {
            Line line = Line.of(source, n + 1, lines.get(n));
            if (line.tokens().isEmpty()) {
                continue;
            }
            if (Character.isLetter(line.token(0).text().charAt(0))) {
                heights = directive(line, heights, !keys.isEmpty());
            } else {
                keys.add(keyframe(line, keys.isEmpty() ? null : keys.get(keys.size() - 1), previousTime));
                previousTime = line.token(0).text();
            }
        }
        if (keys.size() < 2) {
            throw new CameraPathFormatException(source, Math.max(1, lines.size()), 1, "at least 2 keyframes",
                    keys.isEmpty() ? "none" : "1");
        }
        return new CameraPath(heights == null ? HeightReference.SEA : heights, keys);
    }

    /** {@code heights sea|ground}, once, before the first keyframe. */
    private static HeightReference directive(Line line, HeightReference current, boolean afterKeys)
            throws CameraPathFormatException {
        Token name = line.token(0);
        if (!name.text().equals(DIRECTIVE)) {
            throw line.error(name, "a keyframe or the directive 'heights'");
        }
        if (afterKeys) {
            throw line.error(name, "the heights directive before the first keyframe", "it after a keyframe");
        }
        if (current != null) {
            throw line.error(name, "a single heights directive", "a second one");
        }
        if (line.tokens().size() < 2) {
            throw line.errorAtEnd("'sea' or 'ground' after heights");
        }
        Token word = line.token(1);
        HeightReference heights = HeightReference.fromKeyword(word.text())
                .orElseThrow(() -> line.error(word, "'sea' or 'ground' after heights"));
        if (line.tokens().size() > 2) {
            throw line.error(line.token(2), "end of line after heights " + word.text());
        }
        return heights;
    }

    /** {@code time x y z yaw pitch [fov]}, checked left to right so the first bad token is the one reported. */
    private static Keyframe keyframe(Line line, Keyframe previous, String previousTime)
            throws CameraPathFormatException {
        double time = line.number(0, "time");
        if (previous != null && !(time - previous.time() >= MIN_KEY_GAP)) {
            throw line.error(line.token(0), "a time at least 0.001 s after the previous key's " + previousTime);
        }
        double x = coordinate(line, 1, "x");
        double y = coordinate(line, 2, "y");
        double z = coordinate(line, 3, "z");
        double yaw = line.number(4, "yaw");
        double pitch = line.number(5, "pitch");
        if (Math.abs(pitch) > Keyframe.MAX_PITCH) {
            throw line.error(line.token(5), "pitch within [-89, 89] degrees");
        }
        double fov = CameraPose.DEFAULT_FOV;
        if (line.tokens().size() > 6) {
            fov = line.number(6, "fov");
            if (!(fov > Keyframe.MIN_FOV && fov < Keyframe.MAX_FOV)) {
                throw line.error(line.token(6), "fov within (1, 179) degrees");
            }
        }
        if (line.tokens().size() > 7) {
            throw line.error(line.token(7), "end of line after fov");
        }
        return new Keyframe(time, x, y, z, yaw, pitch, fov);
    }

    /** A position's coordinate, metres, within the distance the renderer draws ({@link CameraPose#drawable}). */
    private static double coordinate(Line line, int index, String name) throws CameraPathFormatException {
        double metres = line.number(index, name);
        if (!CameraPose.drawable(metres)) {
            throw line.error(line.token(index),
                    name + " within -16777216 .. 16777216 m (2^24 m, the renderer's reach)");
        }
        return metres;
    }

    private static CameraPathFormatException unreadable(String source, String found) {
        return new CameraPathFormatException(source, 1, 1, "a readable camera path file", found);
    }

    /** A word of a line and its 1-based column. */
    private record Token(String text, int column) {
    }

    /** One line cut into tokens, with the comment removed; it builds the errors that point into it. */
    private record Line(String source, int number, List<Token> tokens, int endColumn) {

        static Line of(String source, int number, String text) {
            int comment = text.indexOf('#');
            String content = comment >= 0 ? text.substring(0, comment) : text;
            List<Token> tokens = new ArrayList<>();
            int i = 0;
            while (i < content.length()) {
                if (Character.isWhitespace(content.charAt(i))) {
                    i++;
                    continue;
                }
                int start = i;
                while (i < content.length() && !Character.isWhitespace(content.charAt(i))) {
                    i++;
                }
                tokens.add(new Token(content.substring(start, i), start + 1));
            }
            int endColumn = tokens.isEmpty() ? 1 : tokens.get(tokens.size() - 1).column()
                    + tokens.get(tokens.size() - 1).text().length();
            return new Line(source, number, tokens, endColumn);
        }

        Token token(int index) {
            return tokens.get(index);
        }

        /** The finite number at {@code index}, named {@code field} in errors. */
        double number(int index, String field) throws CameraPathFormatException {
            if (index >= tokens.size()) {
                throw errorAtEnd("a number for " + field);
            }
            Token token = tokens.get(index);
            if (!NUMBER.matcher(token.text()).matches()) {
                throw error(token, "a number for " + field);
            }
            double value = Double.parseDouble(token.text());
            if (!Double.isFinite(value)) {
                throw error(token, "a finite number for " + field);
            }
            if (Math.abs(value) > MAX_MAGNITUDE) {
                throw error(token, "a number within ±1e9 for " + field);
            }
            return value;
        }

        CameraPathFormatException error(Token at, String expected) {
            return error(at, expected, "'" + at.text() + "'");
        }

        CameraPathFormatException error(Token at, String expected, String found) {
            return new CameraPathFormatException(source, number, at.column(), expected, found);
        }

        CameraPathFormatException errorAtEnd(String expected) {
            return new CameraPathFormatException(source, number, endColumn, expected, "end of line");
        }
    }
}
