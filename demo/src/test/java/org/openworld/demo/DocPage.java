package org.openworld.demo;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * One page as the docs tests read it: its lines and where its fenced code blocks are. The pages are
 * {@code README.md}, {@code CONTRIBUTING.md} and every {@code docs/*.md} ({@link #all()}).
 *
 * @param name  the page's path relative to the repository root, as failures name it
 * @param lines the page's lines
 */
record DocPage(String name, List<String> lines) {

    /** The repository root, seen from the demo module's folder, where the tests run. */
    static final Path ROOT = Path.of("..");

    /** Every page, the README and CONTRIBUTING.md first, then {@code docs/} in name order. */
    static List<DocPage> all() {
        List<DocPage> pages = new ArrayList<>();
        pages.add(read("README.md"));
        pages.add(read("CONTRIBUTING.md"));
        try (Stream<Path> docs = Files.list(ROOT.resolve("docs"))) {
            docs.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".md")).sorted()
                    .forEach(n -> pages.add(read("docs/" + n)));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return pages;
    }

    static DocPage read(String name) {
        try {
            return new DocPage(name, Files.readAllLines(ROOT.resolve(name)));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The page's folder, relative links resolve against it. */
    Path folder() {
        Path parent = Path.of(name).getParent();
        return parent == null ? ROOT : ROOT.resolve(parent);
    }

    /** For each line, whether it is inside a fenced code block (the fence lines themselves count as inside). */
    boolean[] fenced() {
        boolean[] inside = new boolean[lines.size()];
        String fence = null;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (fence == null && line.startsWith("```")) {
                fence = line.substring(0, line.length() - line.replaceFirst("^`+", "").length());
                inside[i] = true;
            } else if (fence != null) {
                inside[i] = true;
                if (line.equals(fence)) {
                    fence = null;
                }
            }
        }
        return inside;
    }

    /** Where a failure points: the page and the line, counted from 1. */
    String at(int index) {
        return name + ":" + (index + 1);
    }
}
