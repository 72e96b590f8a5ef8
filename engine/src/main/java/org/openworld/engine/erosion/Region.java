package org.openworld.engine.erosion;

/**
 * One eroded region of a level: over the support of its weight, {@code (2 · CORE + 1)²} samples centred on its
 * centre, how far erosion moved each height ({@code delta}, m) and the drainage area there ({@code area}, m²).
 */
record Region(float[] delta, float[] area) {
}
