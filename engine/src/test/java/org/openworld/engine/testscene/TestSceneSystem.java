package org.openworld.engine.testscene;

import static org.lwjgl.opengl.GL11C.*;

import java.util.ArrayList;
import java.util.List;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;

/**
 * A test fixture that exercises the whole pipeline with simple geometry: a ground grid with a ring of boxes, lit by
 * the world's sun and fogged by the shared fog. It publishes a flat {@link HeightField} so walk mode has ground to
 * stand on. Pair it with {@link org.openworld.engine.sky.SkySystem} for a background.
 */
public final class TestSceneSystem implements EngineSystem {

    /** Half the side of the ground square, metres. */
    static final float GROUND_HALF_SIZE = 4000;
    /** Side of each box, metres. */
    static final float BOX_SIZE = 40;
    /** Radius of the ring of boxes around the origin, metres. */
    static final float RING_RADIUS = 200;
    static final int BOX_COUNT = 8;

    private ShaderProgram lit;
    private Mesh ground;
    private Mesh boxes;

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("test-scene").reads(Sun.class).writes(HeightField.class).draws(Pass.MAIN);
    }

    @Override
    public void init(EngineContext context) {
        context.world().setResource(HeightField.class, HeightField.FLAT);
        lit = context.shaders().program("testscene/lit.vert", "testscene/lit.frag");
        float h = GROUND_HALF_SIZE;
        ground = new Mesh(context.gl(), new float[] {
            -h, 0, -h, 0, 1, 0,  h, 0, -h, 0, 1, 0,  h, 0, h, 0, 1, 0,  -h, 0, h, 0, 1, 0},
            new int[] {0, 2, 1, 0, 3, 2}, new Mesh.Attribute(0, 3), new Mesh.Attribute(1, 3));
        boxes = ringOfBoxes(context);
    }

    private static Mesh ringOfBoxes(EngineContext context) {
        List<Float> v = new ArrayList<>();
        List<Integer> idx = new ArrayList<>();
        for (int i = 0; i < BOX_COUNT; i++) {
            double angle = 2 * Math.PI * i / BOX_COUNT;
            float cx = (float) (RING_RADIUS * Math.sin(angle));
            float cz = (float) (-RING_RADIUS * Math.cos(angle));
            float height = BOX_SIZE * (1 + i % 3);
            addBox(v, idx, cx, cz, BOX_SIZE / 2, height);
        }
        float[] vertices = new float[v.size()];
        for (int i = 0; i < vertices.length; i++) {
            vertices[i] = v.get(i);
        }
        return new Mesh(context.gl(), vertices, idx.stream().mapToInt(Integer::intValue).toArray(),
                new Mesh.Attribute(0, 3), new Mesh.Attribute(1, 3));
    }

    /** Five faces (no bottom), each with its own normal, counter-clockwise seen from outside. */
    private static void addBox(List<Float> v, List<Integer> idx, float cx, float cz, float half, float height) {
        float[][] normals = {{0, 1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
        for (float[] n : normals) {
            int base = v.size() / 6;
            float[][] corners = faceCorners(n, cx, cz, half, height);
            for (float[] c : corners) {
                v.add(c[0]); v.add(c[1]); v.add(c[2]);
                v.add(n[0]); v.add(n[1]); v.add(n[2]);
            }
            idx.addAll(List.of(base, base + 1, base + 2, base, base + 2, base + 3));
        }
    }

    private static float[][] faceCorners(float[] n, float cx, float cz, float half, float height) {
        float x0 = cx - half, x1 = cx + half, z0 = cz - half, z1 = cz + half;
        if (n[1] > 0) {
            return new float[][] {{x0, height, z1}, {x1, height, z1}, {x1, height, z0}, {x0, height, z0}};
        } else if (n[0] > 0) {
            return new float[][] {{x1, 0, z1}, {x1, 0, z0}, {x1, height, z0}, {x1, height, z1}};
        } else if (n[0] < 0) {
            return new float[][] {{x0, 0, z0}, {x0, 0, z1}, {x0, height, z1}, {x0, height, z0}};
        } else if (n[2] > 0) {
            return new float[][] {{x0, 0, z1}, {x1, 0, z1}, {x1, height, z1}, {x0, height, z1}};
        }
        return new float[][] {{x1, 0, z0}, {x0, 0, z0}, {x0, height, z0}, {x1, height, z0}};
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        // ground grid and boxes, lit by the sun and sky, fogged with distance
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
        glEnable(GL_CULL_FACE);
        lit.use();
        ground.draw(context.stats());
        boxes.draw(context.stats());
        glDisable(GL_CULL_FACE);
    }

    @Override
    public void close() {
        for (AutoCloseable c : new AutoCloseable[] {boxes, ground, lit}) {
            if (c != null) {
                try {
                    c.close();
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }
        }
    }
}
