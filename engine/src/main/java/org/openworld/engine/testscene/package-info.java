/**
 * A small lit scene (a sky gradient, a ground grid, a ring of boxes) that proves the engine end to end before the
 * real world exists: the frame block, the fog, the sun, the image read-back and the benchmark recorder. Tests keep
 * it as a fixture; the demo replaces it with the terrain and sky systems.
 */
package org.openworld.engine.testscene;
