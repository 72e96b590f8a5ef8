package org.openworld.engine;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.Tag;

/**
 * Marks a test class, or a single test, that needs an OpenGL context: JUnit's tag {@code gl}. The GL-free tests run
 * alone, in seconds, with {@code ./mvnw -B verify -Dgroups='!gl'}; the GL ones alone with {@code -Dgroups=gl}.
 *
 * <p>The demo's tests write {@code @Tag("gl")} itself, as modules do not share test classes. {@code GlTestTagsTest}
 * fails when a test that makes a context carries neither.
 */
@Target({ElementType.TYPE, ElementType.METHOD})
@Retention(RetentionPolicy.RUNTIME)
@Tag(GlTest.TAG)
public @interface GlTest {

    /** The JUnit tag, as {@code -Dgroups} names it. */
    String TAG = "gl";
}
