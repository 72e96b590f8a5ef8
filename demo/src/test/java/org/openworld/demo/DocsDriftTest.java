package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Pass;
import org.openworld.engine.settings.Settings;

/**
 * The docs name only what exists. For {@code README.md}, {@code CONTRIBUTING.md} and every {@code docs/*.md}, each
 * inline code span outside fenced blocks is read as
 * <ul>
 *   <li>a class ({@code SkySystem}, {@code @Setting}): a type of that name is declared in the sources of
 *       {@code engine/} or {@code demo/}, main or test;</li>
 *   <li>a member ({@code Engine.settingsFor}, {@code Engine#drawOver(...)}, {@code Pass.SHADOW}, {@code Mesh.Attribute}):
 *       the class exists and its source declares or names the member;</li>
 *   <li>a settings key ({@code water.method}, {@code water.method=fresnel}, {@code --set system.water=off}): when its
 *       first part is a settings group of the demo, the key exists and the value is valid;</li>
 *   <li>a repository path ({@code shaders/common/fog.glsl}, {@code demo/.../Gui.java}, a shader under {@code shaders/}
 *       such as {@code common/fog.glsl}): it exists ({@code ...} stands for any folders);</li>
 * </ul>
 * a class's member used in a fenced {@code java} block ({@code CameraPathParser.parse(...)}) exists too;
 * every relative link and image exists, with its {@code #section} when it has one; and every citation of a section of
 * {@code docs/design.md} or {@code CONTRIBUTING.md} (in a page or a source file) names a heading there. A failure
 * names the page, the line and the word. The README's layout table is checked against the repository's folders.
 * GL-free: the settings come from {@code Engine.settingsFor(DemoScene.systems())}, which allocates nothing.
 */
class DocsDriftTest {

    /** Words in code spans that look like ours but are not, each with why it is allowed. Keep it short. */
    static final Map<String, String> NOT_OURS = Map.ofEntries(
            Map.entry("OpenGL", "the graphics API, not a class"),
            Map.entry("NaN", "a number of the camera path format, spelt as Java spells it"),
            Map.entry("Infinity", "a number of the camera path format, spelt as Java spells it"),
            Map.entry("FrameBlock", "the GLSL uniform block of shaders/common/frame.glsl, not a Java class"));

    /**
     * Where a class that is not ours may come from: the JDK and the libraries the code uses (JOML, JTransforms,
     * LWJGL, picocli). A span naming a class of these packages is checked against the class path.
     */
    static final List<String> LIBRARIES = List.of("java.lang.", "java.util.", "java.util.function.", "java.io.",
            "java.nio.", "java.nio.file.", "org.joml.", "org.jtransforms.fft.", "org.lwjgl.system.", "org.lwjgl.glfw.",
            "picocli.");

    private static final Path ROOT = DocPage.ROOT;
    private static final Pattern SPAN = Pattern.compile("`([^`]+)`");
    private static final Pattern LINK = Pattern.compile("!?\\[[^\\]]*\\]\\(([^)\\s]+)\\)");
    private static final Pattern CLASS = Pattern.compile("@?([A-Z][a-z0-9]+(?:[A-Z][A-Za-z0-9]*)*)(?:<.*>)?");
    private static final Pattern MEMBER = Pattern.compile("([A-Z][A-Za-z0-9]*[a-z][A-Za-z0-9]*)[.#]([A-Za-z_][A-Za-z0-9_]*)(?:\\(.*\\))?");
    /** A static call or a nested type in Java code: {@code CameraPathParser.parse}, {@code Mesh.Attribute}. */
    private static final Pattern CALL = Pattern.compile("(?<![\\w.])[A-Z][A-Za-z0-9]*[a-z][A-Za-z0-9]*\\.(?!class\\b)[A-Za-z]\\w*");
    private static final Pattern KEY = Pattern.compile("([a-z][a-z0-9-]*)\\.([a-z][a-z0-9-]*)(?:=(\\S+))?");
    private static final Pattern SET = Pattern.compile("--set[ =]([a-z][a-z0-9-]*\\.\\S+)");
    private static final Pattern PATH = Pattern.compile("(?:engine|demo|shaders|assets|docs)/[\\w./<>-]*"
            + "|[\\w./-]+\\.(?:glsl|vert|frag|geom|comp|md)");
    private static final Pattern CITATION = Pattern.compile("(docs/design\\.md|CONTRIBUTING\\.md),? \"([^\"]+)\"");
    private static final Pattern ANCHOR = Pattern.compile("(docs/design\\.md|CONTRIBUTING\\.md)#([a-z0-9-]+)");
    private static final Pattern DECLARATION = Pattern.compile(
            "\\b(?:class|interface|enum|record|@interface)\\s+([A-Z][A-Za-z0-9_]*)");

