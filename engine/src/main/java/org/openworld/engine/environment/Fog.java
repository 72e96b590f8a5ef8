package org.openworld.engine.environment;

import org.joml.Vector3f;
import org.joml.Vector3fc;

/**
 * Distance fog shared by every pass (shaders/common/fog.glsl): exponential extinction along the view ray through
 * an atmosphere whose density falls off with height.
 *
 * <p>For a ray of length d from height h0 to h1 the optical depth is
 * {@code τ = density · d · (e^{−k h0} − e^{−k h1}) / (k (h1 − h0))} (→ {@code density · d · e^{−k h0}} as h1 → h0),
 * and the fogged colour is {@code mix(fogColour, surface, e^{−τ})}.
 *
 * @param color          colour of the fog, linear RGB (the sky near the horizon)
 * @param density        extinction at sea level, per metre
 * @param heightFalloff  k, per metre: density halves every ln 2 / k metres of height
 */
public record Fog(Vector3fc color, float density, float heightFalloff) {

    public Fog {
        color = new Vector3f(color);
    }
}
