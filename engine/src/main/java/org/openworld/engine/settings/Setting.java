package org.openworld.engine.settings;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Documents one component of a settings record: what it means, its unit and its valid range. The default lives in
 * the record's {@code DEFAULTS} constant, nowhere else.
 * <pre>{@code
 * public record CameraSettings(
 *         @Setting(doc = "vertical field of view", unit = "deg", min = 20, max = 120) double fov) {
 *     public static final CameraSettings DEFAULTS = new CameraSettings(60);
 * }
 * }</pre>
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.RECORD_COMPONENT)
public @interface Setting {

    /** What the setting does, one line. */
    String doc();

    /** Unit, e.g. {@code m}, {@code deg}, {@code m/s}; empty for counts, flags and choices. */
    String unit() default "";

    /** Smallest valid value (numbers only). */
    double min() default Double.NEGATIVE_INFINITY;

    /** Largest valid value (numbers only). */
    double max() default Double.POSITIVE_INFINITY;

    /**
     * Read once, when the world is built (what the terrain and the clouds are generated from): a change takes effect
     * when the world is built again, which the settings panel offers as "Rebuild world". Every other setting is read
     * each frame and takes effect at once.
     */
    boolean atStart() default false;

    /**
     * A file name: in a settings file ({@code --config}), a relative name is read from the settings file's folder,
     * as an include is in most formats, so a folder holding a settings file and its data can be moved whole.
     */
    boolean file() default false;
}
