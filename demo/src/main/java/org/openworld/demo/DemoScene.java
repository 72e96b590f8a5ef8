package org.openworld.demo;

import java.util.List;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.camera.CameraSystem;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.minimap.MinimapSystem;
import org.openworld.engine.particles.ParticleSystem;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.shadow.ShadowSystem;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.trees.TreeSystem;
import org.openworld.engine.water.WaterSystem;

/**
 * The demo's world: which systems it runs. Adding a system to the demo is one line in {@link #systems()}; the
 * engine orders them from their declarations, and their settings appear in {@code --set} and
 * {@code openworld settings} by themselves.
 */
final class DemoScene {

    /** Where the camera starts when no pose is given: above a valley of the default world, looking north. */
    static final CameraPose DEFAULT_POSE = new CameraPose(0, 400, 900, 0, -8, CameraPose.DEFAULT_FOV);

    private DemoScene() {
    }

    /** A fresh set of the demo's systems (nothing is allocated until the engine initialises them). */
    static List<EngineSystem> systems() {
        return List.of(
                new CameraSystem(),
                new SkySystem(),
                new CullingSystem(),
                new TerrainSystem(line -> System.err.println(line)),
                new ShadowSystem(),
                new TreeSystem(),
                new WaterSystem(),
                new MinimapSystem(),
                new ParticleSystem());
    }
}
