package org.openworld.demo;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.Consumer;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.statistics.Statistics;
import net.jqwik.api.statistics.StatisticsCoverage;

/**
 * Hostile text for the fuzz tests: random text, and (more useful, since it reaches past the first check) valid
 * inputs mutated the ways files really break: a BOM, CRLF or tab separators, a swapped, missing, extra or nasty
 * field, a truncated, duplicated, dropped or reordered line, a stray Unicode character. Every generator draws only
 * from the {@link Random} it is given, so a seed replays an input exactly.
 *
 * <p>The inputs are lines of fields; {@code separator} is what separates fields in the format under test ({@code " "}
 * for camera paths, {@code "="} for settings).
 */
final class FuzzInputs {

    /**
     * Values parsers get wrong: non-finite and overflowing numbers, Java literal forms (hex, type suffixes),
     * Unicode digits and spaces, integers just past {@code int}, signs and dots alone, on/off words.
     */
    private static final List<String> NASTY = List.of("NaN", "nan", "Infinity", "-Infinity", "1e400", "-1e400",
            "1e308", "-1e308", "1.7976931348623157E308", "4.9e-324", "1e-320", "0x1p3", "1d", "1f", "1L", "", " ",
            "\u0663", "\uff11", "1\u00a0", "\u00a01", "1,5", "1_000", "+", "-", ".", "e5", "1e", "--1", "+-1", "0.",
            ".5", "2147483647", "2147483648", "-2147483648", "-2147483649", "99999999999999999999", "-0", "0", "1",
            "-1", "89", "89.0000001", "-89.0000001", "90", "1", "1.0000001", "179", "178.9999", "1e9", "-1e9",
            "1e15", "on", "off", "ON", "yes", "true", "2", "#", "=", "==", "\uFEFF", "\u0000", "\t", "\u202e1",
            "\ud83d\ude00", "\ud800", "caf\u00e9", "heights", "sea", "ground");

    /** Characters random text is drawn from: the formats' own syntax, digits, space kinds and a little Unicode. */
    private static final String ALPHABET = "0123456789.-+eE#= \t\r\n\n\nabcxyzNaInfhegtsroundHS_,;:/\\'\"\u00a0\u2028"
            + "\u0085\uFEFF\u00e9\u0663\uff11\ud83d\ude00";

    /** The outcomes the fuzz tests count, as jqwik statistics. */
    private static final String ACCEPTED = "accepted";
    private static final String REFUSED = "refused";

    private final String separator;

    FuzzInputs(String separator) {
        this.separator = separator;
    }

    /** One parse of a fuzzed input, with its checks when accepted. */
    interface Attempt {
        void run() throws Exception;
    }

    /**
     * The property of every fuzz test: the attempt succeeds (its own checks included), or throws {@code refusal},
     * which {@code check} then examines; any other exception fails the property. Counts both outcomes and requires
     * each in at least 5 % of the inputs.
     */
    static <E extends Exception> void acceptedOrRefused(Attempt attempt, Class<E> refusal, Consumer<E> check)
            throws Exception {
        try {
            attempt.run();
            Statistics.collect(ACCEPTED);
        } catch (Exception e) {
            if (!refusal.isInstance(e)) {
                throw e;
            }
            check.accept(refusal.cast(e));
            Statistics.collect(REFUSED);
        }
        Statistics.coverage(FuzzInputs::bothOutcomes);
    }

    /** Inputs for a property: one in ten random text, the others mutations of one of the {@code valid} inputs. */
    Arbitrary<Case> cases(List<String> valid) {
        return Arbitraries.randomValue(random -> Case.of(random.nextInt(10) == 0 ? randomText(random)
                : mutate(valid.get(random.nextInt(valid.size())), random), random));
    }