    /** Declared type name → the source texts declaring it (a nested type maps to its outer file). */
    private static final Map<String, List<String>> TYPES = new HashMap<>();
    /** Every string literal of the main sources, and every counter's name ({@code sky.tables-ms}, per pass too). */
    private static final Set<String> LITERALS = new HashSet<>();
    private static final Pattern LITERAL = Pattern.compile("\"([^\"\\\\]+)\"");
    private static final Pattern COUNTER = Pattern.compile("Counter\\.of\\(\"([a-z0-9-]+)\", \"([a-z0-9-]+)\"\\)");
    private static Settings settings;
    private static Set<String> groups;

    @BeforeAll
    static void readSources() throws IOException {
        for (String tree : List.of("engine/src/main/java", "engine/src/test/java", "demo/src/main/java",
                "demo/src/test/java")) {
            for (Path file : files(ROOT.resolve(tree), ".java")) {
                String text = Files.readString(file, StandardCharsets.UTF_8);
                Matcher m = DECLARATION.matcher(text);
                while (m.find()) {
                    TYPES.computeIfAbsent(m.group(1), k -> new ArrayList<>()).add(text);
                }
                if (tree.contains("main")) {
                    Matcher literal = LITERAL.matcher(text);
                    while (literal.find()) {
                        LITERALS.add(literal.group(1));
                    }
                    Matcher counter = COUNTER.matcher(text);
                    while (counter.find()) {
                        Counter named = Counter.of(counter.group(1), counter.group(2));
                        LITERALS.add(named.name());
                        Arrays.stream(Pass.values()).forEach(pass -> LITERALS.add(named.in(pass).name()));
                    }
                }
            }
        }
        settings = Engine.settingsFor(DemoScene.systems());
        groups = new HashSet<>();
        settings.keys().forEach(k -> groups.add(k.substring(0, k.indexOf('.'))));
    }

    @Test
    void everyPageNamesOnlyWhatExists() {
        List<String> failures = new ArrayList<>();
        for (DocPage page : DocPage.all()) {
            boolean[] fenced = page.fenced();
            boolean java = false;
            for (int i = 0; i < page.lines().size(); i++) {
                if (fenced[i]) {
                    java = page.lines().get(i).strip().equals("```java") || java && !page.lines().get(i).strip()
                            .startsWith("```");
                    Matcher call = CALL.matcher(java ? page.lines().get(i) : "");
                    while (call.find()) {
                        String problem = checkSpan(call.group());
                        if (problem != null) {
                            failures.add(page.at(i) + ": " + call.group() + ": " + problem);
                        }
                    }
                    continue;
                }
                String line = page.lines().get(i);
                Matcher span = SPAN.matcher(line);
                while (span.find()) {
                    String problem = checkSpan(span.group(1).strip());
                    if (problem != null) {
                        failures.add(page.at(i) + ": `" + span.group(1) + "`: " + problem);
                    }
                }
                Matcher link = LINK.matcher(line);
                while (link.find()) {
                    String problem = checkLink(page, link.group(1));
                    if (problem != null) {
                        failures.add(page.at(i) + ": (" + link.group(1) + "): " + problem);
                    }
                }
                checkCitations(page.at(i), line, failures);
            }
        }
        assertEquals("", String.join("\n", failures), "docs that name what does not exist");
    }

    @Test
    void everySourceCitesSectionsThatExist() throws IOException {
        List<String> failures = new ArrayList<>();
        int citations = 0;
        for (String tree : List.of("engine/src", "demo/src", "shaders")) {
            for (Path file : files(ROOT.resolve(tree), "")) {
                if (!file.toString().matches(".*\\.(java|glsl|vert|frag|geom|comp)")) {
                    continue;
                }
                List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
                for (int i = 0; i < lines.size(); i++) {
                    citations += checkCitations(ROOT.relativize(file) + ":" + (i + 1), lines.get(i), failures);
                }
            }
        }
        assertEquals("", String.join("\n", failures), "citations of sections that do not exist");
        assertTrue(citations >= 10, "the sources' citations were found: " + citations);
    }

