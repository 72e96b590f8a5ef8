package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.WildcardType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.minimap.MinimapSystem;

/**
 * Systems share only through the world: a system's package imports another system's package only for a type it
 * declares as shared data, so that a new system can be written against the world's resources and never against
 * another system's settings or internals.
 *
 * <p><b>System packages</b> are found, not listed: every package directly under {@code org.openworld.engine} (with
 * its sub-packages) whose main sources hold a concrete class implementing {@link EngineSystem}. A new system's
 * package is checked without editing this test.
 *
 * <p><b>The rule.</b> In every main source file of a system package P, each line
 * {@code import [static] org.openworld.engine.Q.…;} where Q is another system package must name a type T (for a
 * static import, the type whose member it imports) such that, for some system of P,
 * <ol>
 *   <li>T is declared in its {@code SystemSpec}'s {@code reads(...)} or {@code writes(...)}, or</li>
 *   <li>T is exposed, one step, by such a declared type D's public API: a public member type of D, or a type in the
 *       signature of one of D's public constructors, methods or fields (generic arguments and array elements
 *       included), as {@code camera.CameraPose} is returned by the declared {@code Camera.pose()}.</li>
 * </ol>
 * A wildcard import of another system's package ({@code Q.*}) is refused: it hides what is used. Only import lines
 * are read; a type written out in full in code, or named in a Javadoc link, is not checked. Neutral packages (core,
 * environment, gl, settings, …) are not system packages: anyone may import them, and shared vocabulary that more
 * than one system writes belongs there.
 *
 * <p><b>The declarations</b> come from the systems themselves: each is made with its no-argument constructor and
 * asked for its {@code spec()} (a system allocates nothing before {@code init}), so what is checked is exactly
 * what the engine orders by.
 */
class SystemImportsTest {

    /** The engine's main sources, seen from the engine module's folder, where the tests run. */
    static final Path SOURCES = Path.of("src/main/java/org/openworld/engine");
    static final String ENGINE = "org.openworld.engine";
    static final Pattern IMPORT = Pattern.compile("^import\\s+(static\\s+)?" + Pattern.quote(ENGINE)
            + "\\.([\\w.]+?)(\\.\\*)?\\s*;");
    static final Pattern PACKAGE_NAME = Pattern.compile("[a-z][a-z0-9_]*");

    /** The systems of each system package, by package (its first name under the engine's). */
    static Map<String, List<EngineSystem>> systemsByPackage() throws IOException {
        Map<String, List<EngineSystem>> systems = new TreeMap<>();
        for (Path file : sources()) {
            String pkg = systemPackageOf(file);
            if (pkg == null) {
                continue;
            }
            Class<?> type = classOf(file);
            if (type == null || !EngineSystem.class.isAssignableFrom(type) || type.isInterface()
                    || Modifier.isAbstract(type.getModifiers())) {
                continue;
            }
            systems.computeIfAbsent(pkg, k -> new ArrayList<>()).add(instantiate(type));
        }
        return systems;
    }

    static List<Path> sources() throws IOException {
        try (Stream<Path> files = Files.walk(SOURCES)) {
            return files.filter(f -> f.toString().endsWith(".java")).sorted().toList();
        }
    }

    /** The first package name under the engine's, or null for a file of the engine's own package. */
    static String systemPackageOf(Path file) {
        Path relative = SOURCES.relativize(file);
        return relative.getNameCount() > 1 ? relative.getName(0).toString() : null;
    }

    /** The top-level class a source file declares, loaded without running its static initialisers; null if none. */
    static Class<?> classOf(Path file) {
        String relative = SOURCES.relativize(file).toString().replace(file.getFileSystem().getSeparator(), ".");
        String name = ENGINE + "." + relative.substring(0, relative.length() - ".java".length());
        if (name.endsWith("package-info")) {
            return null;
        }
        try {
            return Class.forName(name, false, SystemImportsTest.class.getClassLoader());
        } catch (ClassNotFoundException e) {
            throw new AssertionError(file + " declares no class " + name, e);
        }
    }

    static EngineSystem instantiate(Class<?> type) {
        try {
            return (EngineSystem) type.getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(type.getName() + " cannot be made with a no-argument constructor, which this "
                    + "test uses to read its spec(): " + e, e);
        }
    }

    /** What the systems declare in reads(...) and writes(...). */
    static Set<Class<?>> declared(List<EngineSystem> systems) {
        Set<Class<?>> declared = new LinkedHashSet<>();
        for (EngineSystem system : systems) {
            declared.addAll(system.spec().reads());
            declared.addAll(system.spec().writes());
            declared.addAll(system.spec().published());
        }
        return declared;
    }

    static Set<Class<?>> exposedBy(Class<?> type) {
        Set<Class<?>> exposed = new LinkedHashSet<>(List.of(type));
        exposed.addAll(List.of(type.getClasses()));
        for (Method m : type.getMethods()) {
            collect(m.getGenericReturnType(), exposed);
            Stream.of(m.getGenericParameterTypes()).forEach(p -> collect(p, exposed));
        }
        for (Constructor<?> c : type.getConstructors()) {
            Stream.of(c.getGenericParameterTypes()).forEach(p -> collect(p, exposed));
        }
        for (Field f : type.getFields()) {
            collect(f.getGenericType(), exposed);
        }
        return exposed;
    }

