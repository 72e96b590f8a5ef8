package org.openworld.engine.terrain;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.terrain.material.MaterialSettings.Cliffs;
import org.openworld.engine.terrain.material.MaterialSettings.Tiling;

/**
 * One terrain program, named by what it is compiled for: it yields both the {@code #define}s its stages compile with
 * and its role, the name it is owned and labelled by ({@code terrain.role}), so no caller writes either by hand.
 *
 * <p>A kind reads only the choices it depends on; the others are set to their first value as the variant is made,
 * so two variants that compile the same source are equal and share a role. The near program reads all of them; the
 * far one the light, and the tiling only on the clipmap (the tile's far program reads the bake, whichever tiling made
 * it); the far field is unshadowed (it lies beyond every cascade) and shows the repeated tiles' coarse scale; the
 * debug views and the depth program read the layout alone.
 *
 * @param kind   which program: near or far material, the far field's ring, a debug view, or depth only
 * @param tiling how the materials' tiles are laid ({@code MAT_WANG}, {@code MAT_STOCHASTIC})
 * @param cliffs how the near material projects the rock ({@code MAT_TRIPLANAR})
 * @param light  whether the program reads the sun's shadow maps ({@code SUN_UNSHADOWED} when not)
 * @param layout where the heights come from: a tile's pyramid or the streamed clipmap ({@code TERRAIN_CLIPMAP})
 */
record TerrainVariant(Kind kind, Tiling tiling, Cliffs cliffs, Light light, Layout layout) {

    /** Which program of the terrain. */
    enum Kind {
        /** Every layer of the materials, fading into the far look before the far distance. */
        NEAR,
        /** The ground beyond the far distance: the bake on a tile, the coarse scale alone on the clipmap. */
        FAR,
        /** The ring beyond the patches ({@code terrain/farfield.vert}), coloured as the far ground. */
        FAR_FIELD,
        /** The far look tinted by the patch's level (figure 6). */
        LEVELS,
        /** The tangent's rise and the normal, no material (figure 4). */
        TANGENT_SPACE,
        /** Depth only ({@code terrain/depth.frag}), for the passes that need no colour. */
        DEPTH
    }

    /** Whether the pass has the sun's shadow maps bound. */
    enum Light { SHADOWED, UNSHADOWED }

    /** Where the vertex stage reads the heights. */
    enum Layout {
        /** A tile's pyramid. */
        TILE,
        /** Streamed levels' clipmap. */
        CLIPMAP
    }

    /** Sets what the kind does not read to its first value, so equal sources make equal variants. */
    TerrainVariant {
        boolean tiled = kind == Kind.NEAR || kind == Kind.FAR && layout == Layout.CLIPMAP;
        tiling = tiled ? tiling : Tiling.REPEAT;
        cliffs = kind == Kind.NEAR ? cliffs : Cliffs.PLANAR;
        light = kind == Kind.NEAR || kind == Kind.FAR ? light
                : kind == Kind.FAR_FIELD ? Light.UNSHADOWED : Light.SHADOWED;
    }

    /** A program of a kind that reads the layout alone. */
    static TerrainVariant of(Kind kind, Layout layout) {
        return new TerrainVariant(kind, Tiling.REPEAT, Cliffs.PLANAR, Light.SHADOWED, layout);
    }

    /** A far program of this tiling and light. */
    static TerrainVariant far(Tiling tiling, Light light, Layout layout) {
        return new TerrainVariant(Kind.FAR, tiling, Cliffs.PLANAR, light, layout);
    }

    /** Every program a terrain of this layout and projection can make, each once. */
    static List<TerrainVariant> all(Layout layout, Cliffs cliffs) {
        List<TerrainVariant> all = new ArrayList<>();
        for (Kind kind : Kind.values()) {
            for (Tiling tiling : Tiling.values()) {
                for (Light light : Light.values()) {
                    TerrainVariant v = new TerrainVariant(kind, tiling, cliffs, light, layout);
                    if (!all.contains(v)) {
                        all.add(v);
                    }
                }
            }
        }
        return all;
    }

    /** The role the program is owned by: {@code program}, the kind, then the tiling, projection and light. */
    String role() {
        return switch (kind) {
            case DEPTH -> "depth";
            case NEAR -> "program" + tiling.roleSuffix() + (cliffs == Cliffs.PLANAR ? "" : suffix(cliffs)) + lit();
            case FAR -> "program.far" + tiling.roleSuffix() + lit();
            default -> "program." + kind.name().toLowerCase(Locale.ROOT).replace('_', '-');
        };
    }

    /** The names defined at the top of every stage. */
    List<String> defines() {
        List<String> d = new ArrayList<>();
        if (light == Light.UNSHADOWED) {
            d.add("SUN_UNSHADOWED");
        }
        d.addAll(tiling.defines());
        d.addAll(cliffs.defines());
        boolean clipmap = layout == Layout.CLIPMAP;
        switch (kind) {
            case FAR, FAR_FIELD -> {
                d.add("TERRAIN_FAR");
                if (kind == Kind.FAR_FIELD) {
                    d.add("TERRAIN_FARFIELD");
                }
                if (clipmap) {
                    d.add("MAT_COARSE_ONLY"); // nothing baked: the materials at their coarse scale
                }
            }
            case LEVELS -> d.addAll(clipmap ? List.of("TERRAIN_LEVELS") : List.of("TERRAIN_FAR", "TERRAIN_LEVELS"));
            case TANGENT_SPACE -> d.add("TERRAIN_TANGENT_SPACE");
            default -> { }
        }
        if (clipmap) {
            d.add("TERRAIN_CLIPMAP");
        }
        return d;
    }

    /** The program, compiled on first use, owned by {@code context} under its {@link #role}. */
    ShaderProgram program(EngineContext context) {
        return context.own(role(), context.shaders().program(defines(), stages().toArray(String[]::new)));
    }

    /** The vertex and fragment stage files. */
    List<String> stages() {
        return List.of(kind == Kind.FAR_FIELD ? "terrain/farfield.vert" : "terrain/terrain.vert",
                kind == Kind.DEPTH ? "terrain/depth.frag" : "terrain/terrain.frag");
    }

    private String lit() {
        return light == Light.SHADOWED ? "" : suffix(light);
    }

    private static String suffix(Enum<?> choice) {
        return "." + choice.name().toLowerCase(Locale.ROOT);
    }
}
