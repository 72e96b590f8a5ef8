package org.openworld.engine.minimap;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@code docs/adding-a-system.md} shows the minimap's code in excerpts: each fenced block after a line
 * {@code <!-- excerpt: PATH -->} must appear in that file (relative to the repository root) line for line, leading
 * spaces aside, so the walk-through and the shipped code cannot part ways.
 */
class WalkThroughExcerptsTest {

    /** The repository root, seen from the engine module's folder, where the tests run. */
    static final Path ROOT = Path.of("..");
    static final String MARK = "<!-- excerpt: ";

    @Test
    void everyExcerptIsInItsFile() throws IOException {
        List<String> page = Files.readAllLines(ROOT.resolve("docs/adding-a-system.md"));
        int excerpts = 0;
        for (int i = 0; i < page.size(); i++) {
            if (!page.get(i).startsWith(MARK)) {
                continue;
            }
            String file = page.get(i).substring(MARK.length(), page.get(i).indexOf(" -->"));
            assertTrue(page.get(i + 1).startsWith("```"), "a fenced block follows the mark for " + file);
            List<String> block = new ArrayList<>();
            for (int j = i + 2; !page.get(j).startsWith("```"); j++) {
                block.add(page.get(j).strip());
            }
            List<String> source = Files.readAllLines(ROOT.resolve(file)).stream().map(String::strip).toList();
            assertTrue(Collections.indexOfSubList(source, block) >= 0,
                    "docs/adding-a-system.md line " + (i + 1) + ": the excerpt is not in " + file + " as shown");
            excerpts++;
        }
        assertTrue(excerpts >= 8, "the page's excerpts were found: " + excerpts);
    }
}