    private static void collect(Type type, Set<Class<?>> into) {
        if (type instanceof Class<?> c) {
            into.add(c.isArray() ? elementOf(c) : c);
        } else if (type instanceof ParameterizedType p) {
            collect(p.getRawType(), into);
            Stream.of(p.getActualTypeArguments()).forEach(a -> collect(a, into));
        } else if (type instanceof GenericArrayType a) {
            collect(a.getGenericComponentType(), into);
        } else if (type instanceof WildcardType w) {
            Stream.of(w.getUpperBounds()).forEach(b -> collect(b, into));
            Stream.of(w.getLowerBounds()).forEach(b -> collect(b, into));
        }
    }

    private static Class<?> elementOf(Class<?> array) {
        Class<?> c = array;
        while (c.isArray()) {
            c = c.getComponentType();
        }
        return c;
    }

    /**
     * The import lines of one file of system package {@code pkg} that break the rule, each as a message naming the
     * file, the import and why.
     *
     * @param declared what the package's systems declare they read or write ({@link #declared})
     */
    static List<String> violations(String pkg, String file, List<String> lines, Set<String> systemPackages,
                                   Set<Class<?>> declared) {
        Set<Class<?>> allowed = new LinkedHashSet<>();
        declared.forEach(type -> allowed.addAll(exposedBy(type)));
        List<String> found = new ArrayList<>();
        for (String line : lines) {
            Matcher m = IMPORT.matcher(line.strip());
            if (!m.find()) {
                continue;
            }
            boolean isStatic = m.group(1) != null;
            boolean wildcard = m.group(3) != null;
            List<String> names = List.of(m.group(2).split("\\."));
            String other = names.get(0);
            if (!systemPackages.contains(other) || other.equals(pkg)) {
                continue;
            }
            String imported = ENGINE + "." + m.group(2) + (wildcard ? ".*" : "");
            // the package part, then the type and its nesting; a static import names a member after the type
            int first = 0;
            while (first < names.size() && PACKAGE_NAME.matcher(names.get(first)).matches()) {
                first++;
            }
            List<String> typeNames = names.subList(first, isStatic && !wildcard ? names.size() - 1 : names.size());
            if (typeNames.isEmpty()) {
                found.add(file + ": import " + imported + " takes all of system package '" + other
                        + "': name the shared types it declares to read or write");
                continue;
            }
            String binary = ENGINE + "." + String.join(".", names.subList(0, first)) + "."
                    + String.join("$", typeNames);
            Class<?> type;
            try {
                type = Class.forName(binary, false, SystemImportsTest.class.getClassLoader());
            } catch (ClassNotFoundException e) {
                throw new AssertionError(file + ": import " + imported + " names no class " + binary, e);
            }
            if (!allowed.contains(type)) {
                found.add(file + ": import " + imported + " reaches into system package '" + other + "': "
                        + type.getSimpleName() + " is neither declared in reads(...)/writes(...) by a system of '"
                        + pkg + "' nor exposed by a type so declared (declared: " + names(declared) + "); share it "
                        + "through the world as a declared resource, or move it to a neutral package (core, "
                        + "environment)");
            }
        }
        return found;
    }

    private static String names(Set<Class<?>> types) {
        return types.stream().map(Class::getSimpleName).sorted().collect(Collectors.joining(", "));
    }

    @Test
    void aSystemImportsAnotherSystemsPackageOnlyForTheResourcesItDeclares() throws IOException {
        Map<String, List<EngineSystem>> systems = systemsByPackage();
        assertTrue(systems.keySet().containsAll(List.of("camera", "culling", "minimap", "particles", "shadow", "sky",
                "terrain", "water")), "the system packages were found: " + systems.keySet());
        Map<String, Set<Class<?>>> declared = new TreeMap<>();
        systems.forEach((pkg, list) -> declared.put(pkg, declared(list)));
        List<String> found = new ArrayList<>();
        int checked = 0;
        for (Path file : sources()) {
            String pkg = systemPackageOf(file);
            if (pkg != null && systems.containsKey(pkg)) {
                found.addAll(violations(pkg, SOURCES.relativize(file).toString(), Files.readAllLines(file),
                        systems.keySet(), declared.get(pkg)));
                checked++;
            }
        }
        assertTrue(checked > 50, "the system packages' sources were read: " + checked + " files");
        assertTrue(found.isEmpty(), String.join("\n", found));
    }

    @Test
    void theRuleRefusesWhatIsNotDeclaredAndAcceptsWhatADeclaredTypeExposes() {
        Set<String> packages = Set.of("camera", "minimap", "water");
        Set<Class<?>> minimap = declared(List.of(new MinimapSystem()));
        List<String> found = violations("minimap", "minimap/Example.java", List.of(
                "import org.openworld.engine.camera.Camera;",            // declared: reads(Camera.class)
                "import org.openworld.engine.camera.CameraPose;",        // exposed: Camera.pose() returns it
                "import org.openworld.engine.minimap.ReliefMap;",        // its own package
                "import org.openworld.engine.core.World;",               // a neutral package
                "import org.openworld.engine.water.WaterSettings;",      // another system's settings
                "import static org.openworld.engine.water.WaterSettings.DEFAULTS;",
                "import org.openworld.engine.water.*;"), packages, minimap);
        assertEquals(3, found.size(), String.join("\n", found));
        assertTrue(found.get(0).startsWith("minimap/Example.java: import org.openworld.engine.water.WaterSettings "
                + "reaches into system package 'water': WaterSettings is neither declared"), found.get(0));
        assertTrue(found.get(1).contains("import org.openworld.engine.water.WaterSettings.DEFAULTS reaches into"),
                found.get(1));
        assertTrue(found.get(2).contains("takes all of system package 'water'"), found.get(2));
    }
}
