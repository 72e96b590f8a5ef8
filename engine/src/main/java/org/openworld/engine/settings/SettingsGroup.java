package org.openworld.engine.settings;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.List;

/**
 * One system's settings record with its key prefix, e.g. {@code camera} for {@code camera.fov}. Keys are the record
 * components' names in kebab case. Reading and rebuilding records goes through the record's accessors and
 * canonical constructor, the only reflection in the settings code.
 *
 * @param <R> the settings record type
 */
public final class SettingsGroup<R extends Record> {

    /** One key of the group: its record component and its documentation. */
    public record Key(String key, RecordComponent component, Setting doc) {
        public Class<?> type() {
            return component.getType();
        }
    }

    private final String prefix;
    private final Class<R> type;
    private final R defaults;
    private final List<Key> keys = new ArrayList<>();

    private SettingsGroup(String prefix, Class<R> type, R defaults) {
        this.prefix = prefix;
        this.type = type;
        this.defaults = defaults;
        if (!Modifier.isPublic(type.getModifiers())) {
            // Reading and rebuilding records reflectively needs public accessors and constructor; say so now,
            // not as an IllegalAccessException the first time a key is read.
            throw new IllegalStateException("settings record " + type.getName() + " must be public");
        }
        for (RecordComponent c : type.getRecordComponents()) {
            Setting doc = c.getAnnotation(Setting.class);
            if (doc == null) {
                throw new IllegalStateException(type.getSimpleName() + "." + c.getName() + " has no @Setting documentation");
            }
            keys.add(new Key(prefix + "." + kebab(c.getName()), c, doc));
        }
    }

    /**
     * @param prefix   key prefix, e.g. {@code camera}
     * @param type     the settings record class
     * @param defaults the record's {@code DEFAULTS}
     */
    public static <R extends Record> SettingsGroup<R> of(String prefix, Class<R> type, R defaults) {
        return new SettingsGroup<>(prefix, type, defaults);
    }

    public String prefix() {
        return prefix;
    }

    public Class<R> type() {
        return type;
    }

    public R defaults() {
        return defaults;
    }

    public List<Key> keys() {
        return keys;
    }

    /** The value of one component of a record of this group. */
    public Object value(R record, Key key) {
        try {
            return key.component().getAccessor().invoke(record);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A copy of {@code record} with one component replaced by {@code value} (already parsed and checked). */
    public R with(R record, Key changed, Object value) {
        Object[] args = new Object[keys.size()];
        Class<?>[] types = new Class<?>[keys.size()];
        for (int i = 0; i < args.length; i++) {
            Key k = keys.get(i);
            args[i] = k == changed ? value : value(record, k);
            types[i] = k.type();
        }
        try {
            Constructor<R> canonical = type.getDeclaredConstructor(types);
            return canonical.newInstance(args);
        } catch (InvocationTargetException e) {
            // The record's own validation rejected the combination.
            throw new SettingsException(changed.key() + ": " + e.getCause().getMessage());
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(e);
        }
    }

    static String kebab(String camel) {
        return camel.replaceAll("([a-z0-9])([A-Z])", "$1-$2").toLowerCase(java.util.Locale.ROOT);
    }
}
