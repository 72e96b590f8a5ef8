package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * No source, shader, asset or page cites an issue number (the word followed by a number): the reader has the
 * repository, not the tracker, so a comment or a heading says what the work was for instead (CONTRIBUTING.md,
 * "Numbers carry units" asks the same of numbers: a reason the reader can check).
 */
class NoIssueNumbersTest {

    /** The pattern of the working rules' check, {@code grep -rniE "issue ?[0-9]+"}. */
    private static final Pattern CITATION = Pattern.compile("issue ?[0-9]+", Pattern.CASE_INSENSITIVE);

    /** What is read: the folders a reader opens and the two top-level pages; build outputs are not ours. */
    private static final List<String> SEARCHED = List.of("engine/src", "demo/src", "shaders", "assets", "docs", ".ci",
            "README.md", "CONTRIBUTING.md");

    @Test
    void nothingCitesAnIssueNumber() throws IOException {
        List<String> failures = new ArrayList<>();
        int read = 0;
        for (String top : SEARCHED) {
            try (Stream<Path> files = Files.walk(DocPage.ROOT.resolve(top))) {
                for (Path file : files.filter(Files::isRegularFile).filter(NoIssueNumbersTest::isText).toList()) {
                    read++;
                    List<String> lines = Files.readAllLines(file, StandardCharsets.ISO_8859_1);
                    for (int i = 0; i < lines.size(); i++) {
                        if (CITATION.matcher(lines.get(i)).find()) {
                            failures.add(DocPage.ROOT.relativize(file) + ":" + (i + 1) + ": " + lines.get(i).strip());
                        }
                    }
                }
            }
        }
        assertTrue(read > 100, "read only " + read + " files: is the repository root " + DocPage.ROOT + "?");
        assertEquals(List.of(), failures, "issue numbers cited (say what the work was for instead)");
    }

    /** The examples are put together at run time, so this file passes its own check and the grep. */
    @Test
    void theCheckFindsACitation() {
        String word = "Issue";
        assertTrue(CITATION.matcher("the 10 % " + word + " 21 allows").find());
        assertTrue(CITATION.matcher("(" + word.toLowerCase() + "20)").find());
    }

    private static boolean isText(Path file) {
        String name = file.getFileName().toString();
        return !name.matches(".*\\.(png|jpe?g|bin|raw|r16|ktx|class|jar)$");
    }
}
