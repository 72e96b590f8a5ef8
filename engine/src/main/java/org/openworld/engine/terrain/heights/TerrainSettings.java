package org.openworld.engine.terrain.heights;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the terrain's height map and snow map, keys {@code terrain.*}: how the heights are made (spectral
 * synthesis, paper 2.1, or an imported file), how they are scaled, and where snow lies (paper 2.2).
 *
 * @param size           samples per side of a generated map (an imported map brings its own size)
 * @param spacing        distance between neighbouring samples; the tile is {@code size · spacing} metres across
 * @param relief         height from the lowest to the highest sample after normalisation
 * @param seaFraction    fraction of the relief below sea level (height 0), so the lowest valleys hold water
 * @param beta           spectral exponent: the amplitude of frequency ω is proportional to 1/ω^β. β = 1 is the
 *                       paper's 1/ω, spiky; the default 2.2 gives massifs and valleys (why: {@link SpectralSynthesis})
 * @param minWavelength  high-frequency cut-off: shorter wavelengths get amplitude 0
 * @param maxWavelength  low-frequency cut-off: longer wavelengths get amplitude 0, so one frequency ring does not
 *                       dominate and the tile holds several mountains instead of one
 * @param importFile     16-bit grayscale PNG or little-endian float32 {@code .raw/.r32/.f32} height map used instead
 *                       of synthesis (see {@link HeightImport}), or a real elevation model (a GeoTIFF, or a PNG or
 *                       raw file with a sidecar: {@link org.openworld.engine.elevation.ElevationImport}); empty
 *                       generates one. The spectral settings are then ignored
 * @param snowBase       normalised height (0 lowest, 1 highest sample; for a map imported at true scale 0 m and
 *                       {@link org.openworld.engine.elevation.ElevationImport#TRUE_SCALE_RELIEF} 5000 m) where the
 *                       snow probability starts to rise from 0
 * @param snowFull       normalised height at which snow is certain; p(h) = clamp((h − base)/(full − base), 0, 1)
 * @param snowMorphology radius of the opening and the closing that clean up the random snow map, in snow map pixels
 * @param world          {@link World#UNBOUNDED} (the default): the heights made per level ({@link BandedHeights}) and
 *                       streamed around the camera, never repeating; {@link World#TILE}: one map, repeated if generated
 *                       (the paper's). An imported map is always the tile: with {@code importFile} set the record
 *                       holds {@code TILE} whatever it was given, so a saved or default {@code unbounded} never
 *                       refuses an import (the demo's command line refuses the two named together)
 * @param memoryBudget   the unbounded world's GPU memory for streamed heights, slopes and snow, MiB: it sets how many
 *                       samples each level keeps around the camera ({@link org.openworld.engine.terrain.stream.HeightClipmap})
 * @param importScale    keep an imported map's heights and spacing in metres, as its file gives them (a GeoTIFF's
 *                       tags, or a sidecar beside a PNG or raw file; {@link org.openworld.engine.elevation}); false,
 *                       or a file that gives no scale, normalises it to {@code relief} and {@code seaFraction}
 * @param seaLevel       the file's height that becomes sea level (height 0, where the water lies) in a map imported
 *                       at true scale
 * @param importDetail   true-scale import: synthesise the detail below the data's resolution, the octaves the map
 *                       is too coarse to hold, down to {@code spacing} or to a tile of {@code size} samples, whichever
 *                       is coarser
 * @param erosion        the heights of either world carved by rivers (stream power with uplift) and settled to the
 *                       talus ({@link org.openworld.engine.erosion}); off keeps the plain spectral heights
 * @param erosionTalus   the steepest a hillslope stands after erosion, degrees (the angle of repose)
 * @param ranges         the unbounded world's large-scale structure: ranges and plains tens of kilometres across
 *                       ({@link org.openworld.engine.tectonics}); off keeps the bands' even relief
 */
public record TerrainSettings(
        @Setting(doc = "samples per side of the height map, a power of two", min = 256, max = 8192, atStart = true)
        int size,
        @Setting(doc = "distance between neighbouring height samples", unit = "m", min = 0.1, max = 100, atStart = true)
        double spacing,
        @Setting(doc = "height range from lowest valley to highest peak",
                unit = "m", min = 10, max = 10000, atStart = true)
        double relief,
        @Setting(doc = "fraction of the relief below sea level (height 0)", min = 0, max = 0.9, atStart = true)
        double seaFraction,
        @Setting(doc = "spectral exponent: amplitude ~ 1/frequency^beta", min = 1, max = 3, atStart = true) double beta,
        @Setting(doc = "shortest wavelength kept (high-frequency cut-off)",
                unit = "m", min = 0.1, max = 1e6, atStart = true)
        double minWavelength,
        @Setting(doc = "longest wavelength kept (low-frequency cut-off)",
                unit = "m", min = 0.1, max = 1e6, atStart = true)
        double maxWavelength,
        @Setting(doc = "height map to load instead of generating one: GeoTIFF, or 16-bit PNG or float32 .raw",
                atStart = true, file = true)
        String importFile,
        @Setting(doc = "normalised height where snow starts (probability 0)", min = 0, max = 1, atStart = true)
        double snowBase,
        @Setting(doc = "normalised height where snow is certain (probability 1)", min = 0, max = 1, atStart = true)
        double snowFull,
        @Setting(doc = "radius of the snow map's opening and closing", unit = "px", min = 0, max = 8, atStart = true)
        int snowMorphology,
        @Setting(doc = "UNBOUNDED: made per level around the camera, never repeating; TILE: one map, repeated if "
                + "generated; an imported map is always the tile", atStart = true) World world,
        @Setting(doc = "unbounded world: GPU memory for the streamed heights, slopes and snow", unit = "MiB", min = 2,
                max = 4096, atStart = true) int memoryBudget,
        @Setting(doc = "keep an imported map's metres and spacing as its file gives them (GeoTIFF tags or a sidecar)",
                atStart = true) boolean importScale,
        @Setting(doc = "true-scale import: the file's height that becomes sea level", unit = "m", min = -12000,
                max = 9000, atStart = true) double seaLevel,
        @Setting(doc = "true-scale import: synthesise the detail below the data's resolution", atStart = true)
        boolean importDetail,
        @Setting(doc = "heights carved by rivers (stream power with uplift) and thermal erosion, on both worlds",
                atStart = true)
        boolean erosion,
        @Setting(doc = "steepest hillslope after erosion (angle of repose)", unit = "deg", min = 20, max = 60,
                atStart = true) double erosionTalus,
        @Setting(doc = "unbounded world: mountain ranges and plains tens of kilometres across", atStart = true)
        boolean ranges) {

    /** Where the heights come from and how far they reach. */
    public enum World {
        /** One map of {@code terrain.size}² samples (generated and repeated, or imported), made whole at start. */
        TILE,
        /** {@link BandedHeights}: every level made where the camera needs it, no map anywhere, never repeating. */
        UNBOUNDED
    }

    public static final TerrainSettings DEFAULTS = new TerrainSettings(
            2048,   // samples: 4 km at 2 m, fine enough to walk on, generated in about a second
            2,      // m: a sample every two steps of a walker
            800,    // m: alpine foothills, sea to summit
            0.15,   // the lowest 15 % of the relief: valley floors hold lakes, most land stays dry
            2.2,    // amplitude ~ 1/ω^2.2: massifs and valleys, not crumpled paper (see SpectralSynthesis)
            4,      // m: two samples at 2 m spacing, the shortest wavelength the grid can hold
            2048,   // m: half of the default 4 km tile, so a tile holds a few ranges, not one hump
            "",     // generate
            0.35,   // snow may start at a third of the relief (seed 1's median ground is at 0.35)...
            0.60,   // ...and is certain on the top 40 %: snow on the upper slopes, as in the paper's figure 1b
            1,      // px: a 3×3 square keeps the paper's ragged, probabilistic fringe below the snow fields
            World.UNBOUNDED, // the open world the engine is named for; the paper's figures ask for the tile
            20,     // MiB: 512² heights, slopes and snow on each of 8 levels: 1 km across at 2 m, 130 km at the 8th
            true,   // a real place's metres are the point of importing it
            0,      // m: elevation models count from mean sea level
            true,   // a 30-90 m model is soft mush at walking height without the octaves it cannot hold
            false,  // the paper's plain spectral heights, as every picture and test of the tile was made
            38,     // deg: scree's angle of repose, 34-40° (a rock wall stands steeper than any 8 m cell shows)
            false); // the bands' even relief, as every picture and test of the unbounded world was made

    public static final SettingsGroup<TerrainSettings> SETTINGS =
            SettingsGroup.of("terrain", TerrainSettings.class, DEFAULTS);

    /**
     * Checks what single ranges cannot: the size is a power of two, the cut-offs are ordered and overlap the
     * wavelengths the grid can hold, and the snow heights are ordered. An imported map makes the world the tile:
     * the one place that rule lives, so every reader of {@link #world()} sees the world that is drawn.
     */
    public TerrainSettings {
        if (Integer.bitCount(size) != 1) {
            throw new IllegalArgumentException("the height map size must be a power of two (256, 512, ... 8192), got "
                    + size);
        }
        if (!(minWavelength < maxWavelength)) {
            throw new IllegalArgumentException("the shortest wavelength (" + minWavelength
                    + " m) must be less than the longest (" + maxWavelength + " m)");
        }
        if (maxWavelength <= 2 * spacing || minWavelength >= size * spacing) {
            throw new IllegalArgumentException("the wavelengths kept (" + minWavelength + " .. " + maxWavelength
                    + " m) must overlap what the grid holds: two samples (" + 2 * spacing + " m) up to the tile ("
                    + size * spacing + " m)");
        }
        if (!(snowBase < snowFull)) {
            throw new IllegalArgumentException("snow must start (" + snowBase
                    + ") below the height where it is certain (" + snowFull + ")");
        }
        if (world == null) {
            throw new IllegalArgumentException("the world must be TILE or UNBOUNDED, not null");
        }
        if (importFile == null) {
            throw new IllegalArgumentException("the import file must be a path or empty, not null");
        }
        if (!importFile.isBlank()) {
            // One map of the file's size, made whole at start: it cannot be streamed per level.
            world = World.TILE;
        }
    }

    /** Side of a generated tile, metres. */
    public double extent() {
        return size * spacing;
    }

    /** Whether the heights come from {@link #importFile()} rather than synthesis. */
    public boolean imports() {
        return !importFile.isBlank();
    }
}
