package org.openworld.engine.sky;

import org.openworld.engine.settings.Setting;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Where the sun stands and how the sky is shown. The atmosphere itself is {@link AtmosphereSettings}, the clouds
 * {@link CloudSettings}.
 *
 * @param latitude    observer latitude, degrees north: how high the sun climbs and how long dawn lasts
 * @param declination solar declination, degrees (about +23 in June, −23 in December): the season
 * @param exposure    exposure compensation, EV (stops): +1 shows the scene twice as bright
 * @param autoExposure adapt the exposure to the light of the moment (as an eye does); off, the exposure is noon's
 *                    times the compensation, so two skies compare as they are (figure 9: single against multiple
 *                    scattering at dawn); off, too, the night's blue shift
 * @param moonAge     days since new moon: the moon's phase and its place east of the sun (MoonPosition); 14.8 is
 *                    full, rising at sunset
 */
public record SkySettings(
        @Setting(doc = "observer latitude", unit = "deg", min = -89, max = 89) double latitude,
        @Setting(doc = "solar declination (season)", unit = "deg", min = -23.44, max = 23.44) double declination,
        @Setting(doc = "exposure compensation", unit = "EV", min = -6, max = 12) double exposure,
        @Setting(doc = "adapt the exposure to the light of the moment; off: noon's exposure") boolean autoExposure,
        @Setting(doc = "days since new moon (phase and place; 14.8 full)", unit = "d", min = 0, max = 29.5)
        double moonAge) {

    public static final SkySettings DEFAULTS = new SkySettings(46, 10, 0, true, 3);

    public static final SettingsGroup<SkySettings> SETTINGS = SettingsGroup.of("sky", SkySettings.class, DEFAULTS);
}
