package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A text a test compares with a file kept in the repository (a snapshot): any change to the text fails the test with
 * a line diff, until someone who meant the change updates the file on purpose by running the test with
 * {@code -Dsnapshot.update=true}, for example
 * {@code ./mvnw -B -o -pl engine,demo test -Dtest=InfoFrameSnapshotTest -Dsurefire.failIfNoSpecifiedTests=false
 * -Dsnapshot.update=true},
 * and commits the file with the change that caused it.
 *
 * <p>Snapshots live under {@code demo/src/test/resources/snapshots/}, read and written in the source tree (tests run
 * in the module's folder), so an update shows in {@code git diff}.
 */
final class Snapshot {

    /** The system property that rewrites snapshots instead of comparing with them. */
    static final String UPDATE_PROPERTY = "snapshot.update";

    static final Path FOLDER = Path.of("src/test/resources/snapshots");

    /** Lines of context shown around each change in a failure. */
    private static final int CONTEXT = 2;

    private Snapshot() {
    }

    /** Fails with a diff unless {@code actual} equals the snapshot {@code name}; rewrites it when asked to. */
    static void assertMatches(String name, String actual) throws IOException {
        Path file = FOLDER.resolve(name);
        if (Boolean.getBoolean(UPDATE_PROPERTY)) {
            Files.createDirectories(FOLDER);
            Files.writeString(file, actual);
            return;
        }
        String expected = Files.exists(file) ? Files.readString(file) : "";
        if (!expected.equals(actual)) {
            fail(file.toAbsolutePath().normalize() + " no longer matches (- snapshot, + now):\n"
                    + diff(expected.lines().toList(), actual.lines().toList())
                    + "If the change is meant, update the snapshot: run this test with -D" + UPDATE_PROPERTY
                    + "=true and commit the file.");
        }
    }

    /** A line diff from the longest common subsequence, with {@link #CONTEXT} lines around each change. */
    static String diff(List<String> expected, List<String> actual) {
        int n = expected.size();
        int m = actual.size();
        int[][] common = new int[n + 1][m + 1]; // common[i][j]: LCS length of expected[i..] and actual[j..]
        for (int i = n - 1; i >= 0; i--) {
            for (int j = m - 1; j >= 0; j--) {
                common[i][j] = expected.get(i).equals(actual.get(j)) ? common[i + 1][j + 1] + 1
                        : Math.max(common[i + 1][j], common[i][j + 1]);
            }
        }
        List<String> lines = new ArrayList<>();
        int i = 0;
        int j = 0;
        while (i < n || j < m) {
            if (i < n && j < m && expected.get(i).equals(actual.get(j))) {
                lines.add("  " + expected.get(i++));
                j++;
            } else if (i < n && (j == m || common[i + 1][j] >= common[i][j + 1])) {
                lines.add("- " + expected.get(i++));
            } else {
                lines.add("+ " + actual.get(j++));
            }
        }
        StringBuilder shown = new StringBuilder();
        for (int k = 0; k < lines.size(); k++) {
            if (nearChange(lines, k)) {
                shown.append(lines.get(k)).append('\n');
            } else if (k > 0 && nearChange(lines, k - 1)) {
                shown.append("  ...\n");
            }
        }
        return shown.toString();
    }

    private static boolean nearChange(List<String> lines, int k) {
        for (int d = Math.max(0, k - CONTEXT); d <= Math.min(lines.size() - 1, k + CONTEXT); d++) {
            if (!lines.get(d).startsWith("  ")) {
                return true;
            }
        }
        return false;
    }
}
