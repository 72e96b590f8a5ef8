package org.openworld.engine.terrain;

import java.nio.file.Path;
import org.openworld.engine.elevation.ElevationImport;
import org.openworld.engine.erosion.TileErosion;
import org.openworld.engine.erosion.hydraulic.HydraulicErosion;
import org.openworld.engine.erosion.hydraulic.PipeErosion;
import org.openworld.engine.erosion.hydraulic.PipeState;
import org.openworld.engine.terrain.heights.HeightImport;
import org.openworld.engine.terrain.heights.HeightImportException;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.HeightSource;
import org.openworld.engine.terrain.heights.SpectralSynthesis;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.material.SnowMap;

/**
 * What the terrain is made of before anything reaches the GPU: the height pyramid (paper 2.1 and 2.5), the snow
 * map (paper 2.2). Pure CPU work with no OpenGL, so it can run on a worker thread or in a command-line tool.
 *
 * @param pyramid the heights at every power-of-two resolution, level 0 the full map
 * @param snow    where snow lies
 * @param lowest  the height, metres, that the materials and the snow read as normalised 0: the map's lowest sample,
 *                or the file's 0 m for a map at true scale
 * @param highest the height read as normalised 1: the map's highest sample, or
 *                {@link ElevationImport#TRUE_SCALE_RELIEF} above the file's 0 m
 * @param sediment what the hydraulic erosion changed, metres (sediment laid +, bed carried off −), on the grid it
 *                 ran on; null where it did not run
 */
public record TerrainData(HeightPyramid pyramid, SnowMap snow, double lowest, double highest, HeightMap sediment) {

    /** Stage names as {@link StageTimes} records them. */
    public static final String SYNTHESIS = "synthesis";
    public static final String IMPORT = "import";
    public static final String SAMPLING = "sampling";
    public static final String PYRAMID = "pyramid";
    public static final String SNOW_MAP = "snow map";
    public static final String EROSION = "erosion";
    public static final String HYDRAULIC = "hydraulic";

    /**
     * Makes a tile's data from the settings and the seed: {@link #create}, or a tile of another source; {@code pipes}
     * runs the hydraulic erosion (on the GPU where there is one).
     */
    @FunctionalInterface
    public interface Maker {
        TerrainData make(TerrainSettings s, int seed, StageTimes times, PipeState.Runner pipes);
    }

    /** {@link #create(TerrainSettings, int, StageTimes, PipeState.Runner)} with the hydraulic erosion on the CPU. */
    public static TerrainData create(TerrainSettings s, int seed, StageTimes times) {
        return create(s, seed, times, PipeErosion::simulate);
    }

    /**
     * Makes the heights (synthesised from the seed, or imported when {@link TerrainSettings#importFile()} is set),
     * eroded with {@link TerrainSettings#erosion()} (stream power, then the hydraulic erosion run by {@code pipes}),
     * their pyramid and the snow map, timing each stage into {@code times}.
     *
     * @throws HeightImportException if the import file cannot be used
     */
    public static TerrainData create(TerrainSettings s, int seed, StageTimes times, PipeState.Runner pipes) {
        Path file = Path.of(s.importFile());
        boolean real = s.imports() && ElevationImport.handles(file);
        HeightMap made = s.imports()
                ? times.time(IMPORT, () -> real ? ElevationImport.read(file, s, seed) : HeightImport.read(file, s))
                : times.time(SYNTHESIS, () -> SpectralSynthesis.generate(s, seed));
        HeightMap carved = s.erosion() ? times.time(EROSION, () -> TileErosion.erode(made, s.erosionTalus())) : made;
        HydraulicErosion.Result washed = s.erosion() ? times.time(HYDRAULIC, () -> HydraulicErosion.tile(carved,
                TileErosion.routingLevel(carved), s.erosionTalus(), pipes)) : null;
        HeightMap base = washed == null ? made : washed.heights();
        HeightMap sediment = washed == null ? null : washed.change();
        if (!(real && s.importScale())) {
            return of(base, s, seed, times, base.min(), base.max(), sediment);
        }
        // a map at true scale lays its snow and rock by altitude in metres, not over its own range
        TerrainSettings metres = ElevationImport.trueScale(s);
        double lowest = -metres.seaFraction() * metres.relief();
        return of(base, metres, seed, times, lowest, lowest + metres.relief(), sediment);
    }

    /**
     * A tile of any height source: level 0's samples over the tile of {@code size²} samples centred on the origin,
     * then the pyramid and the snow map as for a generated tile.
     *
     * @param periodic whether the source repeats every {@code size} samples, so that copies of the tile join
     */
    public static TerrainData of(HeightSource source, int size, boolean periodic, TerrainSettings s, int seed,
                                 StageTimes times) {
        HeightMap base = times.time(SAMPLING, () -> new HeightMap(size, source.spacing(0),
                source.level(0, -size / 2, -size / 2, size), periodic));
        return of(base, s, seed, times, base.min(), base.max(), null);
    }

    /** A map's pyramid and snow; a normalised map has its own range as {@code lowest .. highest}. */
    private static TerrainData of(HeightMap base, TerrainSettings s, int seed, StageTimes times, double lowest,
                                  double highest, HeightMap sediment) {
        HeightPyramid pyramid = times.time(PYRAMID, () -> HeightPyramid.build(base));
        SnowMap snow = times.time(SNOW_MAP, () -> SnowMap.generate(pyramid, s, seed));
        return new TerrainData(pyramid, snow, lowest, highest, sediment);
    }
}
