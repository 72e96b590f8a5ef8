/**
 * Settings as documented records with one place for defaults (CONTRIBUTING.md, "Settings are records"). A system declares a record whose
 * components carry {@link org.openworld.engine.settings.Setting} (meaning, unit, range) and a {@code DEFAULTS}
 * constant; a {@link org.openworld.engine.settings.SettingsGroup} gives its keys a prefix. The
 * {@link org.openworld.engine.settings.Settings} resource holds the current record of each group, and the command
 * line's {@code --set key=value}, {@code openworld settings} and the in-app panel all go through it, so a key cannot
 * exist in one and be missing from another. Invalid values name the key and the valid range.
 */
package org.openworld.engine.settings;
