package org.openworld.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;
import org.openworld.engine.files.AtomicFiles;

/**
 * The {@code index.html} of {@code openworld figures}: one static page, grouped by the paper's figure, that shows each
 * picture with its id, the paper's words, what to look for and the exact command that made it; a header says how
 * the set was made. Plain HTML and a little CSS, no scripts, so it opens from the folder anywhere.
 */
final class Gallery {

    static final String INDEX = "index.html";

    /** Words a POSIX shell reads as they are; anything else is single-quoted. */
    private static final Pattern PLAIN_WORD = Pattern.compile("[A-Za-z0-9_@%+=:,./-]+");

    /**
     * How the set was made, for the header.
     *
     * @param invocation the {@code openworld figures} command line
     * @param renderer   the OpenGL renderer and context mode, or why there is none
     * @param date       when it was made
     * @param seconds    the whole run's wall time
     */
    record Made(String invocation, String renderer, String date, Size size, int seed, List<String> overrides,
            String preset, double seconds) {
    }

    /**
     * One entry of the gallery: a catalogue entry and its pictures, the default one first and, in a run with a
     * preset, the preset's beside it (a picture that takes no settings is made once).
     */
    record Plate(Figure figure, List<Picture> pictures) {

        Plate {
            pictures = List.copyOf(pictures);
        }
    }

    /**
     * One picture made: the figure as it was made (its id names the files, with the preset's name added for the
     * preset's picture), the command that made it as a shell line, what it measured (a strip's ΔE; empty for a
     * picture that measures nothing) and its wall time.
     */
    record Picture(Figure made, String command, String measured, double seconds) {
    }

    private Gallery() {
    }

    /** Writes {@code index.html} into {@code dir}, which holds the plates' images, whole or not at all. */
    static Path write(Path dir, Made made, List<Plate> plates) throws IOException {
        Path index = dir.resolve(INDEX);
        String page = html(made, plates);
        AtomicFiles.write(index, temp -> Files.writeString(temp, page));
        return index;
    }

    static String html(Made made, List<Plate> plates) {
        Map<Integer, List<Plate>> byFigure = new LinkedHashMap<>();
        plates.forEach(p -> byFigure.computeIfAbsent(p.figure().number(), n -> new ArrayList<>()).add(p));

        StringBuilder html = new StringBuilder();
        html.append("""
                <!DOCTYPE html>
                <html lang="en">
                <head>
                <meta charset="utf-8">
                <title>OpenWorld: the paper's figures</title>
                <style>
                body { font-family: sans-serif; margin: 1.5rem; max-width: 110rem; color: #222; }
                header p, nav { max-width: 60rem; }
                nav a { margin-right: .6rem; }
                section { margin-top: 2rem; border-top: 1px solid #ccc; }
                .plates { display: grid; grid-template-columns: repeat(auto-fill, minmax(26rem, 1fr)); gap: 1.2rem; }
                .beside .plates { grid-template-columns: repeat(auto-fill, minmax(44rem, 1fr)); }
                .pictures { display: grid; grid-template-columns: repeat(auto-fit, minmax(20rem, 1fr)); gap: .6rem; }
                .label { font-weight: bold; margin: .2rem 0; }
                figure { margin: 0; }
                figure img { width: 100%; height: auto; border: 1px solid #ddd; display: block; }
                .id { font-weight: bold; margin-right: .4rem; }
                .measured { margin: .3rem 0; font-weight: bold; }
                blockquote { margin: .3rem 0; font-style: italic; color: #444; }
                .note { margin: .3rem 0; }
                code { display: block; background: #f4f4f4; padding: .4rem; font-size: .85em; white-space: pre-wrap;
                       word-break: break-all; user-select: all; }
                .time, .file { color: #777; font-size: .85em; }
                </style>
                </head>
                """);
        html.append(made.preset().isEmpty() ? "<body>\n" : "<body class=\"beside\">\n")
                .append("<header>\n<h1>OpenWorld: the paper's figures, remade</h1>\n");
        html.append("<p>Made by <code>").append(escape(made.invocation())).append("</code></p>\n");
        html.append(String.format(Locale.ROOT, "<p>Made %s with %s: %d pictures of %s pixels, world seed %d%s, in "
                        + "%.0f s.</p>%n", escape(made.date()), escape(made.renderer()),
                plates.stream().mapToInt(p -> p.pictures().size()).sum(),
                made.size().width() + "×" + made.size().height(), made.seed(),
                made.overrides().isEmpty() ? ""
                        : ", with " + escape(String.join(" ", made.overrides())) + " added to every command",
                made.seconds()));
        if (!made.preset().isEmpty()) {
            html.append("<p>Each picture is shown with the defaults and, beside it, with <b>--preset ")
                    .append(escape(made.preset())).append("</b> (assets/presets/").append(escape(made.preset()))
                    .append(".settings); a picture's own settings win over the preset. Figure 7's diagram and "
                            + "strips take no settings and are made once.</p>\n");
        }
        html.append("<p>Each command writes into the current folder: run it in this folder to remake its picture. "
                + "The quotes are the paper's caption of each figure, or its sentence that shows it.</p>\n"
                + "</header>\n<nav>");
        byFigure.keySet().forEach(n -> html.append("<a href=\"#figure-").append(n).append("\">Figure ").append(n)
                .append("</a>"));
        html.append("</nav>\n");

        byFigure.forEach((number, group) -> {
            html.append("<section id=\"figure-").append(number).append("\">\n<h2>Figure ").append(number)
                    .append("</h2>\n<div class=\"plates\">\n");
            group.forEach(plate -> plate(html, plate, made.preset()));
            html.append("</div>\n</section>\n");
        });
        html.append("</body>\n</html>\n");
        return html.toString();
    }