    /** A new temporary folder for a property's files (the test class removes it after its properties). */
    static Path temporaryFolder(String prefix) {
        try {
            return Files.createTempDirectory(prefix);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Random text, up to a few hundred characters over {@link #ALPHABET}. */
    static String randomText(Random random) {
        int length = random.nextInt(random.nextBoolean() ? 16 : 400);
        StringBuilder s = new StringBuilder(length);
        for (int i = 0; i < length; i++) {
            s.append(ALPHABET.charAt(random.nextInt(ALPHABET.length())));
        }
        return s.toString();
    }

    /**
     * Fails the property unless at least 5 % of its inputs were accepted and 5 % refused: a generator that only ever
     * makes broken inputs (or only valid ones) would let the property pass without testing half of it.
     */
    private static void bothOutcomes(StatisticsCoverage coverage) {
        coverage.check(ACCEPTED).percentage(p -> p >= 5);
        coverage.check(REFUSED).percentage(p -> p >= 5);
    }

    /** One value that is valid now and then and hostile often: a nasty literal, a random number, random text. */
    static String value(Random random) {
        return switch (random.nextInt(6)) {
            case 0, 1 -> NASTY.get(random.nextInt(NASTY.size()));
            case 2 -> Double.toString(random.nextGaussian() * Math.pow(10, random.nextInt(24) - 8));
            case 3 -> Integer.toString(random.nextInt());
            case 4 -> Long.toString(random.nextLong() >> random.nextInt(64));
            default -> randomText(random).strip().replace("\n", "");
        };
    }

    /** {@code valid} with one to four mutations. */
    String mutate(String valid, Random random) {
        String text = valid;
        int count = 1 + random.nextInt(4);
        for (int i = 0; i < count; i++) {
            text = mutateOnce(text, random);
        }
        return text;
    }

    private String mutateOnce(String text, Random random) {
        List<String> lines = new ArrayList<>(Arrays.asList(text.split("\n", -1)));
        int n = random.nextInt(lines.size());
        String line = lines.get(n);
        switch (random.nextInt(16)) {
            case 0 -> {
                return "\uFEFF" + text;
            }
            case 1 -> {
                return text.replace("\n", "\r\n");
            }
            case 2 -> {
                return text.replace(separator, "\t");
            }
            case 3 -> lines.set(n, line.substring(0, random.nextInt(line.length() + 1)));
            case 4 -> lines.add(n, line);
            case 5 -> lines.remove(n);
            case 6 -> lines.set(n, lines.set(random.nextInt(lines.size()), line));
            case 7 -> lines.set(n, withField(line, random, (fields, i) -> fields.set(i, value(random))));
            case 8 -> lines.set(n, withField(line, random, (fields, i) -> fields.add(i, value(random))));
            case 9 -> lines.set(n, withField(line, random, (fields, i) -> fields.remove(i)));
            case 10 -> lines.set(n, withField(line, random,
                    (fields, i) -> fields.set(i, fields.set(random.nextInt(fields.size()), fields.get(i)))));
            case 11 -> lines.set(n, line + separator + value(random));
            case 12 -> lines.set(n, line + (random.nextBoolean() ? "  \t" : " # " + randomText(random)));
            case 13 -> lines.add(n, randomText(random).replace("\n", " "));
            case 14 -> {
                int at = random.nextInt(text.length() + 1);
                return text.substring(0, at) + ALPHABET.charAt(random.nextInt(ALPHABET.length()))
                        + text.substring(Math.min(text.length(), at + random.nextInt(2)));
            }
            default -> {
                return text.substring(0, random.nextInt(text.length() + 1));
            }
        }
        return String.join("\n", lines);
    }

    /** What to do to the fields of a line at one index. */
    private interface FieldEdit {
        void apply(List<String> fields, int index);
    }

    /** The line with one of its fields edited (a line without fields gets the edit at index 0 of one empty one). */
    private String withField(String line, Random random, FieldEdit edit) {
        List<String> fields = new ArrayList<>(Arrays.asList(
                separator.isBlank() ? line.strip().split("\\s+") : line.split(separator, -1)));
        edit.apply(fields, random.nextInt(fields.size()));
        return String.join(separator, fields);
    }

    /**
     * One generated input: its text, and for files a stray byte 0x80..0xFF put in at {@code strayAt} (or none, -1), so
     * that some files are not UTF-8. Printed as a Java literal, which a failing run reports to replay it.
     */
    record Case(String text, int strayAt, int strayByte) {

        /** The text as it is, most of the time; one time in eight a file with a stray byte. */
        static Case of(String text, Random random) {
            int length = text.getBytes(StandardCharsets.UTF_8).length;
            return random.nextInt(8) != 0 ? new Case(text, -1, 0)
                    : new Case(text, random.nextInt(length + 1), 0x80 + random.nextInt(0x80));
        }

        /** The file's bytes: the text in UTF-8, with the stray byte if any. */
        byte[] bytes() {
            byte[] utf8 = text.getBytes(StandardCharsets.UTF_8);
            if (strayAt < 0) {
                return utf8;
            }
            byte[] broken = new byte[utf8.length + 1];
            System.arraycopy(utf8, 0, broken, 0, strayAt);
            broken[strayAt] = (byte) strayByte;
            System.arraycopy(utf8, strayAt, broken, strayAt + 1, utf8.length - strayAt);
            return broken;
        }

        /**
         * Whether {@link #bytes()} are a text file as {@code TextFile} reads one: well-formed UTF-8 without a NUL byte.
         * Anything else is refused as "not a text file: byte 0x.. at offset N", naming the file, before any line.
         */
        boolean isText() {
            try {
                return StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(bytes())).chars().noneMatch(c -> c == 0);
            } catch (CharacterCodingException e) {
                return false;
            }
        }

        /** The message a file that is not text gets, with the file's name in it. */
        static String notTextMessage(String file) {
            return ".*" + java.util.regex.Pattern.quote(file) + ".*not a text file: byte 0x[0-9a-f]{2} at offset \\d+.*";
        }

        @Override
        public String toString() {
            return literal(text) + (strayAt < 0 ? "" : String.format(" with byte 0x%02x at offset %d", strayByte,
                    strayAt));
        }
    }

    /** The text as a Java string literal, every character outside printable ASCII escaped, to replay a failure. */
    static String literal(String text) {
        StringBuilder s = new StringBuilder("\"");
        for (char c : text.toCharArray()) {
            if (c == '"' || c == '\\') {
                s.append('\\').append(c);
            } else if (c == '\n') {
                s.append("\\n");
            } else if (c >= 0x20 && c < 0x7f) {
                s.append(c);
            } else {
                s.append(String.format("\\u%04x", (int) c));
            }
        }
        return s.append('"').toString();
    }
}
