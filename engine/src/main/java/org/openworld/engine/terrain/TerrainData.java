package org.openworld.engine.terrain;

import java.nio.file.Path;
import org.openworld.engine.erosion.TileErosion;

/**
 * What the terrain is made of before anything reaches the GPU: the height pyramid (paper 2.1 and 2.5), the snow
 * map (paper 2.2) and how much sky each place sees. Pure CPU work with no OpenGL, so it can run on a worker thread or in a command-line tool.
 *
 * @param pyramid the heights at every power-of-two resolution, level 0 the full map
 * @param snow    where snow lies
 * @param sky     the share of the sky the relief leaves each place, for the light in the shadows
 */
public record TerrainData(HeightPyramid pyramid, SnowMap snow, SkyVisibility sky) {

    /** Stage names as {@link StageTimes} records them. */
    public static final String SYNTHESIS = "synthesis";
    public static final String IMPORT = "import";
    public static final String PYRAMID = "pyramid";
    public static final String SNOW_MAP = "snow map";
    public static final String SKY_VISIBILITY = "sky view";
    public static final String EROSION = "erosion";

    /**
     * Makes the heights (synthesised from the seed, or imported when {@link TerrainSettings#importFile()} is set),
     * their pyramid, the snow map and the sky's visibility, timing each stage into {@code times}.
     *
     * @throws HeightImportException if the import file cannot be used
     */
    public static TerrainData create(TerrainSettings s, int seed, StageTimes times) {
        HeightMap made = s.imports()
                ? times.time(IMPORT, () -> HeightImport.read(Path.of(s.importFile()), s))
                : times.time(SYNTHESIS, () -> SpectralSynthesis.generate(s, seed));
        HeightMap base = s.erosion() ? times.time(EROSION, () -> TileErosion.erode(made, s.erosionTalus())) : made;
        HeightPyramid pyramid = times.time(PYRAMID, () -> HeightPyramid.build(base));
        SnowMap snow = times.time(SNOW_MAP, () -> SnowMap.generate(pyramid, s, seed));
        SkyVisibility sky = times.time(SKY_VISIBILITY, () -> SkyVisibility.of(pyramid));
        return new TerrainData(pyramid, snow, sky);
    }
}
