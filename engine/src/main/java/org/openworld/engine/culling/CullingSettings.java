package org.openworld.engine.culling;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Settings of the {@link CullingSystem}, keys {@code culling.*}.
 *
 * @param freeze keep culling every pass with the frustum its camera had when this was switched on, and outline the
 *               frozen main frustum, so one can fly out of it and see what was culled
 */
public record CullingSettings(
        @Setting(doc = "cull with the frustums captured when switched on; outline the main one") boolean freeze) {

    /** Culling follows the cameras. */
    public static final CullingSettings DEFAULTS = new CullingSettings(false);

    public static final SettingsGroup<CullingSettings> SETTINGS =
            SettingsGroup.of("culling", CullingSettings.class, DEFAULTS);
}
