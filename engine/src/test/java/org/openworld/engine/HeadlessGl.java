package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.openworld.engine.gl.GlContext;

/**
 * One headless GL context for a test class, and a leak check after every test: each test must leave no live GL
 * object behind, and no texture memory counted. Use as {@code @RegisterExtension static final HeadlessGl GL = new HeadlessGl();}.
 */
public final class HeadlessGl implements BeforeAllCallback, AfterAllCallback, AfterEachCallback {

    private GlContext context;

    public GlContext context() {
        return context;
    }

    @Override
    public void beforeAll(ExtensionContext extension) {
        context = GlContext.headless();
    }

    @Override
    public void afterEach(ExtensionContext extension) {
        assertEquals(0, context.objects().live(), "live GL objects after the test: " + context.objects());
        assertEquals(0, context.textureMemory().bytes(), "texture bytes counted after the test");
    }

    @Override
    public void afterAll(ExtensionContext extension) {
        context.close();
    }
}
