package org.openworld.demo;

import java.util.List;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.camera.CameraSystem;
import org.openworld.engine.sky.clouds.CloudVolumeSystem;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.World;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.grass.GrassSystem;
import org.openworld.engine.minimap.MinimapSystem;
import org.openworld.engine.particles.ParticleSystem;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.shadow.ShadowSystem;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.vegetation.VegetationSystem;
import org.openworld.engine.water.WaterSystem;

/**
 * The demo's world: which systems it runs. Adding a system to the demo is one line in {@link #systems()}; the
 * engine orders them from their declarations, and their settings appear in {@code --set} and
 * {@code openworld settings} by themselves.
 */
final class DemoScene {

    /** Where the camera starts on the default tile: 400 m up (214 m over a valley), looking north. */
    static final CameraPose DEFAULT_POSE = new CameraPose(0, 400, 900, 0, -8, CameraPose.DEFAULT_FOV);
    /** How far over the ground the camera starts where the ground under {@link #DEFAULT_POSE} is higher. */
    static final double DEFAULT_CLEARANCE = 200;

    /**
     * Where the camera starts when no pose is given: {@link #DEFAULT_POSE}, raised to {@link #DEFAULT_CLEARANCE} over
     * the world's ground where that lies higher. The unbounded world's ground there is at 480 m, so its start would
     * otherwise be inside a mountain; the tile's (186 m) leaves the pose, and every picture taken from it, as it was.
     */
    static CameraPose defaultPose(World world) {
        CameraPose p = DEFAULT_POSE;
        double ground = world.findResource(HeightField.class).orElse(HeightField.FLAT).heightAt(p.x(), p.z());
        return new CameraPose(p.x(), Math.max(p.y(), ground + DEFAULT_CLEARANCE), p.z(), p.yaw(), p.pitch(), p.fov());
    }

    private DemoScene() {
    }

    /** A fresh set of the demo's systems (nothing is allocated until the engine initialises them). */
    static List<EngineSystem> systems() {
        return List.of(
                new CameraSystem(),
                new SkySystem(),
                new CloudVolumeSystem(),
                new CullingSystem(),
                new TerrainSystem(line -> System.err.println(line)),
                new ShadowSystem(),
                new VegetationSystem(),
                new GrassSystem(),
                new WaterSystem(),
                new MinimapSystem(),
                new ParticleSystem());
    }
}
