package org.openworld.engine.vegetation;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.Moisture;

/**
 * The plants around the viewer, tile by tile, for one world (heights, moisture, settings, rules and seed): each
 * tile is placed once and kept while it stays within reach, so a move places only the tiles it brings in. Used by
 * one thread at a time (the vegetation's worker, or the GL thread for the first placement, before any worker job).
 */
final class TreePlacer {

    /** Everything the plants depend on but the viewer's position: a new one starts a new placer. */
    record World(HeightField heights, Moisture moisture, VegetationSettings settings, TreePlacement.Limits limits,
                 int seed) {
    }

    private final World world;
    private final PlacementField field;
    private Map<Long, TreePlacement.Tile> tiles = new HashMap<>();

    TreePlacer(World world) {
        this.world = world;
        this.field = new PlacementField(world.heights(), world.moisture(), world.limits(), world.seed());
    }

    World world() {
        return world;
    }

    /** The density field of this world: no state but the seed, safe to read from any thread. */
    PlacementField field() {
        return field;
    }

    /** The plants of the tiles meeting the disc of {@code radius} around (x, z); the tiles beyond it are forgotten. */
    TreePlacement.Layout around(double x, double z, double radius) {
        Map<Long, TreePlacement.Tile> kept = new HashMap<>();
        List<TreePlacement.Tile> list = new ArrayList<>();
        for (long[] t : TreePlacement.tilesAround(x, z, radius)) {
            long key = t[0] * 0x1_0000_0001L ^ t[1];
            TreePlacement.Tile tile = tiles.get(key);
            if (tile == null || tile.tx() != t[0] || tile.tz() != t[1]) {
                tile = TreePlacement.tile(field, world.heights(), t[0], t[1], world.settings(), world.limits(),
                        world.seed());
            }
            kept.put(key, tile);
            list.add(tile);
        }
        tiles = kept;
        return TreePlacement.assemble(list, x, z);
    }
}