    @Test
    void theReadmeLayoutTableMatchesTheTree() throws IOException, InterruptedException {
        List<String> readme = DocPage.read("README.md").lines();
        int start = readme.indexOf("## Layout");
        assertTrue(start >= 0, "README.md has a '## Layout' section");
        Set<String> listed = new TreeSet<>();
        List<String> failures = new ArrayList<>();
        for (int i = start + 1; i < readme.size() && !readme.get(i).startsWith("## "); i++) {
            String row = readme.get(i);
            if (!row.startsWith("| `")) {
                continue;
            }
            Matcher span = SPAN.matcher(row.substring(0, row.indexOf('|', 1)));
            while (span.find()) {
                String path = span.group(1);
                listed.add(path.split("/")[0]);
                if (!Files.exists(ROOT.resolve(path))) {
                    failures.add("README.md:" + (i + 1) + ": `" + path + "` is in the layout table but not in the tree");
                }
            }
        }
        assumeTrue(Files.exists(ROOT.resolve(".git")), "the tree's tracked folders need a git checkout");
        Process git = new ProcessBuilder("git", "ls-files").directory(ROOT.toFile()).start();
        String tracked = new String(git.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, git.waitFor(), "git ls-files");
        Set<String> folders = new TreeSet<>();
        tracked.lines().filter(f -> f.contains("/") && !f.startsWith(".")).forEach(f -> folders.add(f.split("/")[0]));
        folders.stream().filter(f -> !listed.contains(f))
                .forEach(f -> failures.add("README.md: the folder " + f + "/ is missing from the layout table"));
        assertEquals("", String.join("\n", failures), "the README's layout table against the tree");
        assertTrue(listed.size() >= 5, "the layout table's rows were read: " + listed);
    }

    /**
     * A page's settings table ({@code | key | default | unit | meaning |}, as {@code openworld settings} prints them)
     * gives each key's real default and unit.
     */
    @Test
    void settingsTablesGiveTheRealDefaultsAndUnits() {
        Settings defaults = settings.defaults();
        Map<String, String> units = new HashMap<>();
        settings.groups().forEach(g -> g.keys().forEach(k -> units.put(k.key(), k.doc().unit())));
        List<String> failures = new ArrayList<>();
        int rows = 0;
        for (DocPage page : DocPage.all()) {
            List<String> lines = page.lines();
            for (int i = 0; i < lines.size(); i++) {
                if (!lines.get(i).replace(" ", "").equals("|key|default|unit|meaning|")) {
                    continue;
                }
                for (int j = i + 2; j < lines.size() && lines.get(j).startsWith("|"); j++) {
                    String[] cells = lines.get(j).split("\\|");
                    String key = cells[1].strip().replace("`", "");
                    String given = cells[2].strip();
                    rows++;
                    if (!settings.keys().contains(key)) {
                        failures.add(page.at(j) + ": `" + key + "`: no settings key " + key);
                        continue;
                    }
                    String real = defaults.text(key).isEmpty() ? "(none)" : defaults.text(key);
                    if (!given.equals(real)) {
                        failures.add(page.at(j) + ": `" + key + "`: the default is " + real + ", not " + given);
                    }
                    String unit = units.getOrDefault(key, "");
                    if (!cells[3].strip().equals(unit)) {
                        failures.add(page.at(j) + ": `" + key + "`: the unit is '" + unit + "', not '"
                                + cells[3].strip() + "'");
                    }
                }
            }
        }
        assertEquals("", String.join("\n", failures), "settings tables against the settings");
        assertTrue(rows >= 20, "the settings tables' rows were read: " + rows);
    }

    /**
     * The design page's caption links each of the demo's systems to its page, by the system's name; a system
     * added to {@code DemoScene.systems()} must be added there too.
     */
    @Test
    void theDesignPageLinksEveryDemoSystem() {
        List<String> page = DocPage.read("docs/design.md").lines();
        int from = 0;
        while (from < page.size() && !page.get(from).contains("`DemoScene.systems()`")) {
            from++;
        }
        assertTrue(from < page.size(), "docs/design.md names DemoScene.systems()");
        Set<String> linked = new TreeSet<>();
        for (int i = from; i < page.size() && !page.get(i).isBlank(); i++) {
            Matcher link = LINK.matcher(page.get(i));
            while (link.find()) {
                linked.add(link.group().substring(1, link.group().indexOf(']')));
            }
        }
        Set<String> systems = new TreeSet<>();
        DemoScene.systems().forEach(system -> systems.add(system.spec().name()));
        assertEquals(systems, linked, "docs/design.md:" + (from + 1) + ": the demo's systems, each linked by name");
    }