    private static void plate(StringBuilder html, Plate plate, String preset) {
        Figure figure = plate.figure();
        html.append("<figure id=\"").append(escape(figure.id())).append("\">\n<div class=\"pictures\">\n");
        for (int i = 0; i < plate.pictures().size(); i++) {
            Picture picture = plate.pictures().get(i);
            html.append("<div>\n");
            if (plate.pictures().size() > 1) {
                html.append("<p class=\"label\">").append(i == 0 ? "default" : "--preset " + escape(preset))
                        .append("</p>\n");
            }
            picture(html, picture);
            html.append("</div>\n");
        }
        html.append("</div>\n<figcaption><span class=\"id\">").append(escape(figure.id())).append("</span>")
                .append("<blockquote>").append(escape(figure.caption())).append("</blockquote>\n")
                .append("<p class=\"note\">").append(escape(figure.note())).append("</p>\n")
                .append("</figcaption>\n</figure>\n");
    }

    /** One picture's images, what it measured, its command and time. */
    private static void picture(StringBuilder html, Picture picture) {
        List<String> files = picture.made().files();
        for (String file : files) {
            String link = escape(file);
            html.append("<a href=\"").append(link).append("\"><img src=\"").append(link).append("\" alt=\"Figure ")
                    .append(picture.made().number()).append(", ").append(link).append("\" loading=\"lazy\"></a>\n");
            if (files.size() > 1) {
                html.append("<div class=\"file\">").append(link).append("</div>\n");
            }
        }
        html.append(picture.measured().isEmpty() ? ""
                        : "<p class=\"measured\">Measured: " + escape(picture.measured()) + "</p>\n")
                .append("<code>").append(escape(picture.command())).append("</code>\n")
                .append(String.format(Locale.ROOT, "<span class=\"time\">%.1f s</span>\n", picture.seconds()));
    }

    /** Text safe inside an HTML element or a double- or single-quoted attribute. */
    static String escape(String text) {
        StringBuilder out = new StringBuilder(text.length());
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '&' -> out.append("&amp;");
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '"' -> out.append("&quot;");
                case '\'' -> out.append("&#39;");
                default -> out.append(c);
            }
        }
        return out.toString();
    }

    /** Words joined into one line a POSIX shell splits back into the same words. */
    static String shellLine(List<String> words) {
        StringBuilder line = new StringBuilder();
        for (String word : words) {
            if (!line.isEmpty()) {
                line.append(' ');
            }
            line.append(PLAIN_WORD.matcher(word).matches() ? word : "'" + word.replace("'", "'\\''") + "'");
        }
        return line.toString();
    }
}
