/**
 * Erosion: heights carved by rivers and settled to their talus, so that the land measures like a real one
 * ({@link org.openworld.engine.drainage}). {@link org.openworld.engine.erosion.StreamPower} is the stream-power law's
 * steady state with uplift on a flow network (Braun and Willett 2013; Cordonnier et al. 2016).
 */
package org.openworld.engine.erosion;