    @Test
    void theRecognisersTellOursFromProse() {
        assertEquals(null, checkSpan("SkySystem"));
        assertTrue(checkSpan("SkyColoursTest") != null, "a test class that does not exist");
        assertEquals(null, checkSpan("Engine.settingsFor(systems)"));
        assertTrue(checkSpan("Engine.settingsForAll") != null, "a method that does not exist");
        assertEquals(null, checkSpan("--set system.water=off"));
        assertTrue(checkSpan("water.methd") != null, "a key that does not exist in a group that does");
        assertTrue(checkSpan("water.method=teleport") != null, "a value the key does not take");
        assertEquals(null, checkSpan("frames.csv"), "a file name is not a settings key");
        assertEquals(null, checkSpan("demo/.../Gui.java"));
        assertTrue(checkSpan("shaders/sky/rainbow.frag") != null, "a shader that does not exist");
        assertEquals(null, checkSpan("openworld shot --out x.png"), "a command is prose to this test");
        assertEquals(null, checkSpan("FrustumIntersection.testAab"), "a library's class and method");
        assertTrue(checkSpan("FrustumIntersection.testBall") != null, "a library method that does not exist");
        assertEquals(null, checkSpan("sky.tables-ms"), "a counter's name is a string the sources write");
    }

    /** What is wrong with what a code span names, or null when it names what exists (or nothing this test reads). */
    static String checkSpan(String span) {
        if (NOT_OURS.containsKey(span)) {
            return null;
        }
        Matcher set = SET.matcher(span);
        if (set.find()) {
            return checkKey(set.group(1));
        }
        Matcher m;
        if ((m = PATH.matcher(span.replaceFirst(":\\d+:.*$", ""))).matches()) {
            return checkPath(m.group());
        }
        if ((m = MEMBER.matcher(span)).matches()) {
            if (NOT_OURS.containsKey(m.group(1))) {
                return null;
            }
            if (!TYPES.containsKey(m.group(1)) && library(m.group(1)) != null) {
                Class<?> type = library(m.group(1));
                String name = m.group(2);
                return Stream.concat(Stream.of(type.getMethods()).map(java.lang.reflect.Member::getName),
                        Stream.of(type.getFields()).map(java.lang.reflect.Member::getName)).anyMatch(name::equals)
                        ? null : type.getName() + " has no " + name;
            }
            List<String> sources = TYPES.get(m.group(1));
            if (sources == null) {
                return "no class " + m.group(1) + " in engine/ or demo/";
            }
            Pattern member = Pattern.compile("\\b" + Pattern.quote(m.group(2)) + "\\b");
            return sources.stream().anyMatch(s -> member.matcher(s).find()) ? null
                    : m.group(1) + " has no " + m.group(2);
        }
        if ((m = CLASS.matcher(span)).matches()) {
            return NOT_OURS.containsKey(m.group(1)) || TYPES.containsKey(m.group(1)) || library(m.group(1)) != null
                    ? null : "no class " + m.group(1) + " in engine/ or demo/ (main or test) nor in a library";
        }
        if ((m = KEY.matcher(span)).matches() && groups.contains(m.group(1))) {
            return m.group(3) == null && LITERALS.contains(span) ? null : checkKey(span);
        }
        return null;
    }

    private static String checkKey(String assignment) {
        String key = assignment.contains("=") ? assignment.substring(0, assignment.indexOf('=')) : assignment;
        if (key.contains("<") || !settings.keys().contains(key)) {
            return key.contains("<") ? null : "no settings key " + key;
        }
        String value = assignment.contains("=") ? assignment.substring(assignment.indexOf('=') + 1) : null;
        if (value == null || value.contains("<") || value.contains("...") || value.matches("[A-Z]+")) {
            return null;
        }
        try {
            settings.defaults().apply(assignment);
            return null;
        } catch (RuntimeException e) {
            return "not a valid setting: " + e.getMessage();
        }
    }

