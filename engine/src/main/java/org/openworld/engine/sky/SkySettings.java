package org.openworld.engine.sky;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Where the sun stands and how the sky is shown. The atmosphere itself is {@link AtmosphereSettings}, the clouds
 * {@link CloudSettings}.
 *
 * @param latitude    observer latitude, degrees north: how high the sun climbs and how long dawn lasts
 * @param declination solar declination, degrees (about +23 in June, −23 in December): the season
 * @param exposure    exposure compensation, EV (stops): +1 shows the scene twice as bright as the automatic exposure
 */
public record SkySettings(
        @Setting(doc = "observer latitude", unit = "deg", min = -89, max = 89) double latitude,
        @Setting(doc = "solar declination (season)", unit = "deg", min = -23.44, max = 23.44) double declination,
        @Setting(doc = "exposure compensation over the automatic exposure", unit = "EV", min = -6, max = 6)
        double exposure) {

    public static final SkySettings DEFAULTS = new SkySettings(46, 10, 0);

    public static final SettingsGroup<SkySettings> SETTINGS = SettingsGroup.of("sky", SkySettings.class, DEFAULTS);
}
