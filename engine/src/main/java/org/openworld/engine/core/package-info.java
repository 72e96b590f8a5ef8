/**
 * The entity/system core: a {@link org.openworld.engine.core.World} of entities, components and resources, and
 * {@link org.openworld.engine.core.EngineSystem}s that only talk through it.
 *
 * <p><b>Frame order.</b> Each system declares in a {@link org.openworld.engine.core.SystemSpec} what it reads and
 * writes, which systems it follows, which {@link org.openworld.engine.core.Pass}es it draws in and in which
 * {@link org.openworld.engine.core.Layer} (opaque, background, over the opaque picture, transparent).
 * {@link org.openworld.engine.core.SystemOrder} turns that into a graph (writer → reader, after → system, an earlier
 * layer → a later one) and sorts
 * it topologically with Kahn's algorithm, alphabetical among equals: O(S² · T) for S systems and T declared types,
 * microseconds for the dozen systems of the demo, done once at start-up. A cycle, or two writers of one type that
 * nobody ordered, is an error that names the systems. {@code openworld info --frame} prints the resolved order
 * with the reason for every edge.
 *
 * <p><b>Passes.</b> SHADOW → REFLECTION → MAIN → OVERLAY, each with its own {@link org.openworld.engine.core.ViewCamera}
 * and target ({@link org.openworld.engine.core.PassView}): MAIN and OVERLAY the viewer's camera and the scene, SHADOW
 * and REFLECTION what their {@link org.openworld.engine.core.PassOwner} (the shadow system, the water system) gives
 * each frame. The viewer's {@code PassView} is also a world resource, set before the passes, for a system that draws
 * another pass with the viewer in mind (the terrain's shadow casters are no finer than the ground the viewer sees).
 * A world resource that is a {@link org.openworld.engine.core.SharedResource} (the sky's maps, the sun's shadow) is
 * bound for every shader of a pass, over a stand-in, and a system asks
 * {@link org.openworld.engine.core.RenderContext#shares} whether it is. Systems report numbers per frame into the
 * {@link org.openworld.engine.core.Counters}, each keyed by a {@link org.openworld.engine.core.Counter} constant.
 *
 * <p><b>Shared vocabulary.</b> Types that several systems write or read, and that no one system owns, live here
 * rather than in a system's package: {@link org.openworld.engine.core.HeightField} (the ground, published by the
 * terrain or a test scene) and {@link org.openworld.engine.core.Cullable} with its
 * {@link org.openworld.engine.core.BoundsTree} (what a drawing system asks the culling to test). A system imports
 * another system's package only for a type it declares in {@code reads}/{@code writes} (the engine's
 * {@code SystemImportsTest} checks every import line).
 *
 * <p><b>Limits.</b> The world is a hash map per component class: fine for thousands of entities, not for millions
 * (particles live on the GPU, not in the world).
 */
package org.openworld.engine.core;
