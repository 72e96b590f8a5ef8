package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Code quoted by a page cannot part ways with the code: every fenced block after a line
 * {@code <!-- excerpt: PATH -->} (PATH relative to the repository root), on every page, must appear in that file
 * line for line and in order, leading and trailing spaces aside. A block line that is only {@code // ...} or
 * {@code ...} stands for any run of lines, none included, so a quote can leave out what does not concern it and an
 * unrelated edit to the file (one more system in a list) does not break the page. The format is described in
 * {@code CONTRIBUTING.md}, "Excerpts".
 */
class DocsExcerptsTest {

    static final String MARK = "<!-- excerpt: ";

    @Test
    void everyExcerptIsInItsFile() throws IOException {
        int excerpts = 0;
        List<String> failures = new ArrayList<>();
        for (DocPage page : DocPage.all()) {
            List<String> lines = page.lines();
            boolean[] fenced = page.fenced();
            for (int i = 0; i < lines.size(); i++) {
                if (fenced[i] || !lines.get(i).startsWith(MARK)) {
                    continue;
                }
                String file = lines.get(i).substring(MARK.length(), lines.get(i).indexOf(" -->"));
                if (i + 1 >= lines.size() || !lines.get(i + 1).startsWith("```")) {
                    failures.add(page.at(i) + ": no fenced block follows the excerpt mark for " + file);
                    continue;
                }
                List<String> block = new ArrayList<>();
                for (int j = i + 2; j < lines.size() && !lines.get(j).startsWith("```"); j++) {
                    block.add(lines.get(j).strip());
                }
                if (!Files.isRegularFile(DocPage.ROOT.resolve(file))) {
                    failures.add(page.at(i) + ": the excerpt's file " + file + " does not exist");
                } else if (!contains(Files.readAllLines(DocPage.ROOT.resolve(file)).stream().map(String::strip)
                        .toList(), block)) {
                    failures.add(page.at(i) + ": the excerpt is not in " + file + " as shown");
                }
                excerpts++;
            }
        }
        assertEquals(List.of(), failures, "excerpts that do not match their files");
        assertTrue(excerpts >= 12, "the pages' excerpts were found: " + excerpts);
    }

    @Test
    void anEllipsisLineStandsForAnyRunOfLines() {
        List<String> source = List.of("a", "b", "c", "d", "e");
        assertTrue(contains(source, List.of("b", "c")));
        assertTrue(contains(source, List.of("a", "// ...", "d", "e")));
        assertTrue(contains(source, List.of("b", "...", "c")), "the run may be empty");
        assertTrue(contains(source, List.of("// ...", "e")));
        assertTrue(!contains(source, List.of("b", "d")), "without the ellipsis, lines must be consecutive");
        assertTrue(!contains(source, List.of("d", "// ...", "b")), "the parts keep their order");
        assertTrue(!contains(source, List.of("a", "// ...", "f")));
    }

    /**
     * Whether {@code block}'s parts (the runs of lines between ellipsis lines) appear in {@code source} in order, each
     * part consecutively. Taking each part's earliest place leaves the most room to the parts after it, so one pass
     * decides.
     */
    static boolean contains(List<String> source, List<String> block) {
        int from = 0;
        List<String> part = new ArrayList<>();
        List<List<String>> parts = new ArrayList<>();
        for (String line : block) {
            if (line.equals("// ...") || line.equals("...")) {
                parts.add(List.copyOf(part));
                part.clear();
            } else {
                part.add(line);
            }
        }
        parts.add(part);
        for (List<String> each : parts) {
            if (each.isEmpty()) {
                continue;
            }
            int at = indexOf(source, each, from);
            if (at < 0) {
                return false;
            }
            from = at + each.size();
        }
        return true;
    }

    private static int indexOf(List<String> source, List<String> part, int from) {
        for (int i = from; i + part.size() <= source.size(); i++) {
            if (source.subList(i, i + part.size()).equals(part)) {
                return i;
            }
        }
        return -1;
    }
}
