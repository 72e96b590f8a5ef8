package org.openworld.engine.core;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.BiConsumer;

/**
 * Everything the systems share: entities with typed components, and resources (singletons such as the camera, the
 * sun or the terrain height field). Systems talk to each other only through the world, never by calling each other.
 *
 * <p>An entity is a plain {@code int}. A component is any object, stored by its class; a resource likewise. This is
 * the smallest store that serves the engine (a few thousand terrain patches at most): a hash map per component
 * class, iterated in entity order of insertion.
 */
public final class World {

    private int nextEntity = 1;
    private final Map<Class<?>, Map<Integer, Object>> components = new HashMap<>();
    private final Map<Class<?>, Object> resources = new LinkedHashMap<>();

    /** A new entity with no components. */
    public int spawn() {
        return nextEntity++;
    }

    /** Removes an entity and all its components. */
    public void despawn(int entity) {
        components.values().forEach(byEntity -> byEntity.remove(entity));
    }

    /** Attaches (or replaces) the component of this class on the entity. */
    public <T> void add(int entity, T component) {
        components.computeIfAbsent(component.getClass(), c -> new LinkedHashMap<>()).put(entity, component);
    }

    public <T> Optional<T> get(int entity, Class<T> type) {
        Map<Integer, Object> byEntity = components.get(type);
        return byEntity == null ? Optional.empty() : Optional.ofNullable(type.cast(byEntity.get(entity)));
    }

    public <T> void remove(int entity, Class<T> type) {
        Map<Integer, Object> byEntity = components.get(type);
        if (byEntity != null) {
            byEntity.remove(entity);
        }
    }

    /** Calls {@code action(entity, component)} for every entity that has a component of this class. */
    public <T> void each(Class<T> type, BiConsumer<Integer, T> action) {
        Map<Integer, Object> byEntity = components.getOrDefault(type, Map.of());
        byEntity.forEach((entity, component) -> action.accept(entity, type.cast(component)));
    }

    /** The entities that have a component of this class, in insertion order. */
    public List<Integer> with(Class<?> type) {
        return Collections.unmodifiableList(new ArrayList<>(components.getOrDefault(type, Map.of()).keySet()));
    }

    /** Stores a resource under its own class, replacing any earlier one. */
    public <T> void setResource(T resource) {
        setResource(castClass(resource), resource);
    }

    /** Stores a resource under an interface or base class, e.g. {@code setResource(HeightField.class, terrain)}. */
    public <T> void setResource(Class<T> type, T resource) {
        resources.put(type, type.cast(resource));
    }

    /** The resource of this class; a clear error when no system provides it. */
    public <T> T resource(Class<T> type) {
        Object resource = resources.get(type);
        if (resource == null) {
            throw new IllegalStateException("no " + type.getSimpleName() + " resource in the world: add the system that provides it");
        }
        return type.cast(resource);
    }

    public <T> Optional<T> findResource(Class<T> type) {
        return Optional.ofNullable(type.cast(resources.get(type)));
    }

    /** Every resource that is a {@code kind}, in the order they were first set. */
    public <T> List<T> resources(Class<T> kind) {
        return resources.values().stream().filter(kind::isInstance).map(kind::cast).toList();
    }

    @SuppressWarnings("unchecked")
    private static <T> Class<T> castClass(T resource) {
        return (Class<T>) resource.getClass();
    }
}
