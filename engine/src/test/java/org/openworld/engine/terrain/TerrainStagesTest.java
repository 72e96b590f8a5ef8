package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The terrain's stages depend one way: each sub-package of {@code terrain} reads only the stages before it in the
 * map its {@code package-info} prints ({@code <li>{@code terrain.heights}: ...}), and the system's own package comes
 * last. Read from the main sources, without compiling or loading anything: every {@code import} line and every name
 * written out in full outside comments ({@code org.openworld.engine.terrain.stage.Type}) is a dependency. A Javadoc
 * link may point ahead (written in full inside the comment), since reading on is not depending. The shaders mirror
 * the packages: {@code shaders/terrain/<stage>/} holds a stage's files, {@code shaders/terrain/} the system's
 * programs, and an {@code #include} is a dependency too.
 */
class TerrainStagesTest {

    static final Path TERRAIN = Path.of("src/main/java/org/openworld/engine/terrain");
    static final String PACKAGE = "org.openworld.engine.terrain";
    /** One stage of the map: {@code <li>{@code terrain.heights}: ...} or {@code <li>{@code terrain}, ...}. */
    static final Pattern STAGE = Pattern.compile("<li>\\{@code terrain(\\.(\\w+))?}");
    /** A reference to a terrain package: a stage's name after the terrain's, or a type of the terrain's own. */
    static final Pattern REFERENCE = Pattern.compile(Pattern.quote(PACKAGE) + "\\.(\\w+)(\\.[A-Z]\\w*)?");
    /** The terrain's shaders, one folder per stage that has any, the system's programs at the top. */
    static final Path SHADERS = Path.of("../shaders/terrain");
    /** An include of a terrain shader: {@code #include "terrain/material/material.glsl"}, the stage in group 2. */
    static final Pattern INCLUDE = Pattern.compile("#include \"terrain/((\\w+)/)?[\\w.]+\"");

    /**
     * Code that asks which kind of world it is in: a layout's {@code streamed()}, the {@code terrain.world} setting
     * compared with {@code ==} or {@code !=}, or a ground tested with {@code instanceof}. The setting picks the
     * ground once, in a {@code switch} over its values; everything after asks the ground.
     */
    static final Pattern WORLD_BRANCH = Pattern.compile("\\.streamed\\(\\)|\\.world\\(\\)\\s*[!=]="
            + "|[!=]=\\s*(\\w+\\.)*World\\.\\w+|instanceof\\s+\\w*Ground\\b");

    /** The branches on the world kind in a file's code, one message each. */
    static List<String> worldBranches(String file, String source) {
        List<String> found = new ArrayList<>();
        Matcher m = WORLD_BRANCH.matcher(code(source));
        while (m.find()) {
            found.add(file + " branches on the world kind: " + m.group());
        }
        return found;
    }

    /** The stages in the map's order, by sub-package name; "" for the system's own package. */
    static List<String> stages() throws IOException {
        List<String> order = new ArrayList<>();
        Matcher m = STAGE.matcher(Files.readString(TERRAIN.resolve("package-info.java")));
        while (m.find()) {
            order.add(m.group(2) == null ? "" : m.group(2));
        }
        return order;
    }

    /** The file's code without comments and string literals, where a written-out name is a dependency. */
    static String code(String source) {
        return source.replaceAll("(?s)/\\*.*?\\*/", "").replaceAll("//[^\\n]*", "")
                .replaceAll("\"(\\\\.|[^\"\\\\])*\"", "\"\"");
    }

    /**
     * The dependencies of a file of stage {@code stage} on later stages, one message each.
     *
     * @param stages the map's order ({@link #stages})
     */
    static List<String> backward(String file, String stage, String source, List<String> stages) {
        List<String> found = new ArrayList<>();
        int own = stages.indexOf(stage);
        Matcher m = REFERENCE.matcher(code(source));
        while (m.find()) {
            String name = m.group(1);
            String other = Character.isUpperCase(name.charAt(0)) ? "" : name;
            if (stages.indexOf(other) > own) {
                found.add(file + " (stage '" + stage + "') reads " + m.group() + " of the later stage '"
                        + other + "'");
            }
        }
        return found;
    }

    @Test
    void everySubPackageIsAStageOfTheMapInOrder() throws IOException {
        List<String> stages = stages();
        TreeSet<String> packages = new TreeSet<>();
        try (Stream<Path> dirs = Files.list(TERRAIN)) {
            dirs.filter(Files::isDirectory).forEach(d -> packages.add(d.getFileName().toString()));
        }
        packages.add("");
        assertEquals(packages, new TreeSet<>(stages), "the map in terrain's package-info lists " + stages
                + ", the folders are " + packages);
        assertEquals("", stages.get(stages.size() - 1), "the system's own package comes last: " + stages);
        System.out.println("terrain stages, each reading only those before it: " + stages);
    }

    @Test
    void noStageReadsALaterOne() throws IOException {
        List<String> stages = stages();
        List<String> found = new ArrayList<>();
        try (Stream<Path> files = Files.walk(TERRAIN)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).sorted().toList()) {
                Path dir = TERRAIN.relativize(f).getParent();
                String stage = dir == null ? "" : dir.toString();
                found.addAll(backward(TERRAIN.relativize(f).toString(), stage, Files.readString(f), stages));
            }
        }
        assertTrue(found.isEmpty(), String.join("\n", found));
    }

    /** The includes of a shader of stage {@code stage} from later stages, one message each. */
    static List<String> backwardIncludes(String file, String stage, String source, List<String> stages) {
        List<String> found = new ArrayList<>();
        Matcher m = INCLUDE.matcher(source);
        while (m.find()) {
            String other = m.group(2) == null ? "" : m.group(2);
            if (stages.indexOf(other) > stages.indexOf(stage)) {
                found.add(file + " (stage '" + stage + "') includes " + m.group() + " of the later stage '" + other
                        + "'");
            }
        }
        return found;
    }

    @Test
    void theShadersMirrorTheStages() throws IOException {
        List<String> stages = stages();
        List<String> found = new ArrayList<>();
        try (Stream<Path> files = Files.walk(SHADERS)) {
            for (Path f : files.filter(Files::isRegularFile).sorted().toList()) {
                Path dir = SHADERS.relativize(f).getParent();
                String stage = dir == null ? "" : dir.toString();
                if (!stages.contains(stage)) {
                    found.add(f + " lies in '" + stage + "', which is no stage of the map " + stages);
                }
                found.addAll(backwardIncludes(SHADERS.relativize(f).toString(), stage, Files.readString(f), stages));
            }
        }
        assertTrue(found.isEmpty(), String.join("\n", found));
    }

    @Test
    void aLaterStageIncludedByAnEarlierShaderIsFound() {
        List<String> stages = List.of("heights", "material", "stream", "");
        String source = "#include \"common/frame.glsl\"\n#include \"terrain/material/horizon.glsl\"\n"
                + "#include \"terrain/stream/clipmap.glsl\"\n#include \"terrain/terrain.vert\"\n";
        List<String> found = backwardIncludes("material/x.frag", "material", source, stages);
        assertEquals(2, found.size(), "the later stream's and the system's includes, not its own: " + found);
        assertTrue(found.get(0).contains("stream/clipmap") && found.get(1).contains("terrain/terrain.vert"),
                found.toString());
    }

    @Test
    void aLaterStageImportedByAnEarlierOneIsFound() {
        List<String> stages = List.of("heights", "lod", "mesh", "");
        String source = "package " + PACKAGE + ".lod;\n"
                + "import " + PACKAGE + ".heights.HeightMap;\n"
                + "/** Read on: {@link " + PACKAGE + ".mesh.PatchPatterns}. */\n"
                + "class Cut { " + PACKAGE + ".mesh.PatchPatterns patterns; " + PACKAGE + ".TerrainSystem s; }\n";
        List<String> found = backward("lod/Cut.java", "lod", source, stages);
        assertEquals(2, found.size(), "the field's mesh and system types, not the earlier import nor the link: "
                + found);
        assertTrue(found.get(0).contains(".mesh.PatchPatterns") && found.get(1).contains(".TerrainSystem"), found
                .toString());
    }

    /**
     * No class of the terrain branches on the kind of world it draws: the ground, the layout and the residency
     * answer for their kind (polymorphism), and the setting picks the ground once, in a {@code switch}.
     */
    @Test
    void noCodeBranchesOnTheWorldKind() throws IOException {
        List<String> found = new ArrayList<>();
        try (Stream<Path> files = Files.walk(TERRAIN)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).sorted().toList()) {
                found.addAll(worldBranches(TERRAIN.relativize(f).toString(), Files.readString(f)));
            }
        }
        assertTrue(found.isEmpty(), String.join("\n", found));
    }

    @Test
    void aBranchOnTheWorldKindIsFound() {
        String source = "class Pick {\n"
                + "  /** Not in a comment: layout.streamed() */\n"
                + "  Layout a = Layout.of(layout.streamed());\n"
                + "  boolean b = s.world() == TerrainSettings.World.UNBOUNDED;\n"
                + "  boolean c = ground instanceof TileGround;\n"
                + "  Ground d = switch (s.world()) { case TILE -> tile(); case UNBOUNDED -> streamed(); };\n"
                + "}\n";
        List<String> found = worldBranches("Pick.java", source);
        assertEquals(3, found.size(), "the three branches, not the comment nor the switch: " + found);
    }
}
