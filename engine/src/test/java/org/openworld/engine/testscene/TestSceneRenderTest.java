package org.openworld.engine.testscene;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.environment.DaylightSystem;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Image;

class TestSceneRenderTest {

    @Test
    void rendersSkyAboveAndLitGroundBelow() throws Exception {
        try (GlContext gl = GlContext.headless()) {
            Image image;
            try (Engine engine = GlTestSupport.engine(gl, 320, 180, new TestSceneSystem(), new DaylightSystem())) {
                engine.world().resource(Camera.class).setPose(new CameraPose(0, 60, 400, 0, -5, 60));
                engine.update();
                engine.render();
                image = engine.readImage();
            }
            image.writePng(Path.of("target/test-images/test-scene.png"));
            assertEquals(0, gl.objects().live(), "live GL objects after close: " + gl.objects());
        }
    }
}
