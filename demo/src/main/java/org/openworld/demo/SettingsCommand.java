package org.openworld.demo;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/** {@code openworld settings}: every {@code --set} key with its default, unit, valid values and meaning. */
@Command(name = "settings", mixinStandardHelpOptions = true, description = "List every --set key with its default, unit, valid values and meaning.")
final class SettingsCommand implements Callable<Integer> {

    @Mixin
    RenderOptions render;

    @Override
    public Integer call() {
        var settings = Launch.settings(render);
        System.out.print(settings.describe());
        if (render.preset != null) {
            System.out.println();
            System.out.println("With the preset " + render.preset + " (" + Presets.resource(render.preset) + "):");
            Presets.values(render.preset, settings).forEach((key, value) -> System.out.println("  " + key + " = "
                    + value));
        }
        if (!render.set.isEmpty()) {
            System.out.println();
            System.out.println("With your --set values:");
            render.set.forEach(a -> {
                String key = a.substring(0, a.indexOf('=')).trim();
                System.out.println("  " + key + " = " + settings.text(key));
            });
        }
        return 0;
    }
}
