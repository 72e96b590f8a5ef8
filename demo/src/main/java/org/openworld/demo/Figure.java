package org.openworld.demo;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * One picture of the paper's figures as the demo remakes it: which figure it belongs to, what the paper says of it,
 * what to look for, and the command that makes it. {@link FigureCatalogue} lists them all; {@code openworld figures}
 * runs their commands and shows them in a gallery.
 *
 * @param id        the picture's name in the gallery and its file name, e.g. {@code 9c} (the paper's letter where it
 *                  has one, else the figure's variants lettered in the paper's order)
 * @param number    the paper's figure number
 * @param caption   the paper's own words for it: the figure's caption, or the sentence of the text that shows it
 * @param note      one line of what to look for in this picture
 * @param tool      which command makes it
 * @param arguments the command's arguments that fix the picture (seed, time, pose, settings); the output and the
 *                  render size are added by {@link #commandLine}
 */
record Figure(String id, int number, String caption, String note, Tool tool, List<String> arguments) {

    /** The command that makes a picture. */
    enum Tool {
        /** {@code openworld shot}: one rendered image, {@code ID.png}. */
        SHOT("shot"),
        /** {@code openworld heightmap}: the height, snow and spectrum maps, no OpenGL, in the folder {@code ID}. */
        HEIGHTMAP("heightmap"),
        /** {@code openworld sky-strip}: the sky on the CPU at several samplings with their ΔE, {@code ID.png}. */
        STRIP("sky-strip"),
        /** {@code openworld diagram}: figure 7, drawn, {@code ID.png}. */
        DIAGRAM("diagram"),
        /**
         * {@code openworld diff}: where two earlier pictures of the gallery differ (ΔE00), {@code ID.png}; its
         * arguments are their files, relative to the gallery's folder.
         */
        DIFF("diff");

        final String command;

        Tool(String command) {
            this.command = command;
        }
    }

    Figure {
        arguments = List.copyOf(arguments);
    }

    /**
     * The same picture under another id (its files' names) with more arguments after its own, e.g. a preset's:
     * {@code --preset paper} for a shot.
     */
    Figure with(String otherId, List<String> moreArguments) {
        List<String> all = new ArrayList<>(arguments);
        all.addAll(moreArguments);
        return new Figure(otherId, number, caption, note, tool, all);
    }

    /** This picture with its arguments' files, which a difference reads, resolved against {@code folder}. */
    Figure readingFrom(Path folder) {
        return tool == Tool.DIFF
                ? new Figure(id, number, caption, note, tool,
                        arguments.stream().map(a -> folder.resolve(a).toString()).toList())
                : this;
    }

    /** Where the command writes, relative to the gallery's folder: a folder for the maps, else a PNG file. */
    String output() {
        return tool == Tool.HEIGHTMAP ? id : id + ".png";
    }

    /** The images the command writes, relative to the gallery's folder, in the order the gallery shows them. */
    List<String> files() {
        return tool == Tool.HEIGHTMAP
                ? List.of(id + "/" + HeightmapCommand.HEIGHT_PNG, id + "/" + HeightmapCommand.SNOW_PNG,
                        id + "/" + HeightmapCommand.SPECTRUM_PNG)
                : List.of(output());
    }

    /**
     * The whole command line after {@code openworld}: the tool, {@code --out out}, the render size (a shot's only),
     * this picture's arguments, then each override as {@code --set}, last so that it wins.
     */
    List<String> commandLine(String out, Size size, List<String> overrides) {
        List<String> line = new ArrayList<>(List.of(tool.command, "--out", out));
        if (tool == Tool.SHOT) {
            line.add("--size");
            line.add(size.width() + "x" + size.height());
        }
        line.addAll(arguments);
        for (String override : overrides) {
            line.add("--set");
            line.add(override);
        }
        return line;
    }
}
