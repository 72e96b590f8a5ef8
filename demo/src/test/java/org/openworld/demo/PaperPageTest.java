package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * {@code docs/paper.md}, the paper read beside the code, stays complete: it has a heading for every section of the
 * paper, names each of the paper's figures and equations under the section that holds it, links only to files that
 * exist, and names as tests only test classes that exist under {@code engine/src/test} or {@code demo/src/test}.
 * The paper's sections, figures and equations are facts about the paper (Dehlin 2017), written out here, so the test
 * reads nothing outside the repository. GL-free.
 */
class PaperPageTest {

    static final String PAGE = "docs/paper.md";

    /** The paper's numbered sections, in order. */
    static final List<String> SECTIONS = List.of("1", "2", "2.1", "2.2", "2.3", "2.4", "2.5", "3", "3.1", "3.2",
            "3.3", "4", "5", "6");

    /** Each of the paper's figures 1–14, by number, and the section that shows it. */
    static final Map<Integer, String> FIGURES = Map.ofEntries(Map.entry(1, "2.2"), Map.entry(2, "2.2"),
            Map.entry(3, "2.2"), Map.entry(4, "2.2"), Map.entry(5, "2.3"), Map.entry(6, "2.5"), Map.entry(7, "3.1"),
            Map.entry(8, "3.1"), Map.entry(9, "3.1"), Map.entry(10, "3.2"), Map.entry(11, "3.2"),
            Map.entry(12, "3.2"), Map.entry(13, "3.3"), Map.entry(14, "4"));

    /** Each of the paper's equations 1–4, by number, and the section that states it. */
    static final Map<Integer, String> EQUATIONS = Map.of(1, "2.5", 2, "2.5", 3, "3.1", 4, "3.1");

    /** A heading that names one of the paper's sections: {@code ## 2 The large world problem}, {@code ### 2.1 ...}. */
    private static final Pattern SECTION = Pattern.compile("#{2,3} (\\d(?:\\.\\d)?) \\S.*");
    private static final Pattern FIGURE = Pattern.compile("\\b[Ff]igures? (\\d+)[a-f]?\\b");
    private static final Pattern EQUATION = Pattern.compile("\\b[Ee]quations? (\\d+)\\b");
    private static final Pattern LINK = Pattern.compile("!?\\[[^\\]]*\\]\\(([^)\\s]+)\\)");
    private static final Pattern TEST = Pattern.compile("\\b[A-Z][A-Za-z0-9]*Test\\b");

    @Test
    void thePageCoversThePaper() {
        DocPage page = DocPage.read(PAGE);
        assertEquals(List.of(), problems(page, testClasses()), PAGE + " against the paper and the repository");
    }

    /** The checks catch what they are for: on a copy of the page with one thing broken at a time. */
    @Test
    void theChecksCatchWhatIsMissing() {
        DocPage page = DocPage.read(PAGE);
        Set<String> tests = testClasses();
        assertEquals(List.of(), problems(page, tests), "the page itself passes");

        List<String> noFigureSeven = page.lines().stream().map(l -> l.replaceAll("\\b[Ff]igures? 7\\b", "the diagram"))
                .toList();
        assertEquals(List.of("figure 7 is not named under section 3.1"),
                problems(new DocPage(PAGE, noFigureSeven), tests));

        List<String> brokenLink = new ArrayList<>(page.lines());
        brokenLink.add("See [a missing file](../engine/src/main/java/Missing.java).");
        assertEquals(List.of(PAGE + ":" + brokenLink.size() + ": (../engine/src/main/java/Missing.java): no file "
                + "engine/src/main/java/Missing.java"), problems(new DocPage(PAGE, brokenLink), tests));

        List<String> noSuchTest = new ArrayList<>(page.lines());
        noSuchTest.add("| tests | `SkyColoursTest` |");
        assertEquals(List.of(PAGE + ":" + noSuchTest.size() + ": SkyColoursTest is no test class under "
                + "engine/src/test or demo/src/test"), problems(new DocPage(PAGE, noSuchTest), tests));

        List<String> noSectionFive = page.lines().stream().map(l -> l.startsWith("## 5 ") ? "## Problems" : l)
                .toList();
        assertEquals(List.of("no heading for the paper's section 5"),
                problems(new DocPage(PAGE, noSectionFive), tests));
    }

    /** What is wrong with the page: each missing section, figure or equation, broken link and unknown test. */
    static List<String> problems(DocPage page, Set<String> testClasses) {
        List<String> problems = new ArrayList<>();
        boolean[] fenced = page.fenced();
        Map<String, Set<Integer>> figures = new TreeMap<>();
        Map<String, Set<Integer>> equations = new TreeMap<>();
        String section = null;
        for (int i = 0; i < page.lines().size(); i++) {
            String line = page.lines().get(i);
            if (fenced[i]) {
                continue;
            }
            Matcher heading = SECTION.matcher(line);
            if (heading.matches()) {
                section = heading.group(1);
            } else if (line.startsWith("## ")) {
                section = null; // a heading of the page's own, not a section of the paper
            }
            if (section != null) {
                collect(FIGURE, line, figures.computeIfAbsent(section, s -> new TreeSet<>()));
                collect(EQUATION, line, equations.computeIfAbsent(section, s -> new TreeSet<>()));
            }
            Matcher link = LINK.matcher(line);
            while (link.find()) {
                String problem = DocsDriftTest.checkLink(page, link.group(1));
                if (problem != null) {
                    problems.add(page.at(i) + ": (" + link.group(1) + "): " + problem);
                }
            }
            Matcher test = TEST.matcher(line);
            while (test.find()) {
                if (!testClasses.contains(test.group())) {
                    problems.add(page.at(i) + ": " + test.group() + " is no test class under engine/src/test or "
                            + "demo/src/test");
                }
            }
        }
        SECTIONS.stream().filter(s -> !figures.containsKey(s))
                .forEach(s -> problems.add("no heading for the paper's section " + s));
        FIGURES.forEach((n, s) -> {
            if (!figures.getOrDefault(s, Set.of()).contains(n)) {
                problems.add("figure " + n + " is not named under section " + s);
            }
        });
        EQUATIONS.forEach((n, s) -> {
            if (!equations.getOrDefault(s, Set.of()).contains(n)) {
                problems.add("equation " + n + " is not named under section " + s);
            }
        });
        problems.sort(null);
        return problems;
    }

    private static void collect(Pattern numbered, String line, Set<Integer> into) {
        Matcher m = numbered.matcher(line);
        while (m.find()) {
            into.add(Integer.parseInt(m.group(1)));
        }
    }

    /** The names of the test classes: every {@code *Test.java} under {@code engine/src/test} and {@code demo/src/test}. */
    static Set<String> testClasses() {
        Set<String> names = new TreeSet<>();
        for (String tree : List.of("engine/src/test", "demo/src/test")) {
            try (Stream<Path> walk = Files.walk(DocPage.ROOT.resolve(tree))) {
                walk.map(p -> p.getFileName().toString()).filter(n -> n.endsWith("Test.java"))
                        .forEach(n -> names.add(n.substring(0, n.length() - ".java".length())));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        assertTrue(names.size() >= 100, "the test classes were found: " + names.size());
        return names;
    }
}
