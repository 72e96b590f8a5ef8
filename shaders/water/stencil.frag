#version 330 core
// The paper's water (section 3.3), steps 2 and 4; steps 1 and 3 are the stencil rule the water system sets at the
// start of MAIN (WaterSystem.beginPass) and the reflection pass. Step 2 draws the water plane (water.vert gives it
// the plane's depth and cuts it at the horizon): it writes only alpha, the water's reflectivity, and (by the stencil
// state the water system sets) 0xFF into the stencil where it is the nearest surface. Step 4 is a full-screen quad
// of the mirrored scene, kept where the stencil is 0xFF and blended by the destination alpha:
//   colour = reflection * alpha + ground * (1 - alpha)
// Engine: org.openworld.engine.water.WaterSystem (water.method = STENCIL).
#include "common/frame.glsl"

out vec4 fragColor;

uniform int uStep;            // 2: the plane; 4: the blended quad
uniform float uAlpha;         // water.alpha
uniform sampler2D reflection; // the mirrored scene, aligned with the screen

void main() {
    if (uStep == 2) {
        fragColor = vec4(0.0, 0.0, 0.0, uAlpha);
    } else {
        fragColor = vec4(texture(reflection, gl_FragCoord.xy * frame.viewport.zw).rgb, 1.0);
    }
}