    /**
     * A path from the root ({@code engine/...}), a page ({@code README.md}, {@code docs/x.md}) or a shader named from
     * {@code shaders/} or from its system's folder ({@code common/fog.glsl}, {@code flake.vert}). {@code ...} stands
     * for any folders; a path with a placeholder ({@code recorded-YYYYMMDD.path}, {@code shaders/<system>/}) needs
     * only its part before the placeholder; build outputs (under {@code target/}) are not in the tree to check.
     */
    private static String checkPath(String path) {
        if (path.contains("/target/")) {
            return null;
        }
        String relative = path.matches("(?:engine|demo|shaders|assets|docs)/.*") || path.endsWith(".md") ? path
                : "shaders/.../" + path;
        if (relative.endsWith(".md") && !Files.exists(ROOT.resolve(relative))) {
            relative = "docs/" + relative;
        }
        Matcher placeholder = Pattern.compile("[^/]*(?:[A-Z]{2,}|<)").matcher(relative);
        if (placeholder.find()) {
            relative = relative.substring(0, placeholder.start());
        }
        if (!relative.contains("...")) {
            return Files.exists(ROOT.resolve(relative)) ? null : "no file " + relative;
        }
        String prefix = relative.substring(0, relative.indexOf("..."));
        String suffix = relative.substring(relative.indexOf("...") + 3);
        try (Stream<Path> walk = Files.walk(ROOT.resolve(prefix))) {
            return walk.map(f -> ROOT.relativize(f).toString().replace('\\', '/') + (Files.isDirectory(f) ? "/" : ""))
                    .anyMatch(f -> f.endsWith(suffix)) ? null : "no file matches " + relative;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The library class of this simple name, or null. */
    private static Class<?> library(String simpleName) {
        for (String pkg : LIBRARIES) {
            try {
                return Class.forName(pkg + simpleName, false, DocsDriftTest.class.getClassLoader());
            } catch (ClassNotFoundException e) {
                // not in this package; the next one
            }
        }
        return null;
    }

    /** What is wrong with a link on a page (its file or its section missing), or null; PaperPageTest asks too. */
    static String checkLink(DocPage page, String target) {
        if (target.matches("[a-z]+:.*")) {
            return null;
        }
        String file = target.contains("#") ? target.substring(0, target.indexOf('#')) : target;
        String anchor = target.contains("#") ? target.substring(target.indexOf('#') + 1) : null;
        Path resolved = file.isEmpty() ? ROOT.resolve(page.name()) : page.folder().resolve(file).normalize();
        if (!Files.exists(resolved)) {
            return "no file " + ROOT.relativize(resolved);
        }
        if (anchor != null && !anchors(resolved).contains(anchor)) {
            return "no section #" + anchor + " in " + ROOT.relativize(resolved);
        }
        return null;
    }

    /** Checks the section citations on one line, adds a failure for each missing section; returns how many it read. */
    private static int checkCitations(String at, String line, List<String> failures) {
        int count = 0;
        Matcher m = CITATION.matcher(line);
        while (m.find()) {
            count++;
            if (!headings(ROOT.resolve(m.group(1))).contains(m.group(2))) {
                failures.add(at + ": " + m.group() + ": " + m.group(1) + " has no section \"" + m.group(2) + "\"");
            }
        }
        m = ANCHOR.matcher(line);
        while (m.find()) {
            count++;
            if (!anchors(ROOT.resolve(m.group(1))).contains(m.group(2))) {
                failures.add(at + ": " + m.group() + ": " + m.group(1) + " has no section #" + m.group(2));
            }
        }
        return count;
    }

    /** The headings of a page, as written (without the #s). */
    static List<String> headings(Path page) {
        try {
            return Files.readAllLines(page).stream().filter(l -> l.matches("#{1,6} .*"))
                    .map(l -> l.replaceFirst("^#+ ", "").strip()).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The anchors a page's headings get, made as GitHub makes them: lower case, punctuation dropped, spaces to -. */
    static List<String> anchors(Path page) {
        if (!page.toString().endsWith(".md")) {
            return List.of();
        }
        return headings(page).stream().map(h -> h.toLowerCase(Locale.ROOT).replace("`", "")
                .replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-')).toList();
    }

    private static List<Path> files(Path folder, String suffix) {
        if (!Files.isDirectory(folder)) {
            return List.of();
        }
        try (Stream<Path> walk = Files.walk(folder)) {
            return walk.filter(Files::isRegularFile).filter(f -> f.toString().endsWith(suffix)).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
