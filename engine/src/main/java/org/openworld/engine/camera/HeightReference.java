package org.openworld.engine.camera;

import java.util.Optional;

/**
 * What a camera path's y column is measured from, chosen by the {@code heights} directive of the file.
 */
public enum HeightReference {

    /** y is metres above sea level: flights and orbits that must not depend on the terrain. */
    SEA("sea"),

    /** y is eye height above the ground height field: walks that stay on whatever terrain the world has. */
    GROUND("ground");

    private final String keyword;

    HeightReference(String keyword) {
        this.keyword = keyword;
    }

    /** The word after {@code heights} in a path file. */
    public String keyword() {
        return keyword;
    }

    /** The reference a path file names, or empty for an unknown word. */
    public static Optional<HeightReference> fromKeyword(String word) {
        for (HeightReference reference : values()) {
            if (reference.keyword.equals(word)) {
                return Optional.of(reference);
            }
        }
        return Optional.empty();
    }
}
